// How a run is controlled and watched: progress text, "until steady", the
// outputs.fields selection, and SIGTERM with checkpoint and resume.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include <nlohmann/json.hpp>

#include "eye_protocol.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/io/frame_reader.h"
#include "protocols/report/report_format.h"
#include "protocols/run/progress_text.h"
#include "protocols/run/run_scenario.h"
#include "protocols/run/steady_state.h"
#include "sim/core/particle_set.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"
#include "xml_checker.h"

extern char** environ;

namespace fs = std::filesystem;
using tamponade_test::readText;
using tamponade_test::runTamponade;

namespace {

// A coarse eye (d = 1.5 mm, ~1000 fluid particles; one step ~8 ms on this machine, 1 thread).
std::string eyeProtocol(const std::string& schedule, const std::string& outputs = "",
                        const std::string& fill = "90 %") {
  tamponade_test::EyeProtocolOptions eye;
  eye.title = "Run control";
  eye.superiorBreak = true;
  eye.fill = fill;
  eye.schedule = schedule;
  eye.spacing = "1.5 mm";
  eye.outputs = outputs;
  return tamponade_test::eyeProtocolText(eye);
}

protocols::RunProgress progressAt(double time, double endTime) {
  return {time, endTime, 1520, "upright"};
}

protocols::SteadySample sample(double t, double energy, double retina, double macula = 0.0) {
  return {t, energy, {retina, macula}};
}

}  // namespace

TEST_CASE("progress text: ETA, plain line and terminal bar", "[unit][run][progress]") {
  using namespace protocols;
  CHECK(formatWallDuration(0.4) == "0 s");
  CHECK(formatWallDuration(45) == "45 s");
  CHECK(formatWallDuration(200) == "3 min 20 s");
  CHECK(formatWallDuration(7500) == "2 h 05 min");
  CHECK(formatWallDuration(-1) == "?");
  // A quarter done in 20 s at a steady pace leaves 60 s.
  CHECK(estimateRemainingSeconds(0.25, 20.0) == Approx(60.0));
  CHECK(estimateRemainingSeconds(0.0, 20.0) < 0);  // unknown before any progress
  CHECK(progressFraction(progressAt(0.125, 0.5)) == Approx(0.25));
  CHECK(progressFraction(progressAt(0.7, 0.5)) == 1.0);  // the last step may overshoot the end

  const std::string line = renderProgressLine(progressAt(0.125, 0.5), 20.0);
  CHECK(
      line ==
      "progress  25.0 %  t = 0.125 s / 0.5 s  upright  step 1520  elapsed 20 s  ETA 1 min 00 s\n");
  CHECK(renderProgressLine(progressAt(0, 0.5), 1.0).find("ETA ?") != std::string::npos);

  const std::string bar = renderProgressBar(progressAt(0.125, 0.5), 20.0, 20);
  CHECK(bar.rfind("\r[#####...............]  25.0 %", 0) == 0);
  CHECK(bar.find('\n') == std::string::npos);  // redrawn in place
  CHECK(bar.find("ETA 1 min 00 s") != std::string::npos);
  // Fixed width: a shorter line (earlier ETA text) overwrites a longer one completely.
  CHECK(renderProgressBar(progressAt(0.5, 0.5), 1.0, 20).size() == bar.size());

  // Plain lines: the first call, then every 10 % of the run, or after 30 s of silence.
  PlainProgressThrottle throttle(0.1, 30.0);
  CHECK(throttle.due(0.0, 0.0));
  CHECK_FALSE(throttle.due(0.05, 1.0));
  CHECK(throttle.due(0.1, 2.0));
  CHECK_FALSE(throttle.due(0.15, 3.0));
  CHECK(throttle.due(0.16, 33.5));        // slow run: alive after 30 s
  CHECK(throttle.due(0.45, 34.0));        // a jump prints once...
  CHECK_FALSE(throttle.due(0.46, 35.0));  // ...and the next line is due at 50 %
  CHECK(throttle.due(0.5, 36.0));
}

