// Postures at their static equilibrium (duration = "equilibrium", protocols/equilibrium/) in the
// emmetropic eye at 90 % silicone oil: the clinical facts a report must not contradict, the run's
// outputs, and the protocol errors of equilibrium schedules.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "eye_protocol.h"
#include "protocols/assembly/assemble_scenario.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/format/protocol_error.h"
#include "protocols/run/run_equilibrium.h"
#include "protocols/scenario/scenario.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"

using namespace protocols;

namespace {

std::string eyeProtocol(const std::string& postures, const std::string& tamponadeExtra = "") {
  tamponade_test::EyeProtocolOptions eye;
  eye.tamponadeKeys = tamponadeExtra;
  eye.schedule = "[schedule]\n" + postures;
  eye.outputs = "[outputs]\nfolder = \"runs/eq\"\n";
  return tamponade_test::eyeProtocolText(eye);
}

std::string posture(const std::string& name, const std::string& duration = "equilibrium") {
  return tamponade_test::posture(name, duration);
}

// The coverage of each posture's equilibrium: the first frame of each posture.
std::vector<FrameCoverage> postureCoverages(const std::string& text) {
  const Protocol p = parseProtocolText(text, "eq.toml");
  Scenario s = assembleScenario(p);
  const tamponade_test::ScratchDirectory scratch("tamponade_test_equilibrium_postures");
  const std::filesystem::path& out = scratch.path();
  RunOptions options;
  options.outputFolder = out;
  std::vector<FrameCoverage> perPosture;
  (void)runEquilibriumSchedule(p, s, options, {});
  // Rebuild per posture from the CSV the run wrote (one row pair per posture).
  const std::string csv = tamponade_test::readText(out / "coverage.csv");
  REQUIRE(std::filesystem::exists(out / "report.html"));
  REQUIRE(std::filesystem::exists(out / "interface_1.ply"));
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // header: time, kReportedRegions..., breaks
  int row = 0;
  while (std::getline(lines, line)) {
    if (row++ % 2 == 1) continue;
    FrameCoverage f;
    std::istringstream cells(line);
    std::string cell;
    std::getline(cells, cell, ',');
    for (auto& r : f.regions) {
      std::getline(cells, cell, ',');
      r.fraction = std::stod(cell);
    }
    perPosture.push_back(f);
  }
  return perPosture;
}

constexpr std::size_t kMacula = 5, kPosteriorPole = 6;  // kReportedRegions

}  // namespace

TEST_CASE("Equilibrium postures of the emmetropic eye at 90 % silicone oil agree with the clinic",
          "[validation][equilibrium]") {
  // Silicone oil floats: upright, the oil fills the upper eye and the posterior pole with the
  // macula (the aqueous pools inferiorly); supine, the aqueous pools at the posterior pole (the
  // lowest point) and leaves the macula to it; face-down, the posterior pole is the highest point
  // and the oil covers it (the reason for face-down positioning after macular surgery).
  const std::vector<FrameCoverage> c =
      postureCoverages(eyeProtocol(posture("upright") + posture("supine") + posture("face-down")));
  REQUIRE(c.size() == 3);
  CHECK(c[0].regions[kMacula].fraction == Approx(1.0));
  CHECK(c[1].regions[kMacula].fraction == Approx(0.0));
  CHECK(c[1].regions[kPosteriorPole].fraction < 0.1);
  CHECK(c[2].regions[kPosteriorPole].fraction == Approx(1.0));
  // 90 % fill covers a large part of the retina in every posture, and more upright than supine
  // (supine, the aqueous spreads over the posterior pole); Rossi et al. 2021 report 55-78 %
  // retinal contact at 80-90 % fill.
  CHECK(c[0].retina().fraction > 0.55);
  CHECK(c[0].retina().fraction > c[1].retina().fraction);
}

