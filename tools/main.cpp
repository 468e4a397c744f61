// `tamponade`: dispatches to one sub-command. Library errors become messages and exit codes here
// and only here.
#include <array>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "tools/commands.h"

namespace tools {
int runValidate(Args args);      // tools/cmd_validate.cpp
int runVersion(Args args);       // tools/cmd_version.cpp
int runDemo(Args args);          // tools/cmd_demo.cpp
int runMesh(Args args);          // tools/cmd_mesh.cpp
int runBench(Args args);         // tools/cmd_bench.cpp
int runPlan(Args args);          // tools/cmd_plan.cpp
int runRun(Args args);           // tools/cmd_run.cpp
int runReport(Args args);        // tools/cmd_report.cpp
int runSweepCommand(Args args);  // tools/cmd_sweep.cpp
}  // namespace tools

namespace {

constexpr std::array kCommands = {
    tools::Command{"run", "run a protocol: frames, coverage series and report", tools::runRun},
    tools::Command{"plan", "show the assembled scene, pipeline, memory and run-time estimate",
                   tools::runPlan},
    tools::Command{"report", "rebuild a run's report from its files", tools::runReport},
    tools::Command{"sweep",
                   "parameter studies: run a protocol over fills, agents, angles, postures, eyes "
                   "(locally or on Slurm) into one table and plots",
                   tools::runSweepCommand},
    tools::Command{"validate", "check a protocol file and print it in SI units",
                   tools::runValidate},
    tools::Command{"mesh", "check, repair, sample and generate eye meshes", tools::runMesh},
    tools::Command{"demo", "run the built-in dam-break scene, write HDF5 + XDMF frames",
                   tools::runDemo},
    tools::Command{"bench",
                   "benchmarks: bench engine (dam break speed), bench solvers (multiphase "
                   "comparison), bench accuracy (accuracy vs time of a protocol)",
                   tools::runBench},
    tools::Command{"version", "print the version", tools::runVersion},
};

void printUsage(std::FILE* out) {
  std::fprintf(out,
               "tamponade %s: silicone-oil tamponade simulation toolkit\n\n"
               "usage: tamponade <command> [options]   (tamponade <command> --help for details)\n\n"
               "commands:\n",
               TAMPONADE_VERSION);
  for (const auto& c : kCommands)
    std::fprintf(out, "  %-9.*s %.*s\n", static_cast<int>(c.name.size()), c.name.data(),
                 static_cast<int>(c.summary.size()), c.summary.data());
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string_view> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    printUsage(args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    std::printf("tamponade %s\n", TAMPONADE_VERSION);
    return 0;
  }
  for (const auto& c : kCommands) {
    if (c.name != args[0]) continue;
    try {
      return c.run(tools::Args(args).subspan(1));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tamponade %s: error: %s\n", std::string(c.name).c_str(), e.what());
      return 1;
    }
  }
  std::fprintf(stderr, "tamponade: unknown command '%s'\n\n", std::string(args[0]).c_str());
  printUsage(stderr);
  return 2;
}
