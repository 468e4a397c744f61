// The protocol parser: a table of bad protocols, each with its expected message and place, and
// the shipped examples, which must all parse to what they say.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "protocols/format/parse_protocol.h"
#include "tests/support/scratch_directory.h"

namespace fs = std::filesystem;
using protocols::ProtocolError;

namespace {

// A minimal valid protocol; the bad cases replace one of its lines (numbered from 1).
const std::vector<std::string> kBaseLines = {
    "format_version = 1",             // 1
    "[eye]",                          // 2
    "kind = \"emmetropic\"",          // 3
    "side = \"OD\"",                  // 4
    "[tamponade]",                    // 5
    "agent = \"silicone_oil_1000\"",  // 6
    "fill = \"90 %\"",                // 7
    "[schedule]",                     // 8
    "[[schedule.postures]]",          // 9
    "name = \"supine\"",              // 10
    "duration = \"10 min\"",          // 11
};

std::string withLine(int line, const std::string& replacement) {
  std::string text;
  for (int k = 1; k <= static_cast<int>(kBaseLines.size()); ++k)
    text += (k == line ? replacement : kBaseLines[k - 1]) + "\n";
  return text;
}

struct BadCase {
  const char* name;
  std::string text;
  const char* fragment;  // expected in one diagnostic's "what — fix"
  int line;              // of that diagnostic
  int column;
};

std::vector<BadCase> badCases() {
  return {
      {"malformed TOML", withLine(7, "fill = \"90 %"), "malformed TOML", 7, 13},
      {"duplicate key", withLine(7, "fill = \"90 %\"\nfill = \"80 %\""),
       "cannot redefine existing string 'fill'", 8, 8},
      {"unknown key with suggestion", withLine(4, "side = \"OD\"\naxial_lenght = \"24 mm\""),
       "unknown key 'axial_lenght' in [eye] \u2014 did you mean 'axial_length'?", 5, 1},
      {"unknown top-level key", withLine(1, "format_version = 1\nsolvr = \"indsph\""),
       "unknown key 'solvr' at the top level \u2014 did you mean 'solver'?", 2, 1},
      {"wrong type", withLine(4, "side = 1"),
       "eye.side must be a string, one of 'OD', 'OS', not a integer 1", 4, 8},
      {"missing required key", withLine(7, ""),
       "missing required key 'tamponade.fill' in [tamponade]", 5, 1},
      {"missing required table", withLine(8, "").substr(0, withLine(8, "").find("[[schedule")),
       "missing required key 'schedule' at the top level \u2014 add the table [schedule]", 1, 1},
      {"missing format version", withLine(1, ""), "missing required key 'format_version'", 1, 1},
      {"unsupported format version", withLine(1, "format_version = 2"),
       "format_version = 2 is outside the allowed range [1, 1]", 1, 18},
      {"number without unit", withLine(4, "side = \"OD\"\naxial_length = 24"),
       "eye.axial_length = 24 has no unit, and a length needs one \u2014 write it as a string with "
       "a unit, e.g. axial_length = \"24 mm\"",
       5, 16},
      {"wrong dimension", withLine(4, "side = \"OD\"\naxial_length = \"12 kPa\""),
       "'kPa' in \"12 kPa\" is a unit of pressure, but a length is expected", 5, 16},
      {"unknown unit with suggestion", withLine(4, "side = \"OD\"\naxial_length = \"24 mmm\""),
       "unknown unit 'mmm' in \"24 mmm\" \u2014 did you mean 'mm'?", 5, 16},
      {"axial length out of range", withLine(4, "side = \"OD\"\naxial_length = \"4 cm\""),
       "eye.axial_length = 40 mm is outside the allowed range [18, 36] mm", 5, 16},
      {"fill 1.2", withLine(7, "fill = 1.2"),
       "tamponade.fill = 1.2 is outside the allowed range (0, 1]", 7, 8},
      {"fill 120 %", withLine(7, "fill = \"120 %\""),
       "tamponade.fill = 1.2 is outside the allowed range (0, 1]", 7, 8},
      {"fill 0", withLine(7, "fill = 0"), "tamponade.fill = 0 is outside the allowed range (0, 1]",
       7, 8},
      {"bare fill over 1 reads as a percentage typo", withLine(7, "fill = \"90\""),
       "write a fraction like 0.9, or a percentage like \"90 %\"", 7, 8},
      {"negative modulus", withLine(4, "side = \"OD\"\n[eye.sclera]\nyoungs_modulus = \"-2 MPa\""),
       "eye.sclera.youngs_modulus = -2000 kPa is outside the allowed range (0, 1e+06] kPa", 6, 18},
      {"Poisson ratio 0.5", withLine(4, "side = \"OD\"\n[eye.orbital_fat]\npoisson_ratio = 0.5"),
       "eye.orbital_fat.poisson_ratio = 0.5 is outside the allowed range [0, 0.5)", 6, 17},
      {"thickness only for sclera",
       withLine(4, "side = \"OD\"\n[eye.orbital_fat]\nthickness = \"1 mm\""),
       "unknown key 'thickness' in [eye.orbital_fat]", 6, 1},
      {"clock hour 13",
       withLine(4,
                "side = \"OD\"\n[[eye.breaks]]\nname = \"b\"\nclock_hour = 13\nposterior_to_limbus "
                "= \"14 mm\"\ndiameter = \"2 mm\""),
       "eye.breaks[1].clock_hour = 13 is outside the allowed range [1, 13)", 7, 14},
      {"break with two references",
       withLine(4,
                "side = \"OD\"\n[[eye.breaks]]\nname = \"b\"\nclock_hour = 6\nposterior_to_limbus "
                "= \"14 mm\"\nposterior_to_ora = \"3 mm\"\ndiameter = \"2 mm\""),
       "eye.breaks[1] gives both posterior_to_limbus and posterior_to_ora", 9, 20},
      {"break without position",
       withLine(4,
                "side = \"OD\"\n[[eye.breaks]]\nname = \"b\"\nclock_hour = 6\ndiameter = \"2 mm\""),
       "eye.breaks[1] has no position along the wall", 5, 1},
      {"duplicate break names",
       withLine(4,
                "side = \"OD\"\n[[eye.breaks]]\nname = \"b\"\nclock_hour = 6\nposterior_to_ora = "
                "\"3 mm\"\ndiameter = \"2 mm\"\n"
                "[[eye.breaks]]\nname = \"b\"\nclock_hour = 7\nposterior_to_ora = \"3 "
                "mm\"\ndiameter = \"2 mm\""),
       "two breaks are named 'b' (the other at line 6)", 11, 8},
      {"unknown eye kind with suggestion", withLine(3, "kind = \"myopia\""),
       "unknown kind 'myopia' for eye.kind \u2014 did you mean 'myopic'?", 3, 8},
      {"myopic eye needs axial length", withLine(3, "kind = \"myopic\""),
       "missing key 'eye.axial_length': an eye of kind = \"myopic\" needs its axial length", 2, 1},
      {"staphyloma keys on a non-staphyloma eye",
       withLine(4, "side = \"OD\"\nstaphyloma_depth = \"2 mm\""),
       "eye.staphyloma_depth applies only to kind = \"staphyloma\"", 5, 20},
      {"mesh file missing",
       withLine(3, "kind = \"mesh\"\nmesh = \"no_such_mesh.stl\"\nmesh_units = \"mm\""),
       "eye.mesh file not found", 4, 8},
      {"mesh units missing", withLine(3, "kind = \"mesh\"\nmesh = \"no_such_mesh.stl\""),
       "missing key 'eye.mesh_units': mesh files carry no units", 2, 1},
      {"aqueous is not a tamponade", withLine(6, "agent = \"aqueous\""),
       "'aqueous' is not a tamponade", 6, 9},
      {"unknown agent with suggestion", withLine(6, "agent = \"densiron68\""),
       "did you mean 'densiron_68'?", 6, 9},
      {"custom agent needs its properties",
       withLine(6, "agent = \"custom\"\ndensity = \"970 kg/m^3\""),
       "missing key 'tamponade.viscosity': agent = \"custom\" has no library values", 5, 1},
      {"viscosity without unit", withLine(7, "fill = \"90 %\"\nviscosity = 1000"),
       "say which viscosity it is with the unit: \"1000 cSt\" (kinematic) or \"970 mPa s\" "
       "(dynamic)",
       8, 13},
      {"contact angle without unit", withLine(7, "fill = \"90 %\"\ncontact_angle = 18"),
       "tamponade.contact_angle = 18 has no unit, and an angle needs one", 8, 17},
      {"unknown posture with suggestion", withLine(10, "name = \"face_down\""),
       "unknown name 'face_down' for schedule.postures[1].name \u2014 did you mean 'face-down'?",
       10, 8},
      {"posture with name and direction",
       withLine(10, "name = \"supine\"\ngravity_direction = [0, -1, 0]"),
       "schedule.postures[1] gives both a name and a gravity_direction", 11, 21},
      {"posture without name or direction", withLine(10, "label = \"x\""),
       "schedule.postures[1] has neither a name nor a gravity_direction", 9, 1},
      {"zero gravity direction", withLine(10, "gravity_direction = [0, 0, 0]"), "is a zero vector",
       10, 21},
      {"zero duration", withLine(11, "duration = \"0 s\""),
       "schedule.postures[1].duration = 0 s is outside the allowed range [0.001, 86400] s", 11, 12},
      {"negative duration", withLine(11, "duration = \"-5 min\""),
       "= -300 s is outside the allowed range [0.001, 86400] s", 11, 12},
      {"misspelt until steady", withLine(11, "duration = \"until stedy\""),
       "did you mean \"until steady\"?", 11, 12},
      {"max_duration on a fixed posture",
       withLine(11, "duration = \"1 min\"\nmax_duration = \"2 min\""),
       "applies only to duration = \"until steady\"", 12, 16},
      {"steady window without a unit", withLine(8, "[schedule]\nsteady_window = \"0.5\""),
       "schedule.steady_window", 9, 17},
      {"steady coverage change out of range",
       withLine(8, "[schedule]\nsteady_coverage_change = \"150 %\""), "outside the allowed range",
       9, 26},
      {"empty schedule",
       withLine(9, "postures = []").substr(0, withLine(9, "postures = []").find("name =")),
       "schedule.postures is empty", 9, 12},
      {"unknown solver", withLine(1, "format_version = 1\nsolver = \"dfsphh\""),
       "unknown solver 'dfsphh' for solver \u2014 did you mean 'dfsph'?", 2, 10},
      {"effect switch of the wrong type",
       withLine(11, "duration = \"1 min\"\n[effects]\nviscosity = \"yes\""),
       "effects.viscosity must be true (force on), false (force off) or \"auto\"", 13, 13},
      {"unknown effect with suggestion",
       withLine(11, "duration = \"1 min\"\n[effects]\nelastic = false"),
       "did you mean 'elasticity'?", 13, 1},
      {"unknown accuracy preset",
       withLine(11, "duration = \"1 min\"\n[accuracy]\npreset = \"quick\""),
       "unknown preset 'quick' for accuracy.preset \u2014 choose one of 'draft', 'standard', "
       "'fine'",
       13, 10},
      {"unknown surface stress form",
       withLine(11, "duration = \"1 min\"\n[accuracy]\nsurface_stress = \"exact\""),
       "unknown surface_stress 'exact' for accuracy.surface_stress \u2014 choose one of 'auto', "
       "'corrected', 'symmetric'",
       13, 18},
      {"unknown wall model",
       withLine(11, "duration = \"1 min\"\n[accuracy]\nwall_model = \"double\""),
       "unknown wall_model 'double' for accuracy.wall_model \u2014 choose one of 'auto', "
       "'layered', 'single_layer'",
       13, 14},
      {"time-step bounds crossed",
       withLine(11, "duration = \"1 min\"\n[accuracy]\nmin_time_step = \"1 s\""),
       "accuracy.min_time_step (1 s) is larger than accuracy.max_time_step (0.001 s)", 13, 17},
      {"bad field name", withLine(11, "duration = \"1 min\"\n[outputs]\nfields = [\"Position\"]"),
       "outputs.fields: 'Position' is not a field name", 13, 11},
  };
}

const protocols::Diagnostic* findDiagnostic(const ProtocolError& e, const std::string& fragment) {
  for (const protocols::Diagnostic& d : e.diagnostics())
    if (d.toString().find(fragment) != std::string::npos) return &d;
  return nullptr;
}

const fs::path kProtocolDir = fs::path(TAMPONADE_SOURCE_DIR) / "data" / "protocols";

}  // namespace

