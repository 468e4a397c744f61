#include "protocols/format/parameter_table.h"

#include <array>
#include <cctype>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "protocols/format/edit_distance.h"
#include "protocols/format/protocol.h"
#include "protocols/format/stage_names.h"
#include "sim/world/stage_registry.h"

namespace protocols {

namespace {

using D = Dimension;
using K = ValueKind;
using R = Requirement;

constexpr std::array<std::string_view, 4> kMeshUnitNames = {"m", "cm", "mm", "um"};
constexpr std::array<std::string_view, 2> kScleraAnchoring = {"outer_surface", "none"};
constexpr std::array<std::string_view, 2> kFatAnchoring = {"back_face", "none"};
constexpr std::array<std::string_view, 1> kFormatVersions = {"1"};

// Ranges are physical or anatomical plausibility limits in SI, chosen wide enough never to reject
// a real eye: adult axial lengths 20-30 mm with high myopia up to ~35 mm, scleral thickness
// 0.4-1.0 mm (Vurgese 2012, reference-data.md 4.4), Poisson ratio of an isotropic stable solid in
// [0, 0.5) (0.5 = incompressible is singular for the linear elastic model).
// Durations, intervals and windows (simulated time). Floor: 1 ms, a few time steps at the
// presets' largest step (0.5-2 ms); a shorter frame interval or steady window would only
// re-sample every step, and a shorter posture would end inside its first step. Ceiling: one day,
// about 1e8-1e9 steps: longer is no run this toolkit can finish. Both show in the range column of
// docs/protocols.md's reference.
constexpr double kShortestTime = 1e-3;  // [s]
constexpr double kLongestTime = 86400;  // [s]

// clang-format off
const ParameterSpec kParameters[] = {
  {.key = "format_version", .kind = K::kInteger, .min = 1, .max = 1, .requirement = R::kRequired,
   .example = "1", .doc = "Version of this file format; this toolkit reads version 1."},
  {.key = "title", .kind = K::kString, .example = "\"Superior break, 90 % SO 1000, supine then upright\"",
   .doc = "Short name of the scenario, shown in the report."},
  {.key = "description", .kind = K::kString, .example = "\"...\"",
   .doc = "The scenario in words, shown in the report."},
  {.key = "solver", .kind = K::kChoice, .choices = solverNames(), .defaultText = kDefaultSolver,
   .example = "\"indsph\"", .doc = "Pressure solver (all share one interface; docs/methods/solvers.md)."},

  {.key = "eye", .kind = K::kTable, .requirement = R::kRequired, .doc = "The eye: cavity shape, side, breaks, tissues."},
  {.key = "eye.kind", .kind = K::kChoice, .choices = kEyeKindNames, .requirement = R::kRequired,
   .example = "\"emmetropic\"", .doc = "Parametric cavity (emmetropic, myopic, staphyloma) or an imported mesh."},
  {.key = "eye.side", .kind = K::kChoice, .choices = kEyeSideNames, .requirement = R::kRequired,
   .example = "\"OD\"", .doc = "Which eye: OD = right, OS = left (decides nasal/temporal)."},
  {.key = "eye.axial_length", .kind = K::kQuantity, .dimension = D::kLength, .displayUnit = "mm",
   .min = 18e-3, .max = 36e-3, .requirement = R::kConditional,
   .condition = "required for myopic and staphyloma; optional for emmetropic; not for mesh",
   .defaultText = "anatomy's emmetropic eye", .example = "\"28 mm\"", .doc = "Axial length of the eye."},
  {.key = "eye.staphyloma_depth", .kind = K::kQuantity, .dimension = D::kLength, .displayUnit = "mm",
   .min = 0, .max = 8e-3, .minInclusive = false, .requirement = R::kConditional,
   .condition = "kind = staphyloma only (required)", .example = "\"2 mm\"",
   .doc = "How far the posterior staphyloma bulges behind the regular wall."},
  {.key = "eye.staphyloma_width", .kind = K::kQuantity, .dimension = D::kLength, .displayUnit = "mm",
   .min = 0, .max = 25e-3, .minInclusive = false, .requirement = R::kConditional,
   .condition = "kind = staphyloma only (required)", .example = "\"8 mm\"",
   .doc = "Diameter of the staphyloma's base on the wall."},
  {.key = "eye.mesh", .kind = K::kPath, .requirement = R::kConditional,
   .condition = "kind = mesh only (required)", .example = "\"../meshes/eye.stl\"",
   .doc = "Cavity surface mesh (STL/OBJ/PLY), relative to this protocol file."},
  {.key = "eye.mesh_units", .kind = K::kChoice, .choices = kMeshUnitNames, .requirement = R::kConditional,
   .condition = "kind = mesh only (required)", .example = "\"mm\"",
   .doc = "Length unit of the mesh coordinates (mesh files carry none)."},

  {.key = "eye.breaks", .kind = K::kTableArray, .doc = "Retinal breaks, one [[eye.breaks]] table each."},
  {.key = "eye.breaks.name", .kind = K::kString, .requirement = R::kRequired, .example = "\"superior tear\"",
   .doc = "Name used in the report."},
  {.key = "eye.breaks.clock_hour", .kind = K::kNumber, .min = 1, .max = 13,
   .maxInclusive = false, .requirement = R::kRequired, .example = "12",
   .doc = "Clock position as the surgeon sees the fundus (12 superior); decimals allowed, 12.5 = half past 12."},
  {.key = "eye.breaks.posterior_to_limbus", .kind = K::kQuantity, .dimension = D::kLength, .displayUnit = "mm",
   .min = 0, .max = 40e-3, .minInclusive = false, .requirement = R::kConditional,
   .condition = "exactly one of posterior_to_limbus, posterior_to_ora", .example = "\"14 mm\"",
   .doc = "Distance along the wall posterior to the limbus."},
  {.key = "eye.breaks.posterior_to_ora", .kind = K::kQuantity, .dimension = D::kLength, .displayUnit = "mm",
   .min = 0, .max = 35e-3, .requirement = R::kConditional,
   .condition = "exactly one of posterior_to_limbus, posterior_to_ora", .example = "\"3 mm\"",
   .doc = "Distance along the wall posterior to the ora serrata."},
  {.key = "eye.breaks.diameter", .kind = K::kQuantity, .dimension = D::kLength, .displayUnit = "mm",
   .min = 0, .max = 20e-3, .minInclusive = false, .requirement = R::kRequired, .example = "\"2 mm\"",
   .doc = "Diameter of the break (a round patch of retina)."},

  {.key = "eye.sclera", .kind = K::kTable, .defaultText = "no sclera: rigid cavity wall",
   .doc = "Sclera as a tissue (elastic shell around the cavity)."},
  {.key = "eye.sclera.material", .kind = K::kChoice, .choices = kTissueMaterialNames,
   .defaultText = "sclera", .example = "\"sclera\"", .doc = "Material of the material library."},
  {.key = "eye.sclera.youngs_modulus", .kind = K::kQuantity, .dimension = D::kPressure, .displayUnit = "kPa",
   .min = 0, .max = 1e9, .minInclusive = false, .defaultText = "material", .example = "\"2 MPa\"",
   .doc = "Young's modulus (overrides the material)."},
  {.key = "eye.sclera.poisson_ratio", .kind = K::kNumber, .min = 0, .max = 0.5, .maxInclusive = false,
   .defaultText = "material", .example = "0.45", .doc = "Poisson ratio (overrides the material)."},
  {.key = "eye.sclera.density", .kind = K::kQuantity, .dimension = D::kDensity, .displayUnit = "kg/m^3",
   .min = 0, .max = 5000, .minInclusive = false, .defaultText = "material", .example = "\"1100 kg/m^3\"",
   .doc = "Density (overrides the material)."},
  {.key = "eye.sclera.thickness", .kind = K::kQuantity, .dimension = D::kLength, .displayUnit = "mm",
   .min = 0, .max = 3e-3, .minInclusive = false, .defaultText = "anatomical profile, limbus to pole",
   .example = "\"0.7 mm\"", .doc = "Uniform scleral thickness (overrides the anatomical profile)."},
  {.key = "eye.sclera.mode", .kind = K::kChoice, .choices = kTissueModeNames, .defaultText = "auto",
   .example = "\"auto\"", .doc = "auto: elastic only if the estimated deformation matters; or force elastic / rigid."},
  {.key = "eye.sclera.anchoring", .kind = K::kChoice, .choices = kScleraAnchoring,
   .defaultText = "outer_surface", .example = "\"outer_surface\"", .doc = "Which particles are held fixed."},

  {.key = "eye.orbital_fat", .kind = K::kTable, .defaultText = "no orbital fat",
   .doc = "Orbital fat behind the globe as a tissue."},
  {.key = "eye.orbital_fat.material", .kind = K::kChoice, .choices = kTissueMaterialNames,
   .defaultText = "orbital_fat", .example = "\"orbital_fat\"", .doc = "Material of the material library."},
  {.key = "eye.orbital_fat.youngs_modulus", .kind = K::kQuantity, .dimension = D::kPressure, .displayUnit = "kPa",
   .min = 0, .max = 1e9, .minInclusive = false, .defaultText = "material", .example = "\"1 kPa\"",
   .doc = "Young's modulus (overrides the material)."},
  {.key = "eye.orbital_fat.poisson_ratio", .kind = K::kNumber, .min = 0, .max = 0.5, .maxInclusive = false,
   .defaultText = "material", .example = "0.45", .doc = "Poisson ratio (overrides the material)."},
  {.key = "eye.orbital_fat.density", .kind = K::kQuantity, .dimension = D::kDensity, .displayUnit = "kg/m^3",
   .min = 0, .max = 5000, .minInclusive = false, .defaultText = "material", .example = "\"950 kg/m^3\"",
   .doc = "Density (overrides the material)."},
  {.key = "eye.orbital_fat.mode", .kind = K::kChoice, .choices = kTissueModeNames, .defaultText = "auto",
   .example = "\"auto\"", .doc = "auto: elastic only if the estimated deformation matters; or force elastic / rigid."},
  {.key = "eye.orbital_fat.anchoring", .kind = K::kChoice, .choices = kFatAnchoring,
   .defaultText = "back_face", .example = "\"back_face\"", .doc = "Which particles are held fixed."},

  {.key = "tamponade", .kind = K::kTable, .requirement = R::kRequired,
   .doc = "The tamponade agent and fill; the rest of the cavity is aqueous."},
  {.key = "tamponade.agent", .kind = K::kChoice, .choices = kTamponadeAgentNames, .requirement = R::kRequired,
   .example = "\"silicone_oil_1000\"", .doc = "Agent of the material library, or custom (then give all four properties below)."},
  {.key = "tamponade.fill", .kind = K::kQuantity, .dimension = D::kFraction, .min = 0, .max = 1,
   .minInclusive = false, .requirement = R::kRequired, .example = "\"90 %\"",
   .doc = "Fraction of the cavity volume filled with the agent."},
  {.key = "tamponade.density", .kind = K::kQuantity, .dimension = D::kDensity, .displayUnit = "kg/m^3",
   .min = 0, .max = 3000, .minInclusive = false, .requirement = R::kConditional,
   .condition = "required for custom; overrides a library agent", .example = "\"970 kg/m^3\"", .doc = "Density."},
  {.key = "tamponade.viscosity", .kind = K::kViscosity, .min = 0, .minInclusive = false,
   .requirement = R::kConditional, .condition = "required for custom; overrides a library agent",
   .example = "\"1000 cSt\"", .doc = "Dynamic (mPa s, Pa s, cP) or kinematic (cSt, mm^2/s, m^2/s, St) viscosity: the unit says which."},
  {.key = "tamponade.interfacial_tension", .kind = K::kQuantity, .dimension = D::kSurfaceTension,
   .displayUnit = "mN/m", .min = 0, .max = 0.1, .minInclusive = false, .requirement = R::kConditional,
   .condition = "required for custom; overrides a library agent", .example = "\"35 mN/m\"",
   .doc = "Interfacial tension between the agent and aqueous."},
  {.key = "tamponade.contact_angle", .kind = K::kQuantity, .dimension = D::kAngle, .displayUnit = "deg",
   .min = 0, .max = 3.14159265358979323846, .requirement = R::kConditional,
   .condition = "required for custom; overrides a library agent", .example = "\"18 deg\"",
   .doc = "Contact angle on retina measured THROUGH THE AQUEOUS phase (0 = aqueous wets the wall)."},

  {.key = "schedule", .kind = K::kTable, .requirement = R::kRequired, .doc = "The posture schedule."},
  {.key = "schedule.gravity", .kind = K::kQuantity, .dimension = D::kAcceleration, .displayUnit = "m/s^2",
   .min = 0, .max = 100, .minInclusive = false, .defaultText = "1 g = 9.80665 m/s^2", .example = "\"1 g\"",
   .doc = "Magnitude of gravity."},
  {.key = "schedule.steady_window", .kind = K::kQuantity, .dimension = D::kDuration, .displayUnit = "s",
   .min = kShortestTime, .max = kLongestTime, .defaultText = "0.5 s", .example = "\"2 s\"",
   .doc = "\"until steady\": simulated time over which the flow must have stayed calm and every region's coverage flat."},
  {.key = "schedule.steady_coverage_change", .kind = K::kQuantity, .dimension = D::kFraction, .min = 0, .max = 1,
   .minInclusive = false, .defaultText = "0.5 %", .example = "\"0.2 %\"",
   .doc = "\"until steady\": largest change (max - min over the window) of any region's or break's oil coverage."},
  {.key = "schedule.start", .kind = K::kChoice, .choices = kStartNames, .defaultText = "fill_plane",
   .example = "\"equilibrium\"",
   .doc = "Where a simulated schedule's fluid starts: oil above a flat fill plane, or where the first posture's static equilibrium puts it (not for a schedule that begins with postures at equilibrium: its first simulated posture starts from the last of them)."},
  {.key = "schedule.postures", .kind = K::kTableArray, .requirement = R::kRequired,
   .doc = "Postures in the order they are held, one [[schedule.postures]] table each."},
  {.key = "schedule.postures.name", .kind = K::kChoice, .choices = kPostureNames, .requirement = R::kConditional,
   .condition = "exactly one of name, gravity_direction", .example = "\"supine\"",
   .doc = "A named head posture (the anatomy layer turns it into a gravity direction in the eye frame)."},
  {.key = "schedule.postures.gravity_direction", .kind = K::kDirection, .requirement = R::kConditional,
   .condition = "exactly one of name, gravity_direction", .example = "[0.0, -0.7071, -0.7071]",
   .doc = "Direction of gravity in the eye frame (+x patient's left, +y superior, +z anterior); normalised."},
  {.key = "schedule.postures.label", .kind = K::kString, .defaultText = "the name, or \"custom\"",
   .example = "\"reclined 45 deg\"", .doc = "Label of the posture in the report."},
  {.key = "schedule.postures.duration", .kind = K::kDurationOrSteady, .dimension = D::kDuration,
   .displayUnit = "s", .min = kShortestTime, .max = kLongestTime, .requirement = R::kRequired, .example = "\"10 min\"",
   .doc = "How long the posture is held, \"until steady\" (simulated until the coverage stops changing), or \"equilibrium\" (the static equilibrium of the posture, computed directly in seconds; docs/methods/equilibrium.md). Postures at equilibrium come before the simulated ones."},
  {.key = "schedule.postures.max_duration", .kind = K::kQuantity, .dimension = D::kDuration, .displayUnit = "s",
   .min = kShortestTime, .max = kLongestTime, .requirement = R::kConditional, .condition = "only with duration = \"until steady\"",
   .defaultText = "10 min", .example = "\"30 min\"", .doc = "Upper bound on an \"until steady\" posture."},

  {.key = "effects", .kind = K::kTable, .defaultText = "all inferred",
   .doc = "Force a physical effect on (true) or off (false); \"auto\" or absent = inferred from the scene."},
  // effects.<name>: one row per forceable effect of the engine's registry (effectRows).

  {.key = "accuracy", .kind = K::kTable, .defaultText = "preset standard",
   .doc = "A preset, and explicit values that override it."},
  {.key = "accuracy.preset", .kind = K::kChoice, .choices = kAccuracyPresetNames, .defaultText = "standard",
   .example = "\"draft\"", .doc = "draft / standard / fine: spacing, tolerance and time-step bounds (table above)."},
  {.key = "accuracy.particle_spacing", .kind = K::kQuantity, .dimension = D::kLength, .displayUnit = "mm",
   .min = 0.02e-3, .max = 5e-3, .defaultText = "preset", .example = "\"0.4 mm\"",
   .doc = "Particle spacing. `plan` and `run` estimate the memory first and refuse a spacing that needs more than the machine has available (or `--max-memory`), naming the finest that fits."},
  {.key = "accuracy.solver_tolerance", .kind = K::kQuantity, .dimension = D::kFraction, .min = 0, .max = 0.05,
   .minInclusive = false, .defaultText = "preset", .example = "\"0.1 %\"",
   .doc = "Mean relative density error at which the implicit pressure solve (INDSPH, DFSPH, IISPH) stops, within its 100-iteration cap; the report states what it reached. The explicit solvers have none. `tamponade bench accuracy` measures its cost and effect."},
  {.key = "accuracy.min_time_step", .kind = K::kQuantity, .dimension = D::kDuration, .displayUnit = "s",
   .min = 0, .max = 1, .minInclusive = false, .defaultText = "preset", .example = "\"1e-7 s\"",
   .doc = "Smallest time step before the run stops as unstable."},
  {.key = "accuracy.max_time_step", .kind = K::kQuantity, .dimension = D::kDuration, .displayUnit = "s",
   .min = 0, .max = 1, .minInclusive = false, .defaultText = "preset", .example = "\"1 ms\"",
   .doc = "Largest time step (the CFL and effect limits may choose smaller)."},
  {.key = "accuracy.surface_stress", .kind = K::kChoice, .choices = kSurfaceStressNames, .defaultText = "auto",
   .example = "\"symmetric\"",
   .doc = "Interfacial tension's discretisation: corrected (first-order consistent on disordered particles), symmetric (momentum-exact; INDSPH Laplace jump -16 %), auto: symmetric under WCSPH, corrected otherwise (docs/methods/interface.md)."},
  {.key = "accuracy.wall_model", .kind = K::kChoice, .choices = kWallModelNames, .defaultText = "auto",
   .example = "\"single_layer\"",
   .doc = "Cavity wall particles: layered (three lattice layers behind the mesh; the fluid fills the cavity; the contact angle holds as on the flat wall it was validated on; about 2x the run time), single_layer (one Akinci layer on the mesh), auto: layered unless an elastic sclera or fat replaces part of the wall (docs/accuracy.md)."},

  {.key = "outputs", .kind = K::kTable, .defaultText = "all defaults", .doc = "What the run writes."},
  {.key = "outputs.folder", .kind = K::kString, .defaultText = "runs/<protocol file name>",
   .example = "\"runs/superior_break\"", .doc = "Output folder, relative to the working directory; `tamponade run --out` overrides it."},
  {.key = "outputs.frame_interval", .kind = K::kQuantity, .dimension = D::kDuration, .displayUnit = "s",
   .min = kShortestTime, .max = kLongestTime, .defaultText = "1 s", .example = "\"0.5 s\"",
   .doc = "Simulated time between written frames."},
  {.key = "outputs.fields", .kind = K::kStringList, .defaultText = "[\"position\", \"velocity\", \"material\"]",
   .example = "[\"position\", \"velocity\", \"pressure\"]",
   .doc = "Particle fields written per frame (names of the engine's field registry, checked at assembly)."},
  {.key = "outputs.report", .kind = K::kBoolean, .defaultText = "true", .example = "true",
   .doc = "Write report.html, coverage.csv and summary.json."},
};
// clang-format on

std::string_view parentOf(std::string_view key) {
  const std::size_t dot = key.rfind('.');
  return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
}

std::string number(double si, std::string_view unit) {
  std::string text = formatIn(si, unit);
  // formatIn appends the unit; ranges print it once at the end instead.
  if (!unit.empty()) text.resize(text.size() - unit.size() - (unit == "%" ? 0 : 1));
  return text;
}

// kParameters with a row `effects.<name>` after the [effects] table's row for each effect the
// engine's registry lets a protocol force, documented by the registry's own words.
std::vector<ParameterSpec> withEffectRows() {
  struct Texts {
    std::vector<std::string> keys, docs;
  };
  static const Texts texts = [] {
    Texts t;
    for (const sim::EffectEntry& e : sim::effectRegistry()) {
      if (!e.forceable()) continue;
      std::string description = e.description;
      description.front() = static_cast<char>(std::toupper(description.front()));
      t.keys.push_back(fmt::format("effects.{}", e.name));
      t.docs.push_back(fmt::format("{} (inferred: {}).", description, e.inferredWhen));
    }
    return t;
  }();
  std::vector<ParameterSpec> rows;
  for (const ParameterSpec& spec : kParameters) {
    rows.push_back(spec);
    if (spec.key != "effects") continue;
    for (std::size_t k = 0; k < texts.keys.size(); ++k)
      rows.push_back({.key = texts.keys[k],
                      .kind = K::kEffectSwitch,
                      .defaultText = "auto",
                      .example = "true",
                      .doc = texts.docs[k]});
  }
  return rows;
}

}  // namespace

std::span<const ParameterSpec> parameterTable() {
  static const std::vector<ParameterSpec> rows = withEffectRows();
  return rows;
}

const ParameterSpec& parameterSpec(std::string_view key) {
  for (const ParameterSpec& spec : parameterTable())
    if (spec.key == key) return spec;
  throw std::logic_error("protocol parameter table has no key '" + std::string(key) + "'");
}

std::vector<std::string_view> childKeys(std::string_view tablePath) {
  std::vector<std::string_view> keys;
  for (const ParameterSpec& spec : parameterTable())
    if (parentOf(spec.key) == tablePath)
      keys.push_back(tablePath.empty() ? spec.key : spec.key.substr(tablePath.size() + 1));
  return keys;
}

std::string rangeText(const ParameterSpec& spec) {
  if (!spec.hasRange()) return {};
  const std::string_view unit = spec.displayUnit;
  const std::string suffix = unit.empty() || unit == "%" ? "" : fmt::format(" {}", unit);
  if (spec.min > -kUnbounded && spec.max < kUnbounded)
    return fmt::format("{}{}, {}{}{}", spec.minInclusive ? "[" : "(", number(spec.min, unit),
                       number(spec.max, unit), spec.maxInclusive ? "]" : ")", suffix);
  if (spec.min > -kUnbounded)
    return fmt::format("{}{}{}", spec.minInclusive ? ">= " : "> ", number(spec.min, unit), suffix);
  return fmt::format("{}{}{}", spec.maxInclusive ? "<= " : "< ", number(spec.max, unit), suffix);
}

std::string typeText(const ParameterSpec& spec) {
  switch (spec.kind) {
    case K::kTable: return "table";
    case K::kTableArray: return "array of tables";
    case K::kInteger: return "integer";
    case K::kNumber: return "number";
    case K::kQuantity:
      if (spec.dimension == D::kFraction) return "fraction (0.9 or \"90 %\")";
      return std::string(dimensionName(spec.dimension)) + " (" + unitSymbols(spec.dimension) + ")";
    case K::kViscosity: return "dynamic or kinematic viscosity";
    case K::kDurationOrSteady: return "duration, \"until steady\" or \"equilibrium\"";
    case K::kString: return "string";
    case K::kPath: return "path";
    case K::kChoice: return "one of " + joinNames(spec.choices);
    case K::kBoolean: return "boolean";
    case K::kEffectSwitch: return "true, false or \"auto\"";
    case K::kDirection: return "[x, y, z]";
    case K::kStringList: return "list of strings";
  }
  return "?";
}

std::string renderParameterReference() {
  auto cell = [](std::string text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
  };
  std::string md =
      "| key | type | range | required | default | example | description |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const ParameterSpec& spec : parameterTable()) {
    std::string required = spec.requirement == R::kRequired   ? "yes"
                           : spec.requirement == R::kOptional ? "no"
                                                              : std::string(spec.condition);
    const std::string example =
        spec.example.empty() ? std::string() : fmt::format("`{}`", cell(std::string(spec.example)));
    md += fmt::format("| `{}` | {} | {} | {} | {} | {} | {} |\n", spec.key, cell(typeText(spec)),
                      cell(rangeText(spec)), cell(required), cell(std::string(spec.defaultText)),
                      example, cell(std::string(spec.doc)));
  }
  return md;
}