TEST_CASE("until steady: a constructed time series", "[unit][run][steady]") {
  using namespace protocols;
  SteadyCriteria c;
  c.window = 0.2;
  c.kineticEnergyPerMass = 5e-6;
  c.coverageChange = 0.005;
  std::vector<SteadySample> s;
  CHECK_FALSE(isSteady(s, 0.0, c));  // nothing sampled yet

  // Calm and flat from t = 0, sampled every 0.05 s: steady once the posture is a window old.
  for (int k = 0; k <= 3; ++k) s.push_back(sample(0.05 * k, 1e-6, 0.80, 0.0));
  CHECK_FALSE(isSteady(s, 0.0, c));  // t = 0.15 < one window
  s.push_back(sample(0.20, 1e-6, 0.80, 0.0));
  CHECK(isSteady(s, 0.0, c));
  // ... but not if the posture began later than the window reaches back.
  CHECK_FALSE(isSteady(s, 0.05, c));

  // Energy: one sample inside the window at the threshold breaks it; the same sample before the
  // window's start does not.
  std::vector<SteadySample> e = s;
  e[2].kineticEnergyPerMass = 5e-6;  // t = 0.10, inside [0, 0.2]
  CHECK_FALSE(isSteady(e, 0.0, c));
  e.push_back(sample(0.25, 1e-6, 0.80, 0.0));
  e.push_back(sample(0.30, 1e-6, 0.80, 0.0));
  CHECK_FALSE(isSteady(e, 0.0, c));  // window [0.10, 0.30] still holds the sample at 0.10
  e.push_back(sample(0.37, 1e-6, 0.80, 0.0));
  CHECK(isSteady(e, 0.0, c));  // window [0.17, 0.37]: starts with the sample at 0.15

  // Coverage: the whole retina flat while the macula creeps 0.6 points: not steady; 0.4: steady.
  std::vector<SteadySample> creep;
  for (int k = 0; k <= 4; ++k) creep.push_back(sample(0.05 * k, 1e-6, 0.80, 0.0015 * k));
  CHECK_FALSE(isSteady(creep, 0.0, c));
  for (auto& x : creep) x.coverage[1] *= 0.4 / 0.6;
  CHECK(isSteady(creep, 0.0, c));

  // A slosh that returns to the same coverage is caught by the range, not the end points.
  std::vector<SteadySample> slosh;
  for (int k = 0; k <= 4; ++k) slosh.push_back(sample(0.05 * k, 1e-6, k == 2 ? 0.79 : 0.80));
  CHECK_FALSE(isSteady(slosh, 0.0, c));

  // Samples that do not reach back to the window's start (e.g. sparse sampling): not steady.
  CHECK_FALSE(
      isSteady(std::vector<SteadySample>{sample(0.15, 1e-6, 0.8), sample(0.3, 1e-6, 0.8)}, 0.0, c));
}

TEST_CASE("until steady: a settling eye ends its posture before the maximum",
          "[unit][run][steady][cli]") {
  // Start-up: the fluid expands to the wall in the first ms (kinetic energy ~1 J/kg), then
  // settles to the solver's floor (~1e-6 J/kg) by ~0.1 s; with a 0.05 s window the posture must
  // be steady well before its 0.6 s maximum, and not before one window has passed. A full fill:
  // with oil and aqueous the meniscus keeps forming along the wall for longer than 0.6 s since
  // gravity acts relative to the aqueous (docs/methods/solvers.md), so only one fluid settles in
  // time.
  const tamponade_test::ScratchDirectory scratch("tamponade_steady_test");
  const std::filesystem::path& dir = scratch.path();
  std::ofstream(dir / "steady.toml") << eyeProtocol(
      "[schedule]\nsteady_window = \"0.05 s\"\nsteady_coverage_change = \"1 %\"\n"
      "[[schedule.postures]]\nname = \"supine\"\nduration = \"until steady\"\nmax_duration = \"0.6 "
      "s\"\n",
      "[outputs]\nframe_interval = \"0.05 s\"\n", "100 %");
  const auto r = runTamponade("run steady.toml --out a --threads 1", dir);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  std::smatch m;
  REQUIRE(std::regex_search(r.output, m,
                            std::regex("posture 1 \\(supine\\): steady after ([0-9.e+-]+) s")));
  const double steadyAfter = std::stod(m[1].str());
  CHECK(steadyAfter >= 0.05);
  CHECK(steadyAfter < 0.6);
  // The run's record agrees: one "postures" row, steady, at the end; the last frame is the end.
  const protocols::FrameReader reader(dir / "a" / "frames.h5");
  const protocols::SeriesData postures = reader.readSeries("postures");
  REQUIRE(postures.rows == 1);
  CHECK(postures.column("steady")[0] == 1.0);
  CHECK(postures.column("time")[0] == Approx(steadyAfter).epsilon(1e-3));
  CHECK(reader.frames().back().time == postures.column("time")[0]);
  // The report's timeline uses the actual duration, also when rebuilt from the files.
  const std::string html = readText(dir / "a" / "report.html");
  CHECK(protocols_test::checkXml(html).empty());
  CHECK(html.find("supine until steady (reached after") != std::string::npos);
  fs::remove(dir / "a" / "report.html");
  REQUIRE(runTamponade("report a", dir).exitCode == 0);
  CHECK(readText(dir / "a" / "report.html") == html);
}