TEST_CASE("the base protocol of the bad-protocol table is valid", "[unit][protocol]") {
  const protocols::Protocol p = protocols::parseProtocolText(withLine(0, ""), "base.toml");
  CHECK(p.tamponade.fill.value == Approx(0.9).epsilon(1e-12));
  CHECK(p.schedule.postures.at(0).duration.value == Approx(600.0).epsilon(1e-12));
}

TEST_CASE("bad protocols: each problem is reported with its place and a fix", "[unit][protocol]") {
  for (const BadCase& c : badCases()) {
    INFO("case: " << c.name << "\n" << c.text);
    try {
      (void)protocols::parseProtocolText(c.text, "case.toml");
      FAIL("accepted");
    } catch (const ProtocolError& e) {
      INFO("got:\n" << e.what());
      const protocols::Diagnostic* d = findDiagnostic(e, c.fragment);
      REQUIRE(d != nullptr);
      CHECK(d->where.file == "case.toml");
      CHECK(d->where.line == c.line);
      CHECK(d->where.column == c.column);
      // The printed form is `file:line:column: what — fix`.
      const std::string prefix =
          "case.toml:" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": ";
      CHECK(d->toString().rfind(prefix, 0) == 0);
      CHECK_FALSE(d->fix.empty());
    }
  }
}

