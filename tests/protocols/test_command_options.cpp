// Every `tamponade` command checks its options before doing anything: a value that is not a
// number, out of range, an unknown option or a missing value exits 2 with a message naming the
// option; --help explains every command and sub-command on stdout and exits 0.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"

namespace fs = std::filesystem;
using tamponade_test::runTamponade;

namespace {

struct BadOption {
  std::string arguments;
  std::string mustSay;  // names the option (or the argument) and the problem
};

// Nothing here reads a file: every case fails in the option parser, before the protocol, the
// mesh or the folder is looked at.
const std::vector<BadOption> kBadOptions = {
    // run
    {"run p.toml --stop-after-steps abc", "--stop-after-steps: 'abc' must be a positive whole"},
    {"run p.toml --stop-after-steps 0", "--stop-after-steps: '0' must be a positive whole"},
    {"run p.toml --threads 0", "--threads: '0' must be a positive whole number"},
    {"run p.toml --threads -1", "--threads: '-1' must be a positive whole number"},
    {"run p.toml --threads 2x", "--threads: '2x' must be a positive whole number"},
    {"run p.toml --threads 99999999999", "--threads: '99999999999' must be a whole number from 1"},
    {"run p.toml --accuracy bogus", "--accuracy: 'bogus' must be draft, standard or fine"},
    {"run p.toml --max-memory 4", "--max-memory: '4' must be a positive size with a unit"},
    {"run p.toml --out", "--out: 1 required DIR missing"},
    {"run p.toml --frobnicate", "not expected: --frobnicate"},
    {"run p.toml q.toml", "not expected: q.toml"},
    {"run --resume dir p.toml", "excludes --resume"},
    {"run --resume dir --out x", "excludes"},
    {"run", "give the protocol file, or --resume DIR"},
    // plan
    {"plan p.toml --accuracy fast", "--accuracy: 'fast' must be draft, standard or fine"},
    {"plan p.toml --max-memory -1GiB", "--max-memory: '-1GiB' must be a positive size"},
    {"plan p.toml --max-memory", "--max-memory: 1 required SIZE missing"},
    {"plan p.toml --threads 2", "not expected: --threads 2"},
    {"plan", "PROTOCOL.toml is required"},
    // report, validate, version
    {"report", "DIR is required"},
    {"report a b", "not expected: b"},
    {"validate --strict p.toml", "not expected: --strict"},
    {"validate --reference p.toml", "excludes"},
    {"version --verbose", "not expected: --verbose"},
    // sweep and its sub-commands
    {"sweep s.toml --out o --jobs 0", "--jobs: '0' must be a positive whole number"},
    {"sweep s.toml --out o --threads x", "--threads: 'x' must be a positive whole number"},
    {"sweep s.toml --out o --max-points -5", "--max-points: '-5' must be a positive whole"},
    {"sweep s.toml --out o --cpus-per-task 0", "--cpus-per-task: '0' must be a positive whole"},
    {"sweep s.toml --out o --max-parallel many", "--max-parallel: 'many' must be a positive"},
    {"sweep s.toml --out o --partition short", "--partition requires --slurm"},
    {"sweep s.toml --out o --no-submit", "--no-submit requires --slurm"},
    {"sweep s.toml --out", "--out: 1 required DIR missing"},
    {"sweep s.toml --out o --fast", "not expected: --fast"},
    {"sweep s.toml", "give the output folder with --out DIR"},
    {"sweep", "give the sweep file"},
    {"sweep status", "DIR is required"},
    {"sweep collect o --all", "not expected: --all"},
    {"sweep task o abc", "INDEX: 'abc' must be a whole number"},
    {"sweep task o 1 --threads 0", "--threads: '0' must be a positive whole number"},
    // mesh and its sub-commands
    {"mesh", "give a mesh command: check, sample or generate"},
    {"mesh frobnicate x", "not expected: frobnicate x"},
    {"mesh check m.stl --max-hole-edges abc", "--max-hole-edges: 'abc' must be a whole number"},
    {"mesh check m.stl --max-hole-edges 10000", "--max-hole-edges: '10000' must be a whole"},
    {"mesh check m.stl --units inch", "--units: 'inch' must be mm or m"},
    {"mesh check", "FILE is required"},
    {"mesh sample m.stl --spacing 1", "--spacing: '1' is not a length with a unit"},
    {"mesh sample m.stl --spacing", "--spacing: 1 required LENGTH missing"},
    {"mesh sample m.stl", "--spacing is required"},
    {"mesh generate --type myopic --out x.stl --resolution abc", "--resolution: 'abc' must be"},
    {"mesh generate --type myopic --out x.stl --axial-length 28",
     "--axial-length: 28 needs a unit"},
    {"mesh generate --type myopic --out x.stl --cap-sag 1in", "--cap-sag: '1in': unknown unit"},
    {"mesh generate --type round --out x.stl", "--type: 'round' must be emmetropic, myopic or"},
    {"mesh generate --type myopic --out x.vtk", "--out: 'x.vtk' must end in .stl, .obj or .ply"},
    // demo
    {"demo --time abc", "--time: 'abc' must be a positive number"},
    {"demo --time 0", "--time: '0' must be a positive number"},
    {"demo --time 61", "--time: '61' is above its largest value, 60"},
    {"demo --solver bogus", "--solver: 'bogus' must be dfsph, wcsph"},
    {"demo --out", "--out: 1 required DIR missing"},
    {"demo --fast", "not expected: --fast"},
    // bench and its sub-commands
    {"bench", "give a benchmark: engine, solvers or accuracy"},
    {"bench engine --particles abc", "--particles: 'abc' must be a number from 1000 to 5e+07"},
    {"bench engine --particles 30000,10", "--particles: '10' must be a number from 1000"},
    {"bench engine --time 0", "--time: '0' must be a positive number"},
    {"bench engine --solvers dfsph,bogus", "--solvers: 'bogus' must be dfsph, wcsph"},
    {"bench engine --tolerance 0.2", "--tolerance: '0.2' must be a number from 1e-06 to 0.05"},
    {"bench engine --relaxation 0", "--relaxation: '0' must be a number from 0.05 to 1"},
    {"bench engine --max-error-factor -1",
     "--max-error-factor: '-1' must be a number from 0 to 1e+06"},
    {"bench engine --initial-density 0.3",
     "--initial-density: '0.3' must be a number from 0.5 to 1"},
    {"bench solvers --ratios 2,0.5", "--ratios: '0.5': give heavy/light >= 1"},
    {"bench solvers --time abc", "--time: 'abc' must be a positive number"},
    {"bench solvers --quick=maybe", "--quick"},
    {"bench accuracy p.toml --tolerances 0.2", "--tolerances: '0.2' is above its largest value"},
    {"bench accuracy p.toml --spacings 6", "--spacings: '6' is above its largest value, 5"},
    {"bench accuracy p.toml --threads 0", "--threads: '0' must be a positive whole number"},
    {"bench accuracy --out x", "PROTOCOL.toml is required"},
};

}  // namespace

