#include "protocols/format/parse_protocol.h"

#include <algorithm>
#include <fstream>
#include <numbers>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "protocols/format/edit_distance.h"
#include "protocols/format/parse_protocol_document.h"
#include "protocols/format/stage_names.h"
#include "protocols/format/toml_value_reader.h"

namespace protocols {

namespace {

// Why `path` cannot be a mesh file, in words ("" when it is a regular file): a directory, a device
// such as /dev/zero or a symbolic link loop each get their own words, not "not found".
std::string meshPathProblem(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) return "file not found";
  if (ec) return "cannot be opened: " + ec.message();
  if (fs::is_directory(status)) return "is a directory, not a mesh file";
  if (!fs::is_regular_file(status)) return "is not a regular file (a device, pipe or socket)";
  return {};
}

using Table = TomlValueReader::Table;

constexpr double kStandardGravity = 9.80665;   // [m/s^2] CGPM 1901
constexpr double kDefaultSteadyLimit = 600.0;  // [s] upper bound of an "until steady" posture
constexpr double kDefaultFrameInterval = 1.0;  // [s]
constexpr double kDefaultSteadyWindow = 0.5;   // [s] steady_state.h explains the choice
constexpr double kDefaultSteadyCoverageChange = 0.005;  // [1] half a percentage point
constexpr std::array<std::string_view, 3> kDefaultFields = {"position", "velocity", "material"};

// Reads one protocol; every helper reports into the reader and carries on, so one run of the
// parser finds every problem of the file.
class ProtocolParser {
 public:
  ProtocolParser(const std::filesystem::path& file)
      : file_(file), reader_(file.string()), defaultAt_{file.string(), 0, 0} {}

  Protocol parse(std::string_view text);
  Protocol parse(const toml::table& document);

 private:
  template <class Enum>
  Located<Enum> choiceOr(const Table& t, std::string_view key, Enum fallback) {
    if (auto c = reader_.choice(t, key)) return {static_cast<Enum>(c->value), c->where};
    return {fallback, defaultAt_};
  }
  Located<double> quantityOr(const Table& t, std::string_view key, double fallback) {
    if (auto q = reader_.quantity(t, key)) return *q;
    return {fallback, defaultAt_};
  }
  // Reports `key` of `t` as present although `why` forbids it.
  void forbid(const Table& t, std::string_view key, const std::string& why,
              const std::string& fix) {
    if (const toml::node* node = t.table->get(key))
      reader_.error(reader_.at(node->source()), TomlValueReader::shownKey(t, key) + " " + why, fix);
  }
  void requireConditional(const Table& t, std::string_view key, bool present,
                          const std::string& why) {
    if (present || t.table->get(key) != nullptr) return;  // present, or present but invalid
    const ParameterSpec& s = parameterSpec(t.specPath + "." + std::string(key));
    reader_.error(t.where, "missing key '" + TomlValueReader::shownKey(t, key) + "': " + why,
                  "add " + std::string(key) + " = " + std::string(s.example) + " (" +
                      std::string(s.doc) + ")");
  }

  void readEye(const Table& root, Protocol& p);
  void checkEyeKind(const Table& eye, const std::optional<Located<std::string>>& meshPath,
                    const std::optional<Located<std::size_t>>& meshUnits, EyeSpec& e);
  MeshSource readMeshSource(const Located<std::string>& meshPath,
                            const Located<std::size_t>& meshUnits);
  RetinalBreak readBreak(const Table& t);
  void checkMeshEye(const EyeSpec& e);
  std::optional<TissueSpec> readTissue(const Table& eye, std::string_view key, bool isSclera);
  void readTamponade(const Table& root, Protocol& p);
  void readSchedule(const Table& root, Protocol& p);
  void readEffects(const Table& root, Protocol& p);
  void readAccuracy(const Table& root, Protocol& p);
  void readOutputs(const Table& root, Protocol& p);
  void checkEquilibriumPostures(const Protocol& p);