TEST_CASE("all problems of a file are reported at once, in file order", "[unit][protocol]") {
  const std::string text =
      "format_version = 1\n"
      "[eye]\n"
      "kind = \"emmetropic\"\n"
      "side = \"right\"\n"  // 4: unknown side
      "[tamponade]\n"
      "agent = \"silicone_oil_1000\"\n"
      "fill = 1.5\n"           // 7: out of range
      "colour = \"yellow\"\n"  // 8: unknown key
      "[schedule]\n"
      "[[schedule.postures]]\n"
      "name = \"upright\"\n"
      "duration = 10\n";  // 12: no unit
  try {
    (void)protocols::parseProtocolText(text, "many.toml");
    FAIL("accepted");
  } catch (const ProtocolError& e) {
    INFO(e.what());
    REQUIRE(e.diagnostics().size() == 4);
    CHECK(e.diagnostics()[0].where.line == 4);
    CHECK(e.diagnostics()[1].where.line == 7);
    CHECK(e.diagnostics()[2].where.line == 8);
    CHECK(e.diagnostics()[3].where.line == 12);
    // what() holds every diagnostic, one per line.
    const std::string message = e.what();
    CHECK(std::count(message.begin(), message.end(), '\n') == 3);
  }
}

TEST_CASE("a missing file or a folder is a ProtocolError naming it", "[unit][protocol]") {
  CHECK_THROWS_WITH(protocols::parseProtocol(kProtocolDir),
                    Catch::Contains("is a folder, not a protocol file"));
  CHECK_THROWS_MATCHES(
      protocols::parseProtocol("/no/such/protocol.toml"), ProtocolError,
      Catch::Matchers::Message(
          "/no/such/protocol.toml: cannot open the protocol file \u2014 check the path "
          "(see data/protocols/ for examples)"));
}