TEST_CASE("command line: a bad option exits 2 naming the option, before anything runs",
          "[unit][cli]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_command_options_test");
  const std::filesystem::path& dir = scratch.path();
  for (const BadOption& c : kBadOptions) {
    const tamponade_test::CommandResult r = runTamponade(c.arguments, dir);
    INFO("tamponade " << c.arguments << "\n" << r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(c.mustSay) != std::string::npos);
    CHECK(r.output.find("--help explains every option") != std::string::npos);
  }
  // Nothing was written.
  CHECK(fs::is_empty(dir));
}

TEST_CASE("command line: --help on every command and sub-command explains its options",
          "[unit][cli]") {
  const std::vector<std::string> commands = {
      "run",           "plan",          "report",        "validate",      "version",
      "demo",          "sweep",         "sweep status",  "sweep collect", "mesh",
      "mesh check",    "mesh sample",   "mesh generate", "bench",         "bench engine",
      "bench solvers", "bench accuracy"};
  for (const std::string& command : commands) {
    const tamponade_test::CommandResult r = runTamponade(command + " --help");
    INFO("tamponade " << command << " --help\n" << r.output);
    CHECK(r.exitCode == 0);
    CHECK(r.output.rfind("usage: tamponade " + command, 0) == 0);
    CHECK(r.output.find("-h,--help") != std::string::npos);
  }
  CHECK(runTamponade("run --help").output.find("--stop-after-steps N") != std::string::npos);
  CHECK(runTamponade("sweep --help").output.find("--max-points N") != std::string::npos);
}

TEST_CASE("command line: the dispatcher's usage and unknown commands exit 2", "[unit][cli]") {
  const tamponade_test::CommandResult none = runTamponade("");
  CHECK(none.exitCode == 2);
  CHECK(none.output.find("usage: tamponade <command>") != std::string::npos);
  const tamponade_test::CommandResult unknown = runTamponade("frobnicate");
  CHECK(unknown.exitCode == 2);
  CHECK(unknown.output.find("unknown command 'frobnicate'") != std::string::npos);
  CHECK(runTamponade("--help").exitCode == 0);
  CHECK(runTamponade("--version").exitCode == 0);
}