  std::filesystem::path file_;
  TomlValueReader reader_;
  SourceLocation defaultAt_;  // where defaults "come from": the file, line 0
};

Protocol ProtocolParser::parse(std::string_view text) {
  toml::table document;
  try {
    document = toml::parse(text, file_.string());
  } catch (const toml::parse_error& e) {
    reader_.error(
        reader_.at(e.source()), "malformed TOML: " + std::string(e.description()),
        "fix the syntax (TOML 1.0, https://toml.io); strings need quotes, e.g. fill = \"90 %\"");
    throw ProtocolError(reader_.diagnostics());
  }
  return parse(document);
}

Protocol ProtocolParser::parse(const toml::table& document) {
  Protocol p;
  p.file = file_;
  const Table root = reader_.root(document);
  reader_.reportUnknownKeys(root);
  if (auto v = reader_.integer(root, "format_version")) p.formatVersion = *v;
  p.title = reader_.string(root, "title");
  p.description = reader_.string(root, "description");
  if (auto c = reader_.choice(root, "solver"))
    p.solver = {std::string(solverNames()[c->value]), c->where};
  else
    p.solver = {std::string(kDefaultSolver), defaultAt_};
  readEye(root, p);
  readTamponade(root, p);
  readSchedule(root, p);
  readEffects(root, p);
  readAccuracy(root, p);
  readOutputs(root, p);
  checkEquilibriumPostures(p);

  std::vector<Diagnostic> diagnostics = std::move(reader_.diagnostics());
  if (!diagnostics.empty()) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& a, const Diagnostic& b) {
                       return std::tie(a.where.file, a.where.line, a.where.column) <
                              std::tie(b.where.file, b.where.line, b.where.column);
                     });
    throw ProtocolError(std::move(diagnostics));
  }
  return p;
}