TEST_CASE("values, defaults and locations are kept", "[unit][protocol]") {
  const std::string text = withLine(7,
                                    "fill = \"95 %\"\n"
                                    "viscosity = \"1000 cSt\"\n"
                                    "contact_angle = \"18 deg\"") +
                           "[accuracy]\npreset = \"draft\"\nmax_time_step = \"1 ms\"\n";
  const protocols::Protocol p = protocols::parseProtocolText(text, "dir/values.toml");
  CHECK(p.tamponade.fill.value == Approx(0.95).epsilon(1e-12));
  CHECK(p.tamponade.fill.where.line == 7);
  CHECK(p.tamponade.fill.where.column == 8);
  REQUIRE(p.tamponade.viscosity.has_value());
  CHECK(p.tamponade.viscosity->value.kind == protocols::ViscosityKind::kKinematic);
  CHECK(p.tamponade.viscosity->value.value == Approx(1e-3).epsilon(1e-12));
  CHECK(p.tamponade.contactAngle->value ==
        Approx(18.0 * 3.14159265358979323846 / 180.0).epsilon(1e-12));
  CHECK_FALSE(p.tamponade.density.has_value());  // comes from the library later
  // Preset values fill what the file leaves out; an explicit one wins and keeps its line.
  CHECK(p.accuracy.preset.value == protocols::AccuracyPreset::kDraft);
  CHECK(p.accuracy.particleSpacing.value == protocols::kAccuracyPresets[0].particleSpacing);
  CHECK_FALSE(p.accuracy.particleSpacing.where.isInFile());
  CHECK(p.accuracy.maxTimeStep.value == Approx(1e-3).epsilon(1e-12));
  CHECK(p.accuracy.maxTimeStep.where.line == 16);
  CHECK(p.accuracy.surfaceStress.value == protocols::SurfaceStressName::kAuto);  // not in the file
  CHECK_FALSE(p.accuracy.surfaceStress.where.isInFile());
  CHECK(p.accuracy.wallModel.value == protocols::WallModelName::kAuto);
  CHECK_FALSE(p.accuracy.wallModel.where.isInFile());
  // Defaults.
  CHECK(p.solver.value == "indsph");
  CHECK(p.schedule.gravity.value == 9.80665);
  CHECK(p.outputs.folder.value == "runs/values");
  CHECK(p.outputs.report.value);
  for (const auto& setting : p.effects.settings)
    CHECK(setting.value == protocols::EffectSetting::kAuto);
}

