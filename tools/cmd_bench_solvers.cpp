// `tamponade bench solvers [--quick] [--out DIR] [--solvers a,b] [--ratios 2,3,10] [--time S]`:
// the solver comparison (protocols/bench/solver_comparison.h). Every registered
// pressure solver on the two-phase dam break at density ratios 1:2, 1:3, 1:10, 1:30, 1:75; writes
// solvers.csv, solvers.md and per-run compression/iteration series. Not a test.
// Exit codes: 0 ok (unstable runs are results, not failures), 2 bad usage, 1 output error.
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "protocols/bench/solver_comparison.h"
#include "protocols/io/io_error.h"
#include "sim/core/error.h"
#include "tools/cli.h"
#include "tools/cli_values.h"

namespace tools {
namespace {

constexpr const char* kUsage =
    "usage: tamponade bench solvers [--quick] [--out DIR] [--solvers a,b,...] [--ratios 2,3,...]\n"
    "                               [--time SECONDS]\n";

constexpr const char* kDescription =
    "Two-phase dam break (heavy and light column side by side, each a x 2a, released at once)\n"
    "with every registered pressure solver at density ratios 1:2, 1:3, 1:10, 1:30, 1:75: stable\n"
    "or not (and when it failed), mean/max compression, iterations, interface gap, wall time per\n"
    "simulated second. Writes DIR/solvers.csv, DIR/solvers.md, DIR/compression_<run>.csv\n"
    "(paper Fig. 4) and DIR/iterations_<run>.csv (cumulative, Fig. 7).\n"
    "  default: a = 5 cm, d = a/10, depth 4 d (~3200 particles), 0.6 s simulated\n"
    "  --quick: a = 4 cm, d = a/8, depth 4 d (~1000 particles), 0.25 s simulated (a few minutes)\n"
    "Threads: OMP_NUM_THREADS. On a shared machine set OMP_WAIT_POLICY=passive.\n";

struct SolversOptions {
  std::vector<std::string> solvers;
  std::vector<double> ratios{2, 3, 10, 30, 75};
  std::string out = "bench_solvers";
  bool quick = false;
  double time = -1;  // [s] simulated; < 0 = the mode's default
};

void defineSolversOptions(CLI::App& app, SolversOptions& o) {
  for (const auto& entry : sim::solverRegistry()) o.solvers.push_back(entry.name);
  app.add_flag("--quick", o.quick, "the smaller, shorter scene");
  app.add_option("--out", o.out, "output folder")->type_name("DIR")->capture_default_str();
  app.add_option("--solvers", o.solvers, "pressure solvers (default: every registered one)")
      ->type_name("NAME,...")
      ->delimiter(',')
      ->check(oneOf(o.solvers));
  app.add_option("--ratios", o.ratios, "density ratios heavy/light, each >= 1 (75 for 1:75)")
      ->type_name("R,...")
      ->delimiter(',')
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            if (positiveNumber()(text).empty() && std::stod(text) >= 1) return {};
            return "'" + text + "': give heavy/light >= 1 (75 for 1:75)";
          },
          ""))
      ->capture_default_str();
  app.add_option("--time", o.time, "simulated time (default: the mode's)")
      ->type_name("SECONDS")
      ->check(positiveNumber());
}

int runSolvers(const SolversOptions& o) {
  const bool quick = o.quick;
  const double time = o.time;
  const std::string& out = o.out;
  protocols::TwoPhaseDamBreakSpec spec;
  spec.columnWidth = quick ? 0.04 : 0.05;                  // [m]
  spec.spacing = spec.columnWidth / (quick ? 8.0 : 10.0);  // [m]
  spec.depth = 4 * spec.spacing;  // [m] a slab, as the paper's 2D-like figure
  const double duration = time > 0 ? time : (quick ? 0.25 : 0.6);  // [s]
  std::fprintf(stderr, "bench solvers: a = %.3g m, d = %.3g mm, %.3g s simulated, %d thread(s)\n",
               spec.columnWidth, spec.spacing * 1e3, duration, omp_get_max_threads());
  std::vector<protocols::SolverComparisonRun> runs;
  for (const std::string& solver : o.solvers)
    for (double ratio : o.ratios) {
      spec.solver = solver;
      spec.densityRatio = ratio;
      protocols::SolverComparisonRun r = protocols::runSolverComparison(spec, duration);
      std::fprintf(stderr,
                   "  %-15s 1:%-3g %s  t = %.3f s  %ld steps  max compression %.2e  gap %.2f d  "
                   "%.1f s wall\n",
                   solver.c_str(), ratio, r.stable ? "stable  " : "FAILED  ", r.simulatedTime,
                   r.steps, r.maxCompression, r.finalInterfaceGap, r.wallSeconds);
      if (!r.stable)
        std::fprintf(stderr, "      failed at %.4f s: %s\n", r.failedAt, r.failure.c_str());
      runs.push_back(std::move(r));
    }
  try {
    protocols::writeSolverComparison(runs, out);
  } catch (const protocols::IoError& e) {
    std::fprintf(stderr, "tamponade bench solvers: %s\n", e.what());
    return 1;
  }
  std::printf("%s\nwrote %s/solvers.csv, %s/solvers.md and per-run series\n",
              protocols::solverComparisonMarkdown(runs).c_str(), out.c_str(), out.c_str());
  return 0;
}

}  // namespace

Subcommand addBenchSolversCommand(CLI::App& bench) {
  auto o = std::make_shared<SolversOptions>();
  CLI::App* solvers =
      addSubcommand(bench, "solvers", "the multiphase solver comparison", kUsage, kDescription);
  defineSolversOptions(*solvers, *o);
  return {solvers, [o] { return runSolvers(*o); }};
}

}  // namespace tools