std::string renderUnitTable() {
  constexpr std::array kDimensions = {
      D::kLength,         D::kDuration, D::kDensity, D::kDynamicViscosity, D::kKinematicViscosity,
      D::kSurfaceTension, D::kPressure, D::kAngle,   D::kFraction,         D::kAcceleration};
  std::string md = "| dimension | SI unit inside | units a protocol may use |\n|---|---|---|\n";
  for (Dimension d : kDimensions) {
    std::string units;
    for (const Unit& u : knownUnits()) {
      if (u.dimension != d) continue;
      if (!units.empty()) units += ", ";
      units += fmt::format("`{}` = {}", u.symbol, formatQuantity(u.toSi, d));
    }
    if (d == D::kFraction) units += " (or a bare number in [0, 1])";
    const std::string_view si = siUnit(d);
    md += "| " + std::string(dimensionName(d)) + " | " + (si.empty() ? "1" : std::string(si)) +
          " | " + units + " |\n";
  }
  return md;
}

std::string renderAccuracyPresetTable() {
  std::string md =
      "| preset | particle_spacing | solver_tolerance | min_time_step | max_time_step |\n"
      "|---|---|---|---|---|\n";
  for (const AccuracyPresetValues& p : kAccuracyPresets)
    md += "| `" + std::string(p.name) + "` | " + formatIn(p.particleSpacing, "mm") + " | " +
          formatIn(p.solverTolerance, "%") + " | " + formatIn(p.minTimeStep, "s") + " | " +
          formatIn(p.maxTimeStep, "ms") + " |\n";
  return md;
}

}  // namespace protocols