TEST_CASE("an imported mesh is found relative to the protocol file", "[unit][protocol]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_protocols_test_mesh");
  const std::filesystem::path& dir = scratch.path();
  fs::create_directories(dir / "meshes");
  std::ofstream(dir / "meshes" / "eye.stl") << "solid eye\nendsolid eye\n";
  const std::string text =
      withLine(3, "kind = \"mesh\"\nmesh = \"meshes/eye.stl\"\nmesh_units = \"mm\"");
  const protocols::Protocol p = protocols::parseProtocolText(text, dir / "case.toml");
  REQUIRE(p.eye.mesh.has_value());
  CHECK(p.eye.mesh->path.value == (dir / "meshes" / "eye.stl").lexically_normal());
  CHECK(p.eye.mesh->pathAsWritten == "meshes/eye.stl");
  CHECK(p.eye.mesh->metresPerUnit == 1e-3);
}

TEST_CASE("every shipped example protocol parses", "[unit][protocol][examples]") {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kProtocolDir)) {
    if (entry.path().extension() != ".toml") continue;
    INFO(entry.path());
    CHECK_NOTHROW(protocols::parseProtocol(entry.path()));
    ++count;
  }
  CHECK(count >= 5);  // the four scenarios of the brief plus tiny.toml
}

TEST_CASE("the example protocols say what their names promise", "[unit][protocol][examples]") {
  using protocols::PostureName;
  SECTION("emmetropic eye, superior break, 90 % silicone oil 1000, supine 10 min then upright") {
    const auto p = protocols::parseProtocol(kProtocolDir / "emmetropic_superior_break.toml");
    CHECK(p.eye.kind.value == protocols::EyeKind::kEmmetropic);
    REQUIRE(p.eye.breaks.size() == 1);
    CHECK(p.eye.breaks[0].clockHour.value == 12.0);
    CHECK(p.tamponade.agent.value == "silicone_oil_1000");
    CHECK(p.tamponade.fill.value == Approx(0.9).epsilon(1e-12));
    REQUIRE(p.schedule.postures.size() == 2);
    CHECK(p.schedule.postures[0].name.value == PostureName::kSupine);
    CHECK(p.schedule.postures[0].duration.value == Approx(600.0).epsilon(1e-12));
    CHECK(p.schedule.postures[1].name.value == PostureName::kUpright);
  }
  SECTION("myopic eye (28 mm) with staphyloma, 95 %, face-down and upright") {
    const auto p = protocols::parseProtocol(kProtocolDir / "myopic_staphyloma_face_down.toml");
    CHECK(p.eye.kind.value == protocols::EyeKind::kStaphyloma);
    CHECK(p.eye.axialLength->value == Approx(0.028).epsilon(1e-12));
    CHECK(p.tamponade.fill.value == Approx(0.95).epsilon(1e-12));
    REQUIRE(p.schedule.postures.size() == 2);
    CHECK(p.schedule.postures[0].name.value == PostureName::kFaceDown);
    CHECK(p.schedule.postures[1].name.value == PostureName::kUpright);
  }
  SECTION("heavy oil with an inferior break") {
    const auto p = protocols::parseProtocol(kProtocolDir / "heavy_oil_inferior_break.toml");
    CHECK(p.tamponade.agent.value == "densiron_68");
    REQUIRE(p.eye.breaks.size() == 1);
    CHECK(p.eye.breaks[0].clockHour.value == 6.0);
  }
  SECTION("tiny: draft accuracy and short durations") {
    const auto p = protocols::parseProtocol(kProtocolDir / "tiny.toml");
    CHECK(p.accuracy.preset.value == protocols::AccuracyPreset::kDraft);
    double total = 0.0;
    for (const auto& posture : p.schedule.postures) {
      CHECK_FALSE(posture.untilSteady);
      total += posture.duration.value;
    }
    CHECK(total <= 2.0);
  }
}

