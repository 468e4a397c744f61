// Mixed schedules: postures at their static equilibrium, then simulated postures, the first of
// which starts from the last equilibrium (protocols/equilibrium/start_from_equilibrium.h,
// protocols/run/equilibrium_postures.h). The emmetropic eye at 90 % silicone oil, draft preset
// at 1.2 mm, as the tests of schedule.start = "equilibrium" and of equilibrium runs use.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eye_protocol.h"
#include "protocols/coverage/frame_coverage.h"
#include "protocols/equilibrium/start_from_equilibrium.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/io/frame_reader.h"
#include "protocols/run/rebuild_report.h"
#include "protocols/run/run_scenario.h"
#include "sim/core/particle_set.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"
#include "xml_checker.h"

namespace fs = std::filesystem;
using namespace protocols;

namespace {

std::string eyeProtocol(const std::string& schedule) {
  tamponade_test::EyeProtocolOptions eye;
  eye.superiorBreak = true;
  eye.schedule = "[schedule]\n" + schedule;
  eye.outputs = "[outputs]\nframe_interval = \"10 ms\"\n";
  return tamponade_test::eyeProtocolText(eye);
}

using tamponade_test::particleReading;
using tamponade_test::posture;

// The particles placed at the first posture's equilibrium by schedule.start = "equilibrium", an
// all-simulated schedule: the reading a mixed schedule's simulation must start from.
std::vector<double> startReading(const std::string& firstPosture) {
  const Protocol p = parseProtocolText(
      eyeProtocol("start = \"equilibrium\"\n" + posture(firstPosture, "10 ms")), "start.toml");
  return particleReading(assembleStartingScenario(p));
}

// coverage.csv as rows of numbers (time first), the header dropped.
std::vector<std::vector<double>> csvRows(const fs::path& file) {
  std::istringstream lines(tamponade_test::readText(file));
  std::string line;
  std::getline(lines, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(lines, line)) {
    std::istringstream cells(line);
    std::string cell;
    rows.emplace_back();
    while (std::getline(cells, cell, ',')) rows.back().push_back(std::stod(cell));
  }
  return rows;
}

// The largest difference between the reported regions of a coverage.csv row and `regions`.
double largestDifference(const std::vector<double>& row, const std::vector<double>& regions) {
  double largest = 0.0;
  for (std::size_t r = 0; r < regions.size(); ++r)
    largest = std::max(largest, std::abs(row[1 + r] - regions[r]));
  return largest;
}

}  // namespace

TEST_CASE("A simulated posture after postures at equilibrium starts from the last equilibrium",
          "[unit][equilibrium]") {
  // Upright then supine at equilibrium, then upright simulated: its fluid must start at the
  // supine equilibrium (the posture before it), not at the upright one (the schedule's first).
  const Protocol mixed =
      parseProtocolText(eyeProtocol(posture("upright", "equilibrium") +
                                    posture("supine", "equilibrium") + posture("upright", "10 ms")),
                        "mixed.toml");
  Scenario s = assembleStartingScenario(mixed);
  REQUIRE(startingEquilibrium(mixed, s) == std::size_t{1});
  const std::vector<double> supine = startReading("supine");
  const std::vector<double> upright = startReading("upright");
  // The test can tell the two starts apart: they differ by far more than its tolerance.
  REQUIRE(std::abs(supine[0] - upright[0]) > 0.02);

  const tamponade_test::ScratchDirectory scratch("tamponade_test_mixed_start");

  const std::filesystem::path& out = scratch.path();
  RunOptions run;
  run.outputFolder = out;
  const RunSummary summary = runScenario(mixed, s, run);
  CHECK(summary.simulatedTime == Approx(0.01).margin(0.002));  // at most one step over
  const auto rows = csvRows(out / "coverage.csv");
  // Two rows per posture at equilibrium inside its nominal second, then the simulated frames
  // from t = 2 s on the schedule's clock: the start, every 10 ms, the end.
  REQUIRE(rows.size() >= 6);
  CHECK(rows[3][0] == Approx(1.999));
  CHECK(rows[4][0] == 2.0);
  // The first simulated frame is the particles at the supine equilibrium, before any step: the
  // same places and phases read by the same kernel as startReading's, so it agrees to the
  // rounding of coverage.csv's six significant digits (below 1e-6 for a fraction; the 0.032
  // between the supine and the upright start is more than 4 orders of magnitude above it).
  INFO("first simulated frame " << rows[4][1] << ", supine start " << supine[0]
                                << ", upright start " << upright[0]);
  CHECK(largestDifference(rows[4], supine) < 1e-6);
  // The postures at equilibrium carry their own (voxel) reading, the supine one's as in
  // summary.json's equilibria.
  const auto json = nlohmann::json::parse(tamponade_test::readText(out / "summary.json"));
  REQUIRE(json.at("equilibria").size() == 2);
  CHECK(json.at("equilibria").at(1).at("posture") == "supine");
  CHECK(json.at("equilibria").at(1).at("regions").at(0).at("fraction").get<double>() ==
        Approx(rows[2][1]).margin(1e-6));
}