TEST_CASE("until steady: a posture stopped at its maximum says so, with its equilibrium distance",
          "[unit][run][steady][cli]") {
  // The steady window (0.05 s) is longer than the posture's maximum (0.03 s), so the posture
  // cannot be judged steady: it must end unsteady, be named in the report's headline and in
  // summary.json, and carry the retina coverage at the posture's static equilibrium. That
  // coverage must be the one an equilibrium run of the same eye and posture reports (the same
  // solver at the same preset's voxel, reached through the report instead of the schedule).
  const tamponade_test::ScratchDirectory scratch("tamponade_unsteady_test");
  const std::filesystem::path& dir = scratch.path();
  std::ofstream(dir / "unsteady.toml") << eyeProtocol(
      "[schedule]\nsteady_window = \"0.05 s\"\n"
      "[[schedule.postures]]\nname = \"upright\"\nduration = \"until steady\"\n"
      "max_duration = \"0.03 s\"\n",
      "[outputs]\nframe_interval = \"0.01 s\"\n");
  std::ofstream(dir / "equilibrium.toml")
      << eyeProtocol("[[schedule.postures]]\nname = \"upright\"\nduration = \"equilibrium\"\n");
  const auto r = runTamponade("run unsteady.toml --out a --threads 1", dir);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK(r.output.find("posture 1 (upright): not steady, stopped at its maximum") !=
        std::string::npos);
  REQUIRE(runTamponade("run equilibrium.toml --out e --threads 1", dir).exitCode == 0);

  const auto summary = nlohmann::json::parse(readText(dir / "a" / "summary.json"));
  const auto& posture = summary.at("postures").at(0);
  CHECK(posture.at("name") == "upright");
  CHECK(posture.at("ended_steady") == false);
  const double atEnd = posture.at("retina_coverage_at_end").get<double>();
  const double equilibrium = posture.at("equilibrium_retina_coverage").get<double>();
  CHECK(atEnd >= 0.0);
  CHECK(atEnd <= 1.0);
  const auto reference = nlohmann::json::parse(readText(dir / "e" / "summary.json"));
  const auto& regions = reference.at("equilibria").at(0).at("regions");
  REQUIRE(regions.at(0).at("name") == "whole retina");
  CHECK(equilibrium == Approx(regions.at(0).at("fraction").get<double>()).epsilon(1e-6));
  // The equilibrium run's own postures are not "until steady": null, no distance.
  CHECK(reference.at("postures").at(0).at("ended_steady").is_null());
  CHECK_FALSE(reference.at("postures").at(0).contains("equilibrium_retina_coverage"));

  const std::string html = readText(dir / "a" / "report.html");
  CHECK(protocols_test::checkXml(html).empty());
  CHECK(html.find("<strong>Not steady:</strong> the posture upright reached its maximum") !=
        std::string::npos);
  CHECK(html.find("at the posture's static equilibrium it covers " +
                  protocols::formatPercent(equilibrium)) != std::string::npos);
  CHECK(readText(dir / "e" / "report.html").find("Not steady") == std::string::npos);
  // Rebuilt from the files, the report says the same.
  fs::remove(dir / "a" / "report.html");
  REQUIRE(runTamponade("report a", dir).exitCode == 0);
  CHECK(readText(dir / "a" / "report.html") == html);
}