TEST_CASE("tamponade run writes an equilibrium schedule's report and interfaces",
          "[unit][equilibrium]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_test_equilibrium_cli");
  const std::filesystem::path& dir = scratch.path();
  { std::ofstream(dir / "eq.toml") << eyeProtocol(posture("upright")); }
  const auto r = tamponade_test::runTamponade("run eq.toml --out out --threads 1", dir);
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK(r.output.find("equilibrium in") != std::string::npos);
  for (const char* file : {"report.html", "summary.json", "coverage.csv", "interface_1.ply",
                           "interfaces.h5", "interfaces.xmf"})
    CHECK(std::filesystem::exists(dir / "out" / file));
  // The interface as ParaView's time series: the posture's surface at the start of its second.
  const std::string sidecar = tamponade_test::readText(dir / "out" / "interfaces.xmf");
  CHECK(sidecar.find("<Grid Name=\"upright\" GridType=\"Uniform\">") != std::string::npos);
  CHECK(sidecar.find("TopologyType=\"Triangle\"") != std::string::npos);
  CHECK(sidecar.find("<Time Value=\"0\"/>") != std::string::npos);
  const std::string report = tamponade_test::readText(dir / "out" / "report.html");
  CHECK(report.find("Coverage at each posture's equilibrium") != std::string::npos);
  CHECK(report.find("Fundus map: upright") != std::string::npos);
  CHECK(report.find("s simulated") == std::string::npos);
  const auto summary =
      nlohmann::json::parse(tamponade_test::readText(dir / "out" / "summary.json"));
  CHECK(summary.at("equilibria").size() == 1);
  // Nothing to rebuild from: `report` says so instead of asking for frames.h5.
  const auto rebuilt = tamponade_test::runTamponade("report out", dir);
  CHECK(rebuilt.exitCode == 2);
  CHECK(rebuilt.output.find("holds equilibria") != std::string::npos);
}

TEST_CASE("Equilibrium schedules: protocol errors name the key", "[unit][equilibrium]") {
  // The parser's message for `text`, or "" when it accepts it.
  auto errorOf = [](const std::string& text) -> std::string {
    try {
      parseProtocolText(text, "eq.toml");
    } catch (const ProtocolError& e) {
      return e.what();
    }
    return "";
  };
  // Postures at equilibrium first, then simulated ones (the first starts from the last
  // equilibrium): accepted, as are all-equilibrium and all-simulated schedules.
  CHECK(errorOf(eyeProtocol(posture("upright") + posture("supine", "10 s"))).empty());
  CHECK(errorOf(eyeProtocol(posture("upright") + posture("supine") + posture("upright", "1 s") +
                            posture("supine", "until steady")))
            .empty());
  CHECK(errorOf(eyeProtocol(posture("upright", "1 s") + posture("supine", "1 s"))).empty());
  // An equilibrium after a simulated posture: refused at that posture's duration (line 17: eight
  // lines before the postures, then three per posture), naming both postures and the fix.
  const std::string late =
      errorOf(eyeProtocol(posture("upright") + posture("supine", "10 s") + posture("face-down")));
  INFO(late);
  CHECK(late.find("eq.toml:17:") != std::string::npos);
  CHECK(late.find("posture 3 (face-down) asks for its equilibrium after the simulated posture 2 "
                  "(supine)") != std::string::npos);
  CHECK(late.find("move the postures with duration = \"equilibrium\" before the simulated "
                  "ones") != std::string::npos);
  // schedule.start has nothing to choose where the schedule begins with an equilibrium.
  const std::string start = errorOf(
      eyeProtocol("start = \"fill_plane\"\n" + posture("supine") + posture("upright", "1 s")));
  INFO(start);
  CHECK(start.find("eq.toml:9:") != std::string::npos);
  CHECK(start.find("schedule.start does not apply") != std::string::npos);
  CHECK(start.find("starts from the equilibrium of the posture before it (supine)") !=
        std::string::npos);
  CHECK(start.find("remove schedule.start") != std::string::npos);
  const std::string wetting =
      errorOf(eyeProtocol(posture("upright"), "contact_angle = \"0 deg\"\n"));
  CHECK(wetting.find("contact_angle") != std::string::npos);
  CHECK(wetting.find("no contact line") != std::string::npos);
  CHECK(
      errorOf(eyeProtocol(posture("upright", "equilibrim"))).find("did you mean \"equilibrium\"") !=
      std::string::npos);
  CHECK(errorOf(eyeProtocol(posture("upright"))).empty());
}