TEST_CASE("tamponade run: a mixed schedule's outputs, resumed bit-identically",
          "[unit][equilibrium][cli]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_test_mixed_cli");
  const std::filesystem::path& dir = scratch.path();
  // 40 ms upright (about 25 INDSPH steps): long enough to stop at step 16, a z-sort step.
  std::ofstream(dir / "mixed.toml")
      << eyeProtocol(posture("supine", "equilibrium") + posture("upright", "40 ms"));
  const auto whole = tamponade_test::runTamponade("run mixed.toml --out a --threads 1", dir);
  INFO(whole.output);
  REQUIRE(whole.exitCode == 0);
  CHECK(whole.output.find("posture 1/2 (supine): equilibrium in") != std::string::npos);
  for (const char* f :
       {"frames.h5", "report.html", "coverage.csv", "summary.json", "interface_1.ply"})
    CHECK(fs::exists(dir / "a" / f));

  const auto json = nlohmann::json::parse(tamponade_test::readText(dir / "a" / "summary.json"));
  const auto& postures = json.at("postures");
  REQUIRE(postures.size() == 2);
  CHECK(postures.at(0).at("end_s").get<double>() == 1.0);
  CHECK_FALSE(postures.at(0).contains("starts_from_equilibrium_of"));
  CHECK(postures.at(1).at("starts_from_equilibrium_of") == "supine");
  REQUIRE(json.at("equilibria").size() == 1);
  CHECK(json.at("equilibria").at(0).at("breaks").at(0).at("name") == "superior tear");
  CHECK(json.contains("pressure_solve"));
  const auto rows = csvRows(dir / "a" / "coverage.csv");
  REQUIRE(rows.size() >= 4);
  CHECK(json.at("frames").get<std::size_t>() == rows.size());
  CHECK(json.at("equilibria").at(0).at("regions").at(0).at("fraction").get<double>() ==
        Approx(rows[0][1]).margin(1e-6));

  const std::string html = tamponade_test::readText(dir / "a" / "report.html");
  CHECK(protocols_test::checkXml(html).empty());
  CHECK(html.find("supine at its static equilibrium, then upright for 0.04 s, simulated from "
                  "the supine equilibrium") != std::string::npos);
  CHECK(html.find("Coverage at each posture's equilibrium") != std::string::npos);
  CHECK(html.find("Fundus map of oil coverage") != std::string::npos);
  CHECK(html.find("1 posture at equilibrium") != std::string::npos);

  // Stopped at step 16 and resumed: the same coverage, and every frame bit for bit.
  const auto stopped =
      tamponade_test::runTamponade("run mixed.toml --out s --threads 1 --stop-after-steps 16", dir);
  CHECK(stopped.exitCode == 1);
  const auto resumed = tamponade_test::runTamponade("run --resume s --threads 1", dir);
  INFO(resumed.output);
  REQUIRE(resumed.exitCode == 0);
  const std::string csv = tamponade_test::readText(dir / "a" / "coverage.csv");
  CHECK(tamponade_test::readText(dir / "s" / "coverage.csv") == csv);
  const FrameReader continuous(dir / "a" / "frames.h5"), restarted(dir / "s" / "frames.h5");
  REQUIRE(continuous.frames().size() == restarted.frames().size());
  for (std::size_t f = 0; f < continuous.frames().size(); ++f) {
    CHECK(continuous.frames()[f].time == restarted.frames()[f].time);
    for (const char* field : {sim::field::kPosition, sim::field::kVelocity})
      CHECK(continuous.readField(f, "fluid", field).reals ==
            restarted.readField(f, "fluid", field).reals);
  }
  // `tamponade report` solves the equilibrium again and reads the frames: the same CSV.
  fs::remove(dir / "a" / "coverage.csv");
  REQUIRE(tamponade_test::runTamponade("report a", dir).exitCode == 0);
  CHECK(tamponade_test::readText(dir / "a" / "coverage.csv") == csv);

  // plan shows the equilibrium solve and the simulation side by side.
  const auto plan = tamponade_test::runTamponade("plan mixed.toml", dir);
  INFO(plan.output);
  CHECK(plan.exitCode == 0);
  CHECK(plan.output.find("the schedule begins with 1 posture at equilibrium") != std::string::npos);
  CHECK(plan.output.find("equilibria   d [mm]   simulation        total") != std::string::npos);
}
