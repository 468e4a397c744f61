// `tamponade run` end to end on a few milliseconds of a coarse eye: outputs exist and agree,
// the report is well-formed, two runs at the same thread count give identical coverage, and a
// used folder or a bad protocol exits 2 without touching anything.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "protocols/assembly/assemble_scenario.h"
#include "protocols/equilibrium/posture_equilibrium_coverage.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/io/frame_reader.h"
#include "sim/core/particle_set.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"
#include "xml_checker.h"

namespace fs = std::filesystem;

namespace {

using tamponade_test::CommandResult;
using tamponade_test::readText;
using tamponade_test::runTamponade;

// An uninterrupted run's frames and a stopped-and-resumed one's: the same frames, steps and
// times, and every frame's positions and velocities bit for bit.
void checkSameFrames(const fs::path& continuousFile, const fs::path& restartedFile) {
  const protocols::FrameReader continuous(continuousFile), restarted(restartedFile);
  REQUIRE(continuous.frames().size() == restarted.frames().size());
  for (std::size_t f = 0; f < continuous.frames().size(); ++f) {
    CHECK(continuous.frames()[f].step == restarted.frames()[f].step);
    CHECK(continuous.frames()[f].time == restarted.frames()[f].time);
    for (const char* field : {sim::field::kPosition, sim::field::kVelocity})
      CHECK(continuous.readField(f, "fluid", field).reals ==
            restarted.readField(f, "fluid", field).reals);
  }
}

// 8 ms simulated (two postures of 4 ms) at d = 1.5 mm: ~1000 particles, ~110 steps, ~1 s. WCSPH
// by name: the stop/resume check below needs a run longer than the z-sort interval (a run stops
// and checkpoints only at re-sort steps), and the default INDSPH covers 8 ms in 5 steps.
constexpr const char* kShortProtocol =
    "format_version = 1\ntitle = \"Short run\"\nsolver = \"wcsph\"\n"
    "[eye]\nkind = \"emmetropic\"\nside = \"OD\"\n"
    "[[eye.breaks]]\nname = \"superior tear\"\nclock_hour = 12\nposterior_to_limbus = \"14 mm\"\n"
    "diameter = \"2 mm\"\n"
    "[tamponade]\nagent = \"silicone_oil_1000\"\nfill = \"90 %\"\n"
    "[schedule]\n[[schedule.postures]]\nname = \"supine\"\nduration = \"4 ms\"\n"
    "[[schedule.postures]]\nname = \"upright\"\nduration = \"4 ms\"\n"
    "[accuracy]\npreset = \"draft\"\nparticle_spacing = \"1.5 mm\"\n"
    "[outputs]\nframe_interval = \"2 ms\"\n";

// The same eye with the default solver (INDSPH, about 1.8 ms steps): 60 ms over two postures is
// 33 steps, long enough to stop twice at z-sort steps (every 16), once in each posture.
constexpr const char* kIndsphProtocol =
    "format_version = 1\ntitle = \"Short INDSPH run\"\n"
    "[eye]\nkind = \"emmetropic\"\nside = \"OD\"\n"
    "[tamponade]\nagent = \"silicone_oil_1000\"\nfill = \"90 %\"\n"
    "[schedule]\n[[schedule.postures]]\nname = \"supine\"\nduration = \"30 ms\"\n"
    "[[schedule.postures]]\nname = \"upright\"\nduration = \"30 ms\"\n"
    "[accuracy]\npreset = \"draft\"\nparticle_spacing = \"1.5 mm\"\n"
    "[outputs]\nframe_interval = \"10 ms\"\n";

// The "pressure_solve" object of a summary.json as compact JSON text, or "" when it has none.
std::string pressureSolveJson(const std::string& text) {
  const auto json = nlohmann::json::parse(text);
  return json.contains("pressure_solve") ? json.at("pressure_solve").dump() : "";
}

}  // namespace

