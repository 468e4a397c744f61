// Parameter sweeps (protocols/sweep/, `tamponade sweep`): expansion of lists and ranges, every
// point validated with errors at the sweep file's line, the points' protocols, and the command's
// local runs, resume, status, collect and Slurm script. The points are equilibrium postures of
// the emmetropic eye (under a second each).
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "protocols/format/parse_protocol.h"
#include "protocols/format/protocol_error.h"
#include "protocols/sweep/sweep_plan.h"
#include "protocols/sweep/sweep_range.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"

using namespace protocols;
using tamponade_test::readText;
using tamponade_test::runTamponade;

namespace {

const std::filesystem::path kSource = TAMPONADE_SOURCE_DIR;

// A fresh folder holding `base.toml` (one upright equilibrium posture of the emmetropic eye, 90 %
// silicone oil) and `sweep.toml` with the given text.
tamponade_test::ScratchDirectory sweepFolder(const std::string& name,
                                             const std::string& sweepText) {
  tamponade_test::ScratchDirectory dir("tamponade_test_sweep_" + name);
  std::ofstream(dir / "base.toml")
      << "format_version = 1\ntitle = \"Base\"\n"
         "[eye]\nkind = \"emmetropic\"\nside = \"OD\"\n"
         "[[eye.breaks]]\nname = \"superior tear\"\nclock_hour = 12\n"
         "posterior_to_limbus = \"14 mm\"\ndiameter = \"2 mm\"\n"
         "[tamponade]\nagent = \"silicone_oil_1000\"\nfill = \"90 %\"\n"
         "[[schedule.postures]]\nname = \"upright\"\n"
         "duration = \"equilibrium\"\n"
         "[accuracy]\npreset = \"draft\"\n";
  std::ofstream(dir / "sweep.toml") << sweepText;
  return dir;
}

std::string problemsOf(const std::filesystem::path& file) {
  try {
    planSweep(file);
  } catch (const ProtocolError& e) {
    std::string all;
    for (const auto& d : e.diagnostics()) all += d.toString() + "\n";
    return all;
  }
  return "(no problem)";
}

std::size_t lineCount(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace

TEST_CASE("Sweep ranges include both ends and print their values exactly", "[unit][sweep]") {
  std::vector<Diagnostic> problems;
  const SourceLocation at{"s.toml", 3, 20};
  auto values = [&](const std::string& range) {
    const toml::table doc = toml::parse("r = " + range);
    std::vector<std::string> shown;
    for (const auto& v : expandRange(*doc["r"].as_table(), "k", at, problems))
      shown.push_back(v.toml);
    return shown;
  };
  CHECK(values("{ from = \"60 %\", to = \"100 %\", step = \"10 %\" }") ==
        std::vector<std::string>{"\"60 %\"", "\"70 %\"", "\"80 %\"", "\"90 %\"", "\"100 %\""});
  // 0.8 + 2 * 0.05 is 0.9000000000000001 in binary: printed as written.
  CHECK(values("{ from = 0.8, to = 0.95, count = 4 }") ==
        std::vector<std::string>{"0.8", "0.85", "0.9", "0.95"});
  CHECK(values("{ from = 10, to = 40, step = 15 }") == std::vector<std::string>{"10", "25", "40"});
  CHECK(values("{ from = \"40 deg\", to = \"10 deg\", step = \"-15 deg\" }") ==
        std::vector<std::string>{"\"40 deg\"", "\"25 deg\"", "\"10 deg\""});
  CHECK(problems.empty());
  CHECK(values("{ from = \"60 %\", to = \"100 %\", step = \"-5 %\" }").empty());
  CHECK(values("{ from = \"60 %\", to = \"10 mm\", step = 1 }").empty());
  CHECK(values("{ from = 1, to = 2 }").empty());
  REQUIRE(problems.size() == 3);
  CHECK(problems[0].what.find("has no points") != std::string::npos);
  CHECK(problems[1].what.find("different units") != std::string::npos);
  CHECK(problems[2].what.find("step or count") != std::string::npos);
  CHECK(problems[0].where.line == 3);
}

TEST_CASE("A sweep's points: every combination in file order, each a valid protocol",
          "[unit][sweep]") {
  const auto dir = sweepFolder("plan",
                               "base = \"base.toml\"\n[vary]\n"
                               "\"tamponade.fill\" = [\"80 %\", \"95 %\"]\n"
                               "\"schedule.postures.0.name\" = [\"upright\", \"supine\", "
                               "\"face-down\"]\n");
  const SweepPlan plan = planSweep(dir / "sweep.toml");
  REQUIRE(plan.points.size() == 6);
  CHECK(plan.keys[0].path == "tamponade.fill");  // the file's order, not the alphabet's
  CHECK(plan.describe(plan.points[0]) ==
        "tamponade.fill = 80 %, schedule.postures.0.name = upright");
  CHECK(plan.describe(plan.points[5]) ==
        "tamponade.fill = 95 %, schedule.postures.0.name = face-down");
  CHECK(plan.points[5].id == "p006");
  // Each point's protocol file stands alone and holds its values.
  const Protocol p = parseProtocolText(plan.points[4].protocolText, dir / "points/p005.toml");
  CHECK(p.tamponade.fill.value == Approx(0.95).epsilon(1e-12));
  CHECK(p.schedule.postures.at(0).name.value == PostureName::kSupine);
  CHECK(p.title->value.find("[tamponade.fill = 95 %, schedule.postures.0.name = supine]") !=
        std::string::npos);
}

TEST_CASE("Zipped sweeps pair the lists' values", "[unit][sweep]") {
  const auto dir = sweepFolder("zip",
                               "base = \"base.toml\"\ncombine = \"zip\"\n[vary]\n"
                               "\"tamponade.fill\" = [\"80 %\", \"95 %\"]\n"
                               "\"tamponade.agent\" = [\"silicone_oil_1000\", \"densiron_68\"]\n");
  const SweepPlan plan = planSweep(dir / "sweep.toml");
  REQUIRE(plan.points.size() == 2);
  CHECK(plan.describe(plan.points[1]) == "tamponade.fill = 95 %, tamponade.agent = densiron_68");
}

TEST_CASE("A sweep point's relative mesh path still finds the mesh from the sweep's folder",
          "[unit][sweep]") {
  const auto dir =
      sweepFolder("mesh", "base = \"base.toml\"\n[vary]\n\"tamponade.fill\" = [0.8]\n");
  std::filesystem::copy_file(kSource / "data/meshes/emmetropic_al23.58mm.stl", dir / "eye.stl");
  std::ofstream(dir / "base.toml")
      << "format_version = 1\n[eye]\nkind = \"mesh\"\nside = \"OD\"\n"
         "mesh = \"eye.stl\"\nmesh_units = \"mm\"\n"
         "[tamponade]\nagent = \"silicone_oil_1000\"\nfill = \"90 %\"\n"
         "[[schedule.postures]]\nname = \"upright\"\n"
         "duration = \"equilibrium\"\n";
  const SweepPlan plan = planSweep(dir / "sweep.toml");
  const Protocol p =
      parseProtocolText(plan.points[0].protocolText, dir / "points/p001/protocol.toml");
  CHECK(std::filesystem::equivalent(p.eye.mesh->path.value, dir / "eye.stl"));
}

TEST_CASE("Bad sweep files are refused before anything runs, at the line of the cause",
          "[unit][sweep][bad-input]") {
  struct Case {
    const char* vary;
    const char* expected;  // in the message, after "sweep.toml:<line>:<column>: "
  };
  const Case cases[] = {
      {"\"tamponade.fil\" = [\"80 %\"]\n", "4:1: [vary] \"tamponade.fil\" is not a protocol key"},
      {"\"eye\" = [1]\n", "4:1: [vary] \"eye\" is a table, not a value"},
      {"\"schedule.postures.name\" = [\"upright\"]\n", "needs the index of the schedule.postures"},
      {"\"schedule.postures.2.name\" = [\"upright\"]\n", "has 1 element(s), numbered from 0"},
      {"\"tamponade.fill\" = []\n", "4:20: [vary] \"tamponade.fill\" has no values"},
      {"\"tamponade.fill\" = \"80 %\"\n", "must be a list of values or a range"},
      {"\"tamponade.fill\" = { from = \"90 %\", to = \"60 %\", step = \"10 %\" }\n",
       "4:20: [vary] \"tamponade.fill\": from 90 % to 60 % with step 10 % has no points"},
      // A value the protocol refuses: reported where the sweep file has it, with its points.
      {"\"tamponade.fill\" = [\"80 %\", \"150 %\"]\n",
       "4:29: tamponade.fill = 1.5 is outside the allowed range (0, 1] (in point p002)"},
      {"\"schedule.postures.0.name\" = [\"sideways\"]\n",
       "4:31: unknown name 'sideways' for schedule.postures[1].name (in every point)"},
      {"\"tamponade.fill\" = { from = 0.5, to = 1.0, count = 40 }\n"
       "\"eye.axial_length\" = { from = \"20 mm\", to = \"30 mm\", count = 40 }\n",
       "1:1: the sweep has 1600 points, more than --max-points 1000"},
  };
  for (const Case& c : cases) {
    INFO(c.vary);
    const auto dir = sweepFolder("bad", std::string("base = \"base.toml\"\n\n[vary]\n") + c.vary);
    const std::string problems = problemsOf(dir / "sweep.toml");
    INFO(problems);
    const bool placed = c.expected[0] >= '0' && c.expected[0] <= '9';  // "line:column: ..."
    CHECK(problems.find(placed ? (dir / "sweep.toml").string() + ":" + c.expected
                               : std::string(c.expected)) != std::string::npos);
  }
  const auto dir = sweepFolder("bad_top", "base = \"nowhere.toml\"\ncombine = \"all\"\n");
  const std::string problems = problemsOf(dir / "sweep.toml");
  CHECK(problems.find(":1:8: base protocol 'nowhere.toml' is not a file") != std::string::npos);
  CHECK(problems.find(":2:11: combine must be \"factorial\" or \"zip\"") != std::string::npos);
  CHECK(problems.find("has no [vary] table") != std::string::npos);
}

TEST_CASE("tamponade sweep runs every point, resumes, retries failures and collects",
          "[unit][sweep]") {
  const auto dir = sweepFolder("run",
                               "base = \"base.toml\"\ntitle = \"Fill study\"\n[vary]\n"
                               "\"tamponade.fill\" = [\"70 %\", \"80 %\", \"90 %\"]\n"
                               "[plots]\nregions = [\"whole retina\", \"macula\"]\n");
  const auto out = dir / "out";
  auto r = runTamponade("sweep sweep.toml --out out --jobs 2", dir);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK(r.output.find("[3/3]") != std::string::npos);
  for (const char* id : {"p001", "p002", "p003"})
    CHECK(std::filesystem::exists(out / "points" / id / "report.html"));
  const std::string csv = readText(out / "sweep.csv");
  CHECK(lineCount(csv) == 4);
  CHECK(csv.rfind("point,tamponade.fill,state,run_seconds,whole retina final,", 0) == 0);
  CHECK(readText(out / "sweep.html").find("<svg") != std::string::npos);
  CHECK(readText(out / "sweep.md").find("| p003 | 90 % |") != std::string::npos);

  // A second run of the same command has nothing to do.
  r = runTamponade("sweep sweep.toml --out out", dir);
  CHECK(r.exitCode == 0);
  CHECK(r.output.find("3 points, 0 to run (3 done already)") != std::string::npos);

  // A point that fails is listed by status and run again by the same command.
  const auto p2 = out / "points/p002";
  const std::string goodProtocol = readText(p2 / "protocol.toml");
  std::filesystem::remove(p2 / "summary.json");
  std::ofstream(p2 / "protocol.toml") << "this is not TOML\n";
  r = runTamponade("sweep sweep.toml --out out", dir);
  CHECK(r.exitCode == 1);
  CHECK(r.output.find("failed: p002") != std::string::npos);
  r = runTamponade("sweep status out", dir);
  CHECK(r.output.find("3 points: 2 done, 0 running, 0 pending, 1 failed") != std::string::npos);
  CHECK(r.output.find("p002  failed (exit 2)") != std::string::npos);
  CHECK(readText(out / "sweep.csv").find("p002,80 %,failed") != std::string::npos);
  std::ofstream(p2 / "protocol.toml") << goodProtocol;
  r = runTamponade("sweep sweep.toml --out out", dir);
  CHECK(r.exitCode == 0);
  CHECK(r.output.find("1 to run (2 done already)") != std::string::npos);
  CHECK(readText(p2 / "point.json").find("\"attempts\": 3") != std::string::npos);
  r = runTamponade("sweep collect out", dir);
  CHECK(r.output.find("3 of 3 points have results") != std::string::npos);
}

TEST_CASE("A sweep folder holding another sweep is refused", "[unit][sweep][bad-input]") {
  const auto dir = sweepFolder("conflict",
                               "base = \"base.toml\"\n[vary]\n"
                               "\"tamponade.fill\" = [\"80 %\"]\n");
  REQUIRE(runTamponade("sweep sweep.toml --out out", dir).exitCode == 0);
  std::ofstream(dir / "other.toml") << "base = \"base.toml\"\n[vary]\n"
                                       "\"tamponade.fill\" = [\"85 %\"]\n";
  const auto r = runTamponade("sweep other.toml --out out", dir);
  CHECK(r.exitCode == 2);
  CHECK(r.output.find("holds a different sweep") != std::string::npos);
  const auto s = runTamponade("sweep status nowhere", dir);
  CHECK(s.exitCode == 2);
  CHECK(s.output.find("nowhere is not a sweep folder (no sweep.json)") != std::string::npos);
}

TEST_CASE("tamponade sweep --slurm writes a job array over the unfinished points",
          "[unit][sweep]") {
  const auto dir = sweepFolder("slurm",
                               "base = \"base.toml\"\n[vary]\n"
                               "\"tamponade.fill\" = [\"70 %\", \"80 %\", \"90 %\"]\n");
  auto r = runTamponade(
      "sweep sweep.toml --out out --slurm --no-submit --partition short --time 00:20:00 "
      "--mem 2G --cpus-per-task 2 --max-parallel 2",
      dir);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const std::string script = readText(dir / "out/slurm/sweep.sbatch");
  CHECK(script.find("#SBATCH --array=0-2%2\n") != std::string::npos);
  CHECK(script.find("#SBATCH --cpus-per-task=2\n") != std::string::npos);
  CHECK(script.find("#SBATCH --partition=short\n") != std::string::npos);
  CHECK(script.find("#SBATCH --time=00:20:00\n") != std::string::npos);
  CHECK(script.find("#SBATCH --mem=2G\n") != std::string::npos);
  CHECK(script.find("sweep task '") != std::string::npos);

  // What one array task runs; the array is then written for the two points left.
  r = runTamponade("sweep task out 1 --threads 1", dir);
  CHECK(r.exitCode == 0);
  CHECK(readText(dir / "out/points/p002/point.json").find("\"backend\": \"slurm\"") !=
        std::string::npos);
  r = runTamponade("sweep sweep.toml --out out --slurm --no-submit", dir);
  CHECK(readText(dir / "out/slurm/sweep.sbatch").find("#SBATCH --array=0,2\n") !=
        std::string::npos);
  CHECK(runTamponade("sweep task out 3", dir).exitCode == 2);

  // No Slurm on this machine's PATH: a clear refusal, the script kept for submission elsewhere.
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", "/nonexistent", 1);
  r = runTamponade("sweep sweep.toml --out out --slurm", dir);
  setenv("PATH", path.c_str(), 1);
  CHECK(r.exitCode == 1);
  CHECK(r.output.find("Slurm's sbatch is not on PATH, so nothing was submitted") !=
        std::string::npos);
}

TEST_CASE("A stopped simulated point resumes from its checkpoint to the uninterrupted result",
          "[unit][sweep]") {
  // tiny.toml shortened to 2 x 50 ms: about 60 steps at 1.2 mm (a stop request is honoured at
  // the next checkpointable step, every 16).
  const auto dir =
      sweepFolder("resume", "base = \"" + (kSource / "data/protocols/tiny.toml").string() +
                                "\"\n[vary]\n\"schedule.postures.0.duration\" = [\"0.05 s\"]\n"
                                "\"schedule.postures.1.duration\" = [\"0.05 s\"]\n");
  // The folder made without running (--no-submit), then point p001 stopped at step 5 as a Ctrl-C
  // would leave it.
  REQUIRE(runTamponade("sweep sweep.toml --out out --slurm --no-submit", dir).exitCode == 0);
  const auto p1 = dir / "out/points/p001";
  REQUIRE(runTamponade("run out/points/p001/protocol.toml --out out/points/p001 --threads 1 "
                       "--stop-after-steps 5",
                       dir)
              .exitCode == 1);
  REQUIRE(std::filesystem::exists(p1 / "checkpoint.h5"));
  auto r = runTamponade("sweep sweep.toml --out out --jobs 1 --threads 1", dir);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK(readText(p1 / "run.log").find(" run --resume ") != std::string::npos);
  r = runTamponade("sweep sweep.toml --out whole --jobs 1 --threads 1", dir);
  REQUIRE(r.exitCode == 0);
  CHECK(readText(dir / "whole/points/p001/coverage.csv") == readText(p1 / "coverage.csv"));
}
