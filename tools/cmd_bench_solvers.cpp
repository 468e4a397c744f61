// `tamponade bench solvers [--quick] [--out DIR] [--solvers a,b] [--ratios 2,3,10] [--time S]`:
// the solver comparison (protocols/bench/solver_comparison.h). Every registered
// pressure solver on the two-phase dam break at density ratios 1:2, 1:3, 1:10, 1:30, 1:75; writes
// solvers.csv, solvers.md and per-run compression/iteration series. Not a test.
// Exit codes: 0 ok (unstable runs are results, not failures), 2 bad usage, 1 output error.
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "protocols/bench/solver_comparison.h"
#include "protocols/io/io_error.h"
#include "sim/core/error.h"
#include "tools/cli_args.h"
#include "tools/commands.h"

namespace tools {
namespace {

constexpr const char* kUsage =
    "usage: tamponade bench solvers [--quick] [--out DIR] [--solvers a,b,...] [--ratios 2,3,...]\n"
    "                               [--time SECONDS]\n\n"
    "Two-phase dam break (heavy and light column side by side, each a x 2a, released at once)\n"
    "with every registered pressure solver at density ratios 1:2, 1:3, 1:10, 1:30, 1:75: stable\n"
    "or not (and when it failed), mean/max compression, iterations, interface gap, wall time per\n"
    "simulated second. Writes DIR/solvers.csv, DIR/solvers.md, DIR/compression_<run>.csv\n"
    "(paper Fig. 4) and DIR/iterations_<run>.csv (cumulative, Fig. 7). Default DIR: "
    "bench_solvers.\n"
    "  default: a = 5 cm, d = a/10, depth 4 d (~3200 particles), 0.6 s simulated\n"
    "  --quick: a = 4 cm, d = a/8, depth 4 d (~1000 particles), 0.25 s simulated (a few minutes)\n"
    "Threads: OMP_NUM_THREADS. On a shared machine set OMP_WAIT_POLICY=passive.\n";

}  // namespace

int runBenchSolvers(Args args) {
  std::vector<std::string> solvers;
  for (const auto& entry : sim::solverRegistry()) solvers.push_back(entry.name);
  std::vector<double> ratios{2, 3, 10, 30, 75};
  std::string out = "bench_solvers";
  bool quick = false;
  double time = -1;  // [s] simulated; < 0 = the mode's default
  try {
    for (std::size_t k = 0; k < args.size(); ++k) {
      const std::string_view flag = args[k];
      if (flag == "--help" || flag == "-h") {
        std::fputs(kUsage, stdout);
        return 0;
      }
      if (flag == "--quick") {
        quick = true;
        continue;
      }
      if (k + 1 >= args.size()) throw UsageError("option " + std::string(flag) + " needs a value");
      const std::string value(args[++k]);
      if (flag == "--out") {
        out = value;
      } else if (flag == "--time") {
        time = parsePositive(value, "--time");
      } else if (flag == "--ratios") {
        ratios.clear();
        for (const std::string& r : splitList(value)) {
          const double ratio = parsePositive(r, "--ratios");
          if (ratio < 1)
            throw UsageError("--ratios '" + r + "': give heavy/light >= 1 (75 for 1:75)");
          ratios.push_back(ratio);
        }
        if (ratios.empty()) throw UsageError("--ratios needs at least one ratio");
      } else if (flag == "--solvers") {
        solvers = splitList(value);
        if (solvers.empty()) throw UsageError("--solvers needs at least one solver name");
        for (const std::string& s : solvers) {
          bool known = false;
          std::string names;
          for (const auto& entry : sim::solverRegistry()) {
            known = known || entry.name == s;
            names += (names.empty() ? "" : ", ") + entry.name;
          }
          if (!known)
            throw UsageError("--solvers: unknown solver '" + s + "' (known: " + names + ")");
        }
      } else {
        throw UsageError("unknown option '" + std::string(flag) + "'");
      }
    }
  } catch (const UsageError& e) {
    std::fprintf(stderr, "tamponade bench solvers: %s\n\n%s", e.what(), kUsage);
    return 2;
  }

  protocols::TwoPhaseDamBreakSpec spec;
  spec.columnWidth = quick ? 0.04 : 0.05;                  // [m]
  spec.spacing = spec.columnWidth / (quick ? 8.0 : 10.0);  // [m]
  spec.depth = 4 * spec.spacing;  // [m] a slab, as the paper's 2D-like figure
  const double duration = time > 0 ? time : (quick ? 0.25 : 0.6);  // [s]
  std::fprintf(stderr, "bench solvers: a = %.3g m, d = %.3g mm, %.3g s simulated, %d thread(s)\n",
               spec.columnWidth, spec.spacing * 1e3, duration, omp_get_max_threads());
  std::vector<protocols::SolverComparisonRun> runs;
  for (const std::string& solver : solvers)
    for (double ratio : ratios) {
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

}  // namespace tools