TEST_CASE("tamponade run: a short protocol writes frames, series and a well-formed report",
          "[unit][scenario][cli]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_run_test");
  const std::filesystem::path& dir = scratch.path();
  std::ofstream(dir / "short.toml") << kShortProtocol;
  const CommandResult r = runTamponade("run short.toml --out a --threads 1", dir);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK(r.output.find("run finished:") != std::string::npos);
  for (const char* f : {"frames.h5", "frames.xmf", "report.html", "coverage.csv", "summary.json"})
    CHECK(fs::exists(dir / "a" / f));
  const std::string html = readText(dir / "a" / "report.html");
  CHECK(protocols_test::checkXml(html).empty());
  CHECK(html.find("superior tear") != std::string::npos);
  // The report states the interface physics used: sigma and the contact angle.
  CHECK(html.find("Interfacial tension against aqueous 40 mN/m") != std::string::npos);
  CHECK(html.find("18.2\u00b0 through the aqueous") != std::string::npos);
  // WCSPH has no pressure solve to report on.
  CHECK(pressureSolveJson(readText(dir / "a" / "summary.json")).empty());
  CHECK(html.find("pressure solve (achieved)") == std::string::npos);
  // Frames at 0, every 2 ms (the first step past each multiple) and the end: 5 rows.
  const std::string csv = readText(dir / "a" / "coverage.csv");
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 1 + 5);
  // The printed mean coverage is the report's.
  const std::size_t at = r.output.find("mean retinal coverage ");
  REQUIRE(at != std::string::npos);
  const std::string mean = r.output.substr(at + 22, r.output.find('\n', at) - at - 22);
  CHECK(html.find("oil covered on average <strong>" + mean + "</strong>") != std::string::npos);

  // Same thread count, same result, bit for bit (deterministic sums, static schedules).
  const CommandResult again = runTamponade("run short.toml --out b --threads 1", dir);
  REQUIRE(again.exitCode == 0);
  CHECK(readText(dir / "b" / "coverage.csv") == csv);

  // `tamponade report DIR` recomputes the coverage from the frames: the same CSV, bit for bit
  // (float64 frames hold the exact state), and the same numbers in the HTML.
  fs::remove(dir / "a" / "coverage.csv");
  fs::remove(dir / "a" / "report.html");
  const CommandResult rebuilt = runTamponade("report a", dir);
  INFO(rebuilt.output);
  CHECK(rebuilt.exitCode == 0);
  CHECK(readText(dir / "a" / "coverage.csv") == csv);
  const std::string html2 = readText(dir / "a" / "report.html");
  CHECK(protocols_test::checkXml(html2).empty());
  CHECK(html2.find("oil covered on average <strong>" + mean + "</strong>") != std::string::npos);
  CHECK(runTamponade("report nowhere", dir).exitCode == 2);

  // Stopped at step 48 (as by Ctrl-C: checkpoint, exit 1, no report), then resumed: the same
  // coverage and the same particle states in every frame as the uninterrupted run, bit for bit.
  const CommandResult stopped =
      runTamponade("run short.toml --out s --threads 1 --stop-after-steps 48", dir);
  INFO(stopped.output);
  CHECK(stopped.exitCode == 1);
  CHECK(stopped.output.find("tamponade run --resume s") != std::string::npos);
  CHECK(fs::exists(dir / "s" / "checkpoint.h5"));
  CHECK_FALSE(fs::exists(dir / "s" / "report.html"));
  const CommandResult resumed = runTamponade("run --resume s --threads 1", dir);
  INFO(resumed.output);
  CHECK(resumed.exitCode == 0);
  CHECK(readText(dir / "s" / "coverage.csv") == csv);
  checkSameFrames(dir / "a" / "frames.h5", dir / "s" / "frames.h5");
  CHECK(runTamponade("run --resume a", dir).exitCode == 2);  // no checkpoint there

  // A folder that holds a run is refused, untouched.
  const auto before = fs::last_write_time(dir / "a" / "frames.h5");
  const CommandResult used = runTamponade("run short.toml --out a", dir);
  CHECK(used.exitCode == 2);
  CHECK(used.output.find("already holds a run") != std::string::npos);
  CHECK(fs::last_write_time(dir / "a" / "frames.h5") == before);

  // A bad protocol: exit 2, file:line:col, no folder.
  std::ofstream(dir / "bad.toml") << "format_version = 1\n[eye]\nkind = \"emetropic\"\n";
  const CommandResult bad = runTamponade("run bad.toml --out c", dir);
  CHECK(bad.exitCode == 2);
  CHECK(bad.output.find("bad.toml:3:") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "c"));
}

TEST_CASE(
    "tamponade run: an INDSPH run stopped twice and resumed ends bit-identical to the "
    "uninterrupted one",
    "[unit][scenario][cli]") {
  // INDSPH keeps state between steps (warm-start pressures, the implicit viscosity's previous
  // solution, the adaptive dt); a checkpoint that missed any of it would change the resumed
  // run's steps and so its last frame. Stopped at step 16 (supine) and 32 (upright).
  const tamponade_test::ScratchDirectory scratch("tamponade_run_indsph_test");
  const std::filesystem::path& dir = scratch.path();
  std::ofstream(dir / "ind.toml") << kIndsphProtocol;
  const CommandResult whole = runTamponade("run ind.toml --out a --threads 1", dir);
  INFO(whole.output);
  REQUIRE(whole.exitCode == 0);
  CHECK(whole.output.find("run finished: 33 steps") != std::string::npos);
  const CommandResult first =
      runTamponade("run ind.toml --out s --threads 1 --stop-after-steps 16", dir);
  INFO(first.output);
  CHECK(first.exitCode == 1);
  CHECK(first.output.find("(step 16)") != std::string::npos);
  const CommandResult second =
      runTamponade("run --resume s --threads 1 --stop-after-steps 32", dir);
  INFO(second.output);
  CHECK(second.exitCode == 1);
  CHECK(second.output.find("(step 32)") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "s" / "report.html"));
  const CommandResult last = runTamponade("run --resume s --threads 1", dir);
  INFO(last.output);
  REQUIRE(last.exitCode == 0);
  CHECK(readText(dir / "s" / "coverage.csv") == readText(dir / "a" / "coverage.csv"));
  checkSameFrames(dir / "a" / "frames.h5", dir / "s" / "frames.h5");
  // What the pressure solve achieved is carried over both resumes (checkpoint counters) and
  // rebuilt by `tamponade report` from the frames' series: the same totals, digit for digit.
  const std::string solve = pressureSolveJson(readText(dir / "a" / "summary.json"));
  INFO(solve);
  REQUIRE_FALSE(solve.empty());
  CHECK(nlohmann::json::parse(solve).at("steps").get<int>() == 33);
  CHECK(pressureSolveJson(readText(dir / "s" / "summary.json")) == solve);
  fs::remove(dir / "a" / "summary.json");
  REQUIRE(runTamponade("report a", dir).exitCode == 0);
  CHECK(pressureSolveJson(readText(dir / "a" / "summary.json")) == solve);
}