TEST_CASE("outputs.fields: only the named fields are written, unknown names are located",
          "[unit][run][fields][cli]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_fields_test");
  const std::filesystem::path& dir = scratch.path();
  const std::string schedule =
      "[schedule]\n[[schedule.postures]]\nname = \"supine\"\nduration = \"2 ms\"\n";
  std::ofstream(dir / "fields.toml") << eyeProtocol(
      schedule, "[outputs]\nframe_interval = \"1 ms\"\nfields = [\"velocity\", \"pressure\"]\n");
  const auto r = runTamponade("run fields.toml --out a --threads 1", dir);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const protocols::FrameReader reader(dir / "a" / "frames.h5");
  REQUIRE(reader.frames().size() >= 2);
  for (const auto& f : reader.frames()) {
    auto names = reader.fieldNames(f.index, "fluid");
    std::sort(names.begin(), names.end());
    // position and material always (coverage, report and resume read them), then the list.
    CHECK(names == std::vector<std::string>{"material", "position", "pressure", "velocity"});
  }
  std::string xmf = readText(dir / "a" / "frames.xmf");
  xmf.erase(0, xmf.find("?>") + 2);  // the checker knows no <?xml ...?> declaration
  CHECK(protocols_test::checkXml(xmf).empty());
  CHECK(readText(dir / "a" / "frames.xmf").find("pressure") != std::string::npos);

  // A misspelt field: file:line:column of the name, a suggestion, exit 2, no folder.
  std::ofstream(dir / "bad.toml") << eyeProtocol(
      schedule, "[outputs]\nfields = [\"velocity\", \"presure\"]\n");
  const auto bad = runTamponade("run bad.toml --out b", dir);
  INFO(bad.output);
  CHECK(bad.exitCode == 2);
  // [outputs] is line 21 of eyeProtocol's text, fields line 22; "presure" starts at column 23.
  CHECK(bad.output.find("bad.toml:22:23: outputs.fields: 'presure' is not a particle field") !=
        std::string::npos);
  CHECK(bad.output.find("did you mean 'pressure'") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "b"));
}

TEST_CASE("SIGTERM: checkpoint, readable frames, exit 143, resume equals the continuous run",
          "[unit][run][signal][cli]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_sigterm_test");
  const std::filesystem::path& dir = scratch.path();
  // 60 ms simulated, ~700 steps (~5 s): long enough to be interrupted after its first frame.
  std::ofstream(dir / "long.toml") << eyeProtocol(
      "[schedule]\n[[schedule.postures]]\nname = \"supine\"\nduration = \"30 ms\"\n"
      "[[schedule.postures]]\nname = \"upright\"\nduration = \"30 ms\"\n",
      "[outputs]\nframe_interval = \"5 ms\"\n");

  // Start `tamponade run` as a child process, output to a file.
  const std::string exe = TAMPONADE_EXECUTABLE;
  const std::string protocolPath = (dir / "long.toml").string(), outPath = (dir / "s").string();
  std::vector<std::string> argv = {exe, "run", protocolPath, "--out", outPath, "--threads", "1"};
  std::vector<char*> cargv;
  for (auto& a : argv) cargv.push_back(a.data());
  cargv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string logPath = (dir / "s.log").string();
  posix_spawn_file_actions_addopen(&actions, 1, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  setenv("OMP_WAIT_POLICY", "passive", 1);
  pid_t child = -1;
  REQUIRE(posix_spawn(&child, exe.c_str(), &actions, nullptr, cargv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&actions);

  // Wait for the first frame after the initial one: the sidecar is rewritten after each frame.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  auto gridCount = [&]() {
    const std::string xmf = readText(dir / "s" / "frames.xmf");
    std::size_t count = 0;
    for (std::size_t at = xmf.find("<Time "); at != std::string::npos;
         at = xmf.find("<Time ", at + 1))
      ++count;
    return count;
  };
  while (gridCount() < 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  REQUIRE(gridCount() >= 2);
  REQUIRE(kill(child, SIGTERM) == 0);
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  const std::string log = readText(dir / "s.log");
  INFO(log);
  // Documented in `tamponade run --help`: 128 + SIGTERM (15) = 143, after the checkpoint.
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 143);
  CHECK(log.find("tamponade run --resume") != std::string::npos);
  CHECK(log.find("progress ") != std::string::npos);  // plain progress lines: stderr is a file
  CHECK(log.find("ETA ") != std::string::npos);

  // What the stopped run left is readable: the checkpoint restores, the frames open, the sidecar
  // parses and lists exactly the complete frames.
  REQUIRE(fs::exists(dir / "s" / "checkpoint.h5"));
  {
    // Closed before the resume: HDF5 shares one open file per process, so a reader kept open here
    // would show later readers in this process the stopped run's state.
    const protocols::FrameReader stopped(dir / "s" / "frames.h5");
    CHECK(stopped.frames().size() >= 2);
    CHECK(stopped.unreadableFrames().empty());
    std::string xmf = readText(dir / "s" / "frames.xmf");
    xmf.erase(0, xmf.find("?>") + 2);  // the checker knows no <?xml ...?> declaration
    CHECK(protocols_test::checkXml(xmf).empty());
    CHECK(gridCount() == stopped.frames().size());
    for (const auto& f : stopped.frames())
      CHECK(stopped.readField(f.index, "fluid", sim::field::kPosition).rows > 0);
    CHECK(stopped.frames().back().time < 0.06);  // stopped early, not finished
  }

  // Resume, and compare with an uninterrupted run at the same thread count: bit-identical.
  const auto resumed = runTamponade("run --resume s --threads 1", dir);
  INFO(resumed.output);
  REQUIRE(resumed.exitCode == 0);
  const auto continuous = runTamponade("run long.toml --out c --threads 1", dir);
  REQUIRE(continuous.exitCode == 0);
  CHECK(readText(dir / "s" / "coverage.csv") == readText(dir / "c" / "coverage.csv"));
  const protocols::FrameReader a(dir / "c" / "frames.h5"), b(dir / "s" / "frames.h5");
  REQUIRE(a.frames().size() == b.frames().size());
  const std::size_t last = a.frames().size() - 1;
  CHECK(a.frames()[last].step == b.frames()[last].step);
  for (const char* field : {sim::field::kPosition, sim::field::kVelocity})
    CHECK(a.readField(last, "fluid", field).reals == b.readField(last, "fluid", field).reals);
}