TEST_CASE("custom agent, tissues, gravity direction and forced effects are read",
          "[unit][protocol][examples]") {
  const auto p = protocols::parseProtocol(kProtocolDir / "custom_agent_reclined.toml");
  CHECK(p.tamponade.isCustom());
  REQUIRE(p.tamponade.viscosity.has_value());
  CHECK(p.tamponade.viscosity->value.kind == protocols::ViscosityKind::kKinematic);
  CHECK(p.tamponade.density->value == Approx(970.0).epsilon(1e-12));
  CHECK(p.tamponade.interfacialTension->value == Approx(0.035).epsilon(1e-12));
  CHECK(p.tamponade.fill.value == 0.85);
  REQUIRE(p.eye.sclera.has_value());
  CHECK(p.eye.sclera->youngsModulus->value == Approx(2e6).epsilon(1e-12));
  CHECK(p.eye.sclera->mode.value == protocols::TissueMode::kRigid);
  CHECK(p.eye.sclera->anchoring.value == protocols::Anchoring::kOuterSurface);  // default
  REQUIRE(p.eye.orbitalFat.has_value());
  CHECK(p.eye.orbitalFat->material.value == "orbital_fat");
  CHECK(p.eye.orbitalFat->anchoring.value == protocols::Anchoring::kBackFace);
  CHECK(p.eye.breaks.at(0).reference == protocols::DistanceReference::kOraSerrata);
  REQUIRE(p.schedule.postures.size() == 1);
  const protocols::Posture& posture = p.schedule.postures[0];
  CHECK(posture.name.value == protocols::PostureName::kCustom);
  CHECK(posture.label.value == "reclined 45 deg");
  const auto& g = posture.gravityDirection.value;
  // [0, -0.7071, -0.7071] normalised: unit length to rounding, equal components kept equal.
  CHECK(std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) == Approx(1.0).epsilon(1e-14));
  CHECK(g[1] == g[2]);
  CHECK(p.effects.get("interfacial_tension").value == protocols::EffectSetting::kOn);
  CHECK(p.effects.get("elasticity").value == protocols::EffectSetting::kOff);
  CHECK(p.effects.get("wall_adhesion").value == protocols::EffectSetting::kAuto);
  CHECK(p.accuracy.particleSpacing.value == Approx(0.6e-3).epsilon(1e-12));
  CHECK(p.accuracy.solverTolerance.value == protocols::kAccuracyPresets[0].solverTolerance);
}