TEST_CASE(
    "tamponade bench accuracy: a table of tolerance against cost and coverage, bad usage exits 2",
    "[unit][scenario][cli]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_bench_accuracy_test");
  const std::filesystem::path& dir = scratch.path();
  std::ofstream(dir / "ind.toml") << kIndsphProtocol;
  const CommandResult r =
      runTamponade("bench accuracy ind.toml --tolerances 0.001,0.005 --out acc --threads 1", dir);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const std::string csv = readText(dir / "acc" / "accuracy.csv");
  INFO(csv);
  // Header and one row per tolerance, loose first; the last (tightest) run is the reference.
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(csv);
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> cells;
    std::istringstream cellStream(line);
    for (std::string cell; std::getline(cellStream, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  REQUIRE(rows.size() == 3);
  CHECK(rows[0][1] == "solver_tolerance");
  CHECK(std::stod(rows[1][1]) == 0.005);
  CHECK(std::stod(rows[2][1]) == 0.001);
  CHECK(std::stod(rows[2][10]) == 0.0);  // whole_retina_diff of the reference itself
  // The looser solve takes fewer iterations and stops at a larger mean density error, each at
  // or below its tolerance (no step of this short run reaches the cap).
  CHECK(std::stod(rows[1][5]) < std::stod(rows[2][5]));
  CHECK(std::stod(rows[1][7]) > std::stod(rows[2][7]));
  CHECK(std::stod(rows[1][7]) <= 0.005);
  CHECK(std::stod(rows[2][7]) <= 0.001);
  CHECK(fs::exists(dir / "acc" / "accuracy.md"));
  CHECK(fs::exists(dir / "acc" / "runs" / "d1.5mm_tol0.005" / "report.html"));

  // Each row's distance from the answer: the retina's coverage at a posture's end (the run's own
  // coverage.csv) minus the posture's static equilibrium, solved here independently of the bench;
  // the posture farthest from its equilibrium is named. 1e-5: the CSVs' 6 significant digits.
  REQUIRE(rows[0].size() == 16);
  CHECK(rows[0][13] == "equilibrium_diff");
  const protocols::Protocol protocol = protocols::parseProtocol((dir / "ind.toml").string());
  const protocols::Scenario scenario = protocols::assembleScenario(protocol);
  const auto equilibria =
      protocols::equilibriumRetinaCoverage(scenario, protocol.tamponade.fill.value);
  REQUIRE(equilibria.size() == 2);
  REQUIRE(equilibria[0].has_value());
  REQUIRE(equilibria[1].has_value());
  std::istringstream series(readText(dir / "acc" / "runs" / "d1.5mm_tol0.001" / "coverage.csv"));
  const std::array<double, 2> ends = {0.03, 0.06};  // [s] the postures' ends
  std::array<double, 2> atEnd{};
  std::string line;
  std::getline(series, line);  // header
  while (std::getline(series, line)) {
    const double time = std::stod(line);
    const double retina = std::stod(line.substr(line.find(',') + 1));
    for (std::size_t k = 0; k < ends.size(); ++k)
      if (time <= ends[k] * (1 + 1e-9)) atEnd[k] = retina;
  }
  const double supine = atEnd[0] - *equilibria[0], upright = atEnd[1] - *equilibria[1];
  const bool supineWorst = std::abs(supine) >= std::abs(upright);
  CHECK(std::stod(rows[2][13]) == Approx(supineWorst ? supine : upright).margin(1e-5));
  CHECK(rows[2][14] == (supineWorst ? "\"supine\"" : "\"upright\""));

  // Bad usage and a bad protocol: exit 2, the reason, nothing written.
  const CommandResult tooLoose =
      runTamponade("bench accuracy ind.toml --tolerances 0.2 --out x", dir);
  CHECK(tooLoose.exitCode == 2);
  CHECK(tooLoose.output.find("--tolerances: '0.2' is above its largest value") !=
        std::string::npos);
  CHECK(runTamponade("bench accuracy --out x", dir).exitCode == 2);
  std::ofstream(dir / "bad.toml") << "format_version = 1\n[eye]\nkind = \"emetropic\"\n";
  const CommandResult bad = runTamponade("bench accuracy bad.toml --out x", dir);
  CHECK(bad.exitCode == 2);
  CHECK(bad.output.find("bad.toml:3:") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "x"));
}