void ProtocolParser::readEye(const Table& root, Protocol& p) {
  const std::optional<Table> eye = reader_.table(root, "eye");
  if (!eye) return;
  EyeSpec& e = p.eye;
  const auto kind = reader_.choice(*eye, "kind");
  if (kind) e.kind = {static_cast<EyeKind>(kind->value), kind->where};
  if (auto side = reader_.choice(*eye, "side"))
    e.side = {static_cast<EyeSide>(side->value), side->where};
  e.axialLength = reader_.quantity(*eye, "axial_length");
  e.staphylomaDepth = reader_.quantity(*eye, "staphyloma_depth");
  e.staphylomaWidth = reader_.quantity(*eye, "staphyloma_width");
  const auto meshPath = reader_.string(*eye, "mesh");
  const auto meshUnits = reader_.choice(*eye, "mesh_units");
  if (kind) checkEyeKind(*eye, meshPath, meshUnits, e);

  for (const Table& t : reader_.tableArray(*eye, "breaks")) e.breaks.push_back(readBreak(t));
  for (std::size_t i = 0; i < e.breaks.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (!e.breaks[i].name.value.empty() && e.breaks[i].name.value == e.breaks[j].name.value)
        reader_.error(e.breaks[i].name.where,
                      "two breaks are named '" + e.breaks[i].name.value + "' (the other at line " +
                          std::to_string(e.breaks[j].name.where.line) + ")",
                      "give each break its own name: the report lists coverage per break");
  e.sclera = readTissue(*eye, "sclera", true);
  e.orbitalFat = readTissue(*eye, "orbital_fat", false);
  if (kind && e.kind.value == EyeKind::kMesh) checkMeshEye(e);
}

// The keys each kind of eye needs and those it must not have; the mesh source of a mesh eye.
void ProtocolParser::checkEyeKind(const Table& eye,
                                  const std::optional<Located<std::string>>& meshPath,
                                  const std::optional<Located<std::size_t>>& meshUnits,
                                  EyeSpec& e) {
  const EyeKind k = e.kind.value;
  const std::string kindText = "kind = \"" + std::string(toString(k)) + "\"";
  if (k == EyeKind::kMyopic || k == EyeKind::kStaphyloma)
    requireConditional(eye, "axial_length", e.axialLength.has_value(),
                       "an eye of " + kindText + " needs its axial length");
  if (k == EyeKind::kStaphyloma) {
    requireConditional(eye, "staphyloma_depth", e.staphylomaDepth.has_value(),
                       "a staphyloma needs its depth");
    requireConditional(eye, "staphyloma_width", e.staphylomaWidth.has_value(),
                       "a staphyloma needs its width");
  } else {
    for (std::string_view key : {"staphyloma_depth", "staphyloma_width"})
      forbid(eye, key, "applies only to kind = \"staphyloma\", not " + kindText,
             "remove it, or set kind = \"staphyloma\"");
  }
  if (k == EyeKind::kMesh) {
    forbid(eye, "axial_length", "does not apply to an imported mesh (its size is the mesh's)",
           "remove it, or scale the mesh with mesh_units");
    requireConditional(eye, "mesh", meshPath.has_value(), "kind = \"mesh\" needs the mesh file");
    requireConditional(eye, "mesh_units", meshUnits.has_value(),
                       "mesh files carry no units, so the protocol must say them");
    if (meshPath && meshUnits) e.mesh = readMeshSource(*meshPath, *meshUnits);
  } else {
    for (std::string_view key : {"mesh", "mesh_units"})
      forbid(eye, key, "applies only to kind = \"mesh\", not " + kindText,
             "remove it, or set kind = \"mesh\"");
  }
}

// The mesh file (relative to the protocol file's folder) and its units.
MeshSource ProtocolParser::readMeshSource(const Located<std::string>& meshPath,
                                          const Located<std::size_t>& meshUnits) {
  MeshSource m;
  m.pathAsWritten = meshPath.value;
  const std::filesystem::path written(meshPath.value);
  const std::filesystem::path resolved =
      written.is_absolute() ? written : file_.parent_path() / written;
  m.path = {resolved.lexically_normal(), meshPath.where};
  const std::string_view unit = parameterSpec("eye.mesh_units").choices[meshUnits.value];
  m.units = {std::string(unit), meshUnits.where};
  m.metresPerUnit = findUnit(unit)->toSi;
  if (const std::string problem = meshPathProblem(m.path.value); !problem.empty())
    reader_.error(
        meshPath.where, "eye.mesh " + problem + ": " + m.path.value.string(),
        "the path is relative to the protocol file's folder (" +
            (file_.parent_path().empty() ? std::string(".") : file_.parent_path().string()) + ")");
  return m;
}

// What an imported mesh cannot carry, found by validate rather than at assembly: breaks are
// placed by clinical coordinates and elastic tissue is sampled from the anatomy, neither of which
// a mesh has (scenario.cpp and tissue_particles.cpp refuse the same at assembly).
void ProtocolParser::checkMeshEye(const EyeSpec& e) {
  if (!e.breaks.empty())
    reader_.error(e.breaks.front().where,
                  "retinal break '" + e.breaks.front().name.value +
                      "' on an imported mesh cavity (kind = \"mesh\")",
                  "breaks are placed by clinical coordinates, which need a parametric eye (kind "
                  "= \"emmetropic\", \"myopic\" or \"staphyloma\"); remove the breaks or use one");
  for (const std::optional<TissueSpec>* tissue : {&e.sclera, &e.orbitalFat})
    if (*tissue && (*tissue)->mode.value == TissueMode::kElastic)
      reader_.error((*tissue)->mode.where,
                    std::string("mode = \"elastic\" for the ") +
                        (tissue == &e.sclera ? "sclera" : "orbital fat") +
                        " on an imported mesh cavity, which has no anatomy to sample it from",
                    "use a parametric eye (kind = \"emmetropic\", \"myopic\" or \"staphyloma\") "
                    "or set mode = \"rigid\"");
}

RetinalBreak ProtocolParser::readBreak(const Table& t) {
  RetinalBreak b;
  b.where = t.where;
  if (auto name = reader_.string(t, "name")) b.name = *name;
  if (auto hour = reader_.number(t, "clock_hour")) b.clockHour = *hour;
  const auto limbus = reader_.quantity(t, "posterior_to_limbus");
  const auto ora = reader_.quantity(t, "posterior_to_ora");
  const bool hasLimbus = t.table->get("posterior_to_limbus") != nullptr;
  const bool hasOra = t.table->get("posterior_to_ora") != nullptr;
  if (hasLimbus && hasOra) {
    reader_.error(reader_.at(t.table->get("posterior_to_ora")->source()),
                  t.shownPath + " gives both posterior_to_limbus and posterior_to_ora",
                  "give the distance from one reference only");
  } else if (!hasLimbus && !hasOra) {
    reader_.error(t.where, t.shownPath + " has no position along the wall",
                  "add posterior_to_limbus = \"14 mm\" or posterior_to_ora = \"3 mm\"");
  }
  if (limbus) {
    b.reference = DistanceReference::kLimbus;
    b.distance = *limbus;
  } else if (ora) {
    b.reference = DistanceReference::kOraSerrata;
    b.distance = *ora;
  }
  if (auto d = reader_.quantity(t, "diameter")) b.diameter = *d;
  return b;
}

std::optional<TissueSpec> ProtocolParser::readTissue(const Table& eye, std::string_view key,
                                                     bool isSclera) {
  const std::optional<Table> t = reader_.table(eye, key);
  if (!t) return std::nullopt;
  TissueSpec s;
  s.where = t->where;
  if (auto m = reader_.choice(*t, "material"))
    s.material = {std::string(kTissueMaterialNames[m->value]), m->where};
  else
    s.material = {isSclera ? "sclera" : "orbital_fat", defaultAt_};
  s.youngsModulus = reader_.quantity(*t, "youngs_modulus");
  s.poissonRatio = reader_.number(*t, "poisson_ratio");
  s.density = reader_.quantity(*t, "density");
  if (isSclera) s.thickness = reader_.quantity(*t, "thickness");
  s.mode = choiceOr(*t, "mode", TissueMode::kAuto);
  // Anchoring choices differ per tissue; map the chosen name to the common enum.
  s.anchoring = {isSclera ? Anchoring::kOuterSurface : Anchoring::kBackFace, defaultAt_};
  if (auto a = reader_.choice(*t, "anchoring")) {
    const std::string_view name = parameterSpec(t->specPath + ".anchoring").choices[a->value];
    for (std::size_t k = 0; k < kAnchoringNames.size(); ++k)
      if (kAnchoringNames[k] == name) s.anchoring = {static_cast<Anchoring>(k), a->where};
  }
  return s;
}

void ProtocolParser::readTamponade(const Table& root, Protocol& p) {
  const std::optional<Table> t = reader_.table(root, "tamponade");
  if (!t) return;
  TamponadeSpec& s = p.tamponade;
  const toml::node* agentNode = t->table->get("agent");
  if (agentNode != nullptr && agentNode->value<std::string_view>() == std::string_view("aqueous")) {
    reader_.error(reader_.at(agentNode->source()),
                  "tamponade.agent 'aqueous' is not a tamponade: the volume the agent does not "
                  "fill is aqueous",
                  "choose one of " + joinNames(kTamponadeAgentNames, true));
  } else if (auto a = reader_.choice(*t, "agent")) {
    s.agent = {std::string(kTamponadeAgentNames[a->value]), a->where};
  }
  if (auto f = reader_.quantity(*t, "fill")) s.fill = *f;
  s.density = reader_.quantity(*t, "density");
  s.viscosity = reader_.viscosity(*t, "viscosity");
  s.interfacialTension = reader_.quantity(*t, "interfacial_tension");
  s.contactAngle = reader_.quantity(*t, "contact_angle");
  if (s.isCustom()) {
    const std::string why =
        "agent = \"custom\" has no library values, so it needs all of density, "
        "viscosity, interfacial_tension and contact_angle";
    requireConditional(*t, "density", s.density.has_value(), why);
    requireConditional(*t, "viscosity", s.viscosity.has_value(), why);
    requireConditional(*t, "interfacial_tension", s.interfacialTension.has_value(), why);
    requireConditional(*t, "contact_angle", s.contactAngle.has_value(), why);
  }
}

void ProtocolParser::readSchedule(const Table& root, Protocol& p) {
  p.schedule.steadyWindow = {kDefaultSteadyWindow, defaultAt_};
  p.schedule.steadyCoverageChange = {kDefaultSteadyCoverageChange, defaultAt_};
  p.schedule.start = {StartName::kFillPlane, defaultAt_};
  const std::optional<Table> t = reader_.table(root, "schedule");
  if (!t) return;
  p.schedule.start = choiceOr(*t, "start", StartName::kFillPlane);
  p.schedule.gravity = quantityOr(*t, "gravity", kStandardGravity);
  p.schedule.steadyWindow = quantityOr(*t, "steady_window", kDefaultSteadyWindow);
  p.schedule.steadyCoverageChange =
      quantityOr(*t, "steady_coverage_change", kDefaultSteadyCoverageChange);
  const std::vector<Table> postures = reader_.tableArray(*t, "postures");
  const toml::node* node = t->table->get("postures");
  if (postures.empty() && node != nullptr && node->is_array() && node->as_array()->empty())
    reader_.error(reader_.at(node->source()), "schedule.postures is empty",
                  "add at least one [[schedule.postures]] table with a name and a duration");
  for (const Table& pt : postures) {
    Posture posture;
    posture.where = pt.where;
    const auto name = reader_.choice(pt, "name");
    const auto gravity = reader_.direction(pt, "gravity_direction");
    const bool hasName = pt.table->get("name") != nullptr;
    const bool hasGravity = pt.table->get("gravity_direction") != nullptr;
    if (hasName && hasGravity)
      reader_.error(reader_.at(pt.table->get("gravity_direction")->source()),
                    pt.shownPath + " gives both a name and a gravity_direction",
                    "keep one: a named posture already fixes the gravity direction");
    else if (!hasName && !hasGravity)
      reader_.error(pt.where, pt.shownPath + " has neither a name nor a gravity_direction",
                    "add name = \"supine\" (or " + joinNames(kPostureNames, true) +
                        "), or gravity_direction = [x, y, z] in the eye frame");
    if (name) {
      posture.name = {static_cast<PostureName>(name->value), name->where};
      posture.label = {std::string(kPostureNames[name->value]), defaultAt_};
    } else if (gravity) {
      posture.name = {PostureName::kCustom, gravity->where};
      posture.gravityDirection = *gravity;
      posture.label = {"custom", defaultAt_};
    }
    if (auto label = reader_.string(pt, "label")) posture.label = *label;
    const auto duration = reader_.durationOrSteady(pt, "duration");
    const auto limit = reader_.quantity(pt, "max_duration");
    if (duration) {
      posture.untilSteady = duration->value == kUntilSteadyDuration;
      posture.equilibrium = duration->value == kEquilibriumDuration;
      posture.duration = posture.untilSteady   ? Located<double>{kDefaultSteadyLimit, defaultAt_}
                         : posture.equilibrium ? Located<double>{kEquilibriumHold, duration->where}
                                               : *duration;
      if (posture.untilSteady && limit) posture.duration = *limit;
      if (!posture.untilSteady)
        forbid(pt, "max_duration", "applies only to duration = \"until steady\"",
               "remove it: this posture has a fixed duration");
    }
    p.schedule.postures.push_back(std::move(posture));
  }
}

// Equilibrium postures come first: a schedule may begin with postures at their static
// equilibrium and continue with simulated ones, the first of which starts from the equilibrium
// just before it (protocols/equilibrium/start_from_equilibrium.h). An equilibrium after a
// simulated posture is refused: it does not depend on what was simulated, and a run that turned
// from stepping particles back to solving would need its checkpoints to hold both. Where the
// schedule begins with equilibria, schedule.start has nothing to choose. Any equilibrium needs a
// contact angle with a contact line (0 and 180 deg are complete wetting).
void ProtocolParser::checkEquilibriumPostures(const Protocol& p) {
  const auto& postures = p.schedule.postures;
  const auto first = std::find_if(postures.begin(), postures.end(),
                                  [](const Posture& x) { return x.equilibrium; });
  const bool startsAtEquilibrium = p.schedule.start.value == StartName::kEquilibrium;
  if (first == postures.end() && !startsAtEquilibrium) return;
  const auto simulated = std::find_if(postures.begin(), postures.end(),
                                      [](const Posture& x) { return !x.equilibrium; });
  for (auto later = simulated; later != postures.end(); ++later)
    if (later->equilibrium) {
      reader_.error(later->duration.where.isInFile() ? later->duration.where : later->where,
                    fmt::format("posture {} ({}) asks for its equilibrium after the simulated "
                                "posture {} ({})",
                                later - postures.begin() + 1, later->label.value,
                                simulated - postures.begin() + 1, simulated->label.value),
                    "move the postures with duration = \"equilibrium\" before the simulated "
                    "ones (the first simulated posture then starts from the equilibrium before "
                    "it), or compute this equilibrium in a protocol of its own: it does not "
                    "depend on what was simulated before it");
      return;
    }
  if (first != postures.end() && simulated != postures.end() && p.schedule.start.where.isInFile())
    reader_.error(p.schedule.start.where,
                  fmt::format("schedule.start does not apply to a schedule that begins with "
                              "postures at their equilibrium: its first simulated posture ({}) "
                              "starts from the equilibrium of the posture before it ({})",
                              simulated->label.value, (simulated - 1)->label.value),
                  "remove schedule.start");
  const std::string needs = first != postures.end()
                                ? "the equilibrium of duration = \"equilibrium\""
                                : "schedule.start = \"equilibrium\"";
  if (const auto& angle = p.tamponade.contactAngle;
      angle && (angle->value <= 0.0 || angle->value >= std::numbers::pi))
    reader_.error(
        angle->where,
        "tamponade.contact_angle = " + std::to_string(angle->value * 180.0 / std::numbers::pi) +
            " deg: complete wetting has no contact line, and " + needs + " needs one",
        "give an angle strictly between 0 and 180 deg (the retina's is about 18 deg "
        "through the aqueous)");
}

void ProtocolParser::readEffects(const Table& root, Protocol& p) {
  const std::span<const std::string_view> names = effectSwitchNames();
  p.effects.settings.assign(names.size(), {EffectSetting::kAuto, defaultAt_});
  const std::optional<Table> t = reader_.table(root, "effects");
  if (!t) return;
  for (std::size_t k = 0; k < names.size(); ++k)
    if (auto s = reader_.effectSwitch(*t, names[k])) p.effects.settings[k] = *s;
}

void ProtocolParser::readAccuracy(const Table& root, Protocol& p) {
  AccuracySpec& a = p.accuracy;
  a.preset = {AccuracyPreset::kStandard, defaultAt_};
  const std::optional<Table> t = reader_.table(root, "accuracy");
  if (t) a.preset = choiceOr(*t, "preset", AccuracyPreset::kStandard);
  const AccuracyPresetValues& preset = kAccuracyPresets[static_cast<std::size_t>(a.preset.value)];
  a.particleSpacing = {preset.particleSpacing, defaultAt_};
  a.solverTolerance = {preset.solverTolerance, defaultAt_};
  a.minTimeStep = {preset.minTimeStep, defaultAt_};
  a.maxTimeStep = {preset.maxTimeStep, defaultAt_};
  a.surfaceStress = {SurfaceStressName::kAuto, defaultAt_};
  a.wallModel = {WallModelName::kAuto, defaultAt_};
  if (!t) return;
  a.surfaceStress = choiceOr(*t, "surface_stress", SurfaceStressName::kAuto);
  a.wallModel = choiceOr(*t, "wall_model", WallModelName::kAuto);
  if (auto v = reader_.quantity(*t, "particle_spacing")) a.particleSpacing = *v;
  if (auto v = reader_.quantity(*t, "solver_tolerance")) a.solverTolerance = *v;
  if (auto v = reader_.quantity(*t, "min_time_step")) a.minTimeStep = *v;
  if (auto v = reader_.quantity(*t, "max_time_step")) a.maxTimeStep = *v;
  if (a.minTimeStep.value > a.maxTimeStep.value) {
    const Located<double>& explicitOne =
        a.maxTimeStep.where.isInFile() ? a.maxTimeStep : a.minTimeStep;
    reader_.error(explicitOne.where.isInFile() ? explicitOne.where : t->where,
                  "accuracy.min_time_step (" + formatIn(a.minTimeStep.value, "s") +
                      ") is larger than accuracy.max_time_step (" +
                      formatIn(a.maxTimeStep.value, "s") + ")",
                  "make min_time_step <= max_time_step");
  }
}

void ProtocolParser::readOutputs(const Table& root, Protocol& p) {
  OutputsSpec& o = p.outputs;
  o.folder = {"runs/" + file_.stem().string(), defaultAt_};
  o.frameInterval = {kDefaultFrameInterval, defaultAt_};
  for (std::string_view f : kDefaultFields) o.fields.push_back({std::string(f), defaultAt_});
  o.report = {true, defaultAt_};
  const std::optional<Table> t = reader_.table(root, "outputs");
  if (!t) return;
  if (auto v = reader_.string(*t, "folder")) {
    if (v->value.empty())
      reader_.error(v->where, "outputs.folder is empty",
                    "give a folder, e.g. folder = \"runs/my_case\"");
    else
      o.folder = *v;
  }
  o.frameInterval = quantityOr(*t, "frame_interval", kDefaultFrameInterval);
  if (auto fields = reader_.stringList(*t, "fields")) {
    o.fields = std::move(*fields);
    for (std::size_t i = 0; i < o.fields.size(); ++i) {
      const std::string& f = o.fields[i].value;
      const bool isIdentifier = !f.empty() && std::all_of(f.begin(), f.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
      });
      if (!isIdentifier)
        reader_.error(
            o.fields[i].where, "outputs.fields: '" + f + "' is not a field name",
            "field names are lower_case identifiers such as \"position\" or \"pressure\"");
      for (std::size_t j = 0; j < i; ++j)
        if (o.fields[j].value == f)
          reader_.error(o.fields[i].where, "outputs.fields lists '" + f + "' twice",
                        "list each field once");
    }
  }
  if (auto v = reader_.boolean(*t, "report")) o.report = *v;
}

}  // namespace

Protocol parseProtocolText(std::string_view text, const std::filesystem::path& file) {
  return ProtocolParser(file).parse(text);
}

Protocol parseProtocolDocument(const toml::table& document, const std::filesystem::path& file) {
  return ProtocolParser(file).parse(document);
}

Protocol parseProtocol(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw ProtocolError(
        {Diagnostic{SourceLocation{file.string(), 0, 0}, "is a folder, not a protocol file",
                    "give the path of a .toml protocol file"}});
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw ProtocolError(
        {Diagnostic{SourceLocation{file.string(), 0, 0}, "cannot open the protocol file",
                    "check the path (see data/protocols/ for examples)"}});
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parseProtocolText(text.str(), file);
}

}  // namespace protocols