TEST_CASE("the README's default protocol stays a few-second equilibrium run",
          "[unit][protocol][examples]") {
  // tools/quickstart.sh runs it; the README promises seconds on a 2-core machine. That holds
  // while every posture is an equilibrium at the draft preset; its simulated counterpart
  // (default_eye_dynamic.toml) stays a short draft run: at most 1.2 s simulated, spacing >= 1.2 mm.
  const fs::path examples = fs::path(TAMPONADE_SOURCE_DIR) / "data" / "protocols";
  const protocols::Protocol p = protocols::parseProtocol(examples / "default_eye.toml");
  CHECK(p.accuracy.preset.value == protocols::AccuracyPreset::kDraft);
  for (const auto& posture : p.schedule.postures) CHECK(posture.equilibrium);
  const protocols::Protocol dynamic =
      protocols::parseProtocol(examples / "default_eye_dynamic.toml");
  CHECK(dynamic.accuracy.particleSpacing.value >= 1.2e-3);
  double total = 0.0;  // [s]
  for (const auto& posture : dynamic.schedule.postures) {
    CHECK(posture.untilSteady);
    total += posture.duration.value;
  }
  CHECK(total <= 1.2);
}

TEST_CASE("the next frame or sample time always advances past now", "[unit][run]") {
  using protocols::nextTimeAfter;
  // On the grid start + k interval, as before: the first multiple after now.
  CHECK(nextTimeAfter(0.1, 0.1, 0.25) == Approx(0.3));
  CHECK(nextTimeAfter(0.5, 0.1, 0.25) == 0.5);  // already ahead: unchanged
  // An interval too small to advance the time in floating point (1e-20 s after 1.6 ms) used to
  // loop forever; far behind, the next time is taken from now.
  CHECK(nextTimeAfter(1e-3, 1e-20, 1.6e-3) > 1.6e-3);
  CHECK(nextTimeAfter(0.0, 1e-9, 1.0) == Approx(1.0 + 1e-9));
  CHECK(nextTimeAfter(0.0, 0.0, 1.0) > 1.0);
}
