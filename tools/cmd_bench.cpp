// `tamponade bench engine`: the engine benchmark. Runs the 3D dam break (column a x 2a
// x a, sim/scenes/dam_break.h) at the requested particle counts for a fixed simulated time with
// each solver and writes bench_engine.csv and bench_engine.md: particles, steps, mean dt, mean
// solver iterations, wall time per step, particle-steps per second, time per pipeline stage.
// Not a test: numbers depend on the machine and its load. Exit codes: 0 ok, 2 bad usage,
// 1 run failure (e.g. an unstable run or an unwritable output folder).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/core/error.h"
#include "sim/scenes/dam_break.h"
#include "sim/world/stage_registry.h"
#include "tools/cli.h"
#include "tools/cli_values.h"

namespace tools {

Subcommand addBenchSolversCommand(CLI::App& bench);   // tools/cmd_bench_solvers.cpp
Subcommand addBenchAccuracyCommand(CLI::App& bench);  // tools/cmd_bench_accuracy.cpp

namespace {

constexpr const char* kBenchUsage =
    "usage: tamponade bench solvers [--quick] [--out DIR]   (the multiphase solver comparison;\n"
    "                                                         --help for its options)\n"
    "       tamponade bench accuracy PROTOCOL.toml [--tolerances ...] [--spacings ...]\n"
    "                              (what each accuracy choice costs and changes; --help)\n"
    "       tamponade bench engine [--particles 30000,100000] [--time SECONDS]\n"
    "                              [--solvers dfsph,wcsph] [--tolerance F] [--relaxation W]\n"
    "                              [--max-error-factor F] [--no-pair-cache]\n"
    "                              [--initial-density R] [--out DIR]\n";

constexpr const char* kEngineUsage =
    "usage: tamponade bench engine [--particles 30000,100000] [--time SECONDS]\n"
    "                              [--solvers dfsph,wcsph] [--tolerance F] [--relaxation W]\n"
    "                              [--max-error-factor F] [--no-pair-cache]\n"
    "                              [--initial-density R] [--out DIR]\n";

constexpr const char* kEngineDescription =
    "Runs the 3D dam break (water column a x 2a x a, a = 0.1 m, in a 4a long tank) with about\n"
    "the given numbers of particles for a fixed simulated time with each solver, and writes\n"
    "DIR/bench_engine.csv and DIR/bench_engine.md. Prints progress. Every iterative solver\n"
    "stops at the same mean density error (--tolerance), so their iterations compare.\n"
    "The table also counts the particles whose centre passed the tank's walls (the most after\n"
    "any step, and the deepest in particle spacings): what a stopping rule buys.\n"
    "Threads: OMP_NUM_THREADS. On a shared machine set OMP_WAIT_POLICY=passive.\n";

struct BenchOptions {
  std::vector<double> particles{30000, 100000};  // about, rounded
  double time = 0.05;                            // [s] simulated
  std::vector<std::string> solvers{"dfsph", "wcsph"};
  // [1] mean relative density error at which every iterative solver stops: the standard
  // preset's 0.1 %, so that solvers whose own defaults differ (INDSPH's 0.01 %, the paper's eta)
  // are compared at the same accuracy.
  double tolerance = 1e-3;
  std::optional<double> relaxation;  // [1] Jacobi omega of every solver that has one
  // [1] DFSPH's stopping rule on the largest compression (DfsphParameters::maxErrorFactor);
  // 0 turns it off. Unset: the solver's default.
  std::optional<double> maxErrorFactor;
  bool noPairCache = false;     // WorldParameters::cachePairKernels = false
  double initialDensity = 1.0;  // [1] DamBreakSpec::initialDensityRatio
  std::string out = ".";
};

void defineEngineOptions(CLI::App& app, BenchOptions& o) {
  std::vector<std::string> names;
  for (const auto& entry : sim::solverRegistry()) names.push_back(entry.name);
  app.add_option("--particles", o.particles, "approximate particle counts, one run each")
      ->type_name("N,N,...")
      ->delimiter(',')
      ->check(numberBetween(1000, 5e7))
      ->capture_default_str();
  app.add_option("--time", o.time, "simulated time of each run")
      ->type_name("SECONDS")
      ->check(positiveNumber())
      ->capture_default_str();
  app.add_option("--solvers", o.solvers, "pressure solvers, one run each")
      ->type_name("NAME,...")
      ->delimiter(',')
      ->check(oneOf(names))
      ->capture_default_str();
  app.add_option("--tolerance", o.tolerance,
                 "mean relative density error at which every iterative solver stops")
      ->type_name("F")
      ->check(numberBetween(1e-6, 0.05))
      ->capture_default_str();
  app.add_option("--relaxation", o.relaxation,
                 "Jacobi relaxation of every solver that has one (DFSPH, INDSPH, IISPH; default: "
                 "each solver's own)")
      ->type_name("W")
      ->check(numberBetween(0.05, 1.0));
  app.add_option("--max-error-factor", o.maxErrorFactor,
                 "DFSPH: also iterate while a particle is compressed by more than F times the "
                 "tolerance (default 10; 0 turns the rule off)")
      ->type_name("F")
      ->check(numberBetween(0.0, 1e6));
  app.add_flag("--no-pair-cache", o.noPairCache,
               "keep no kernel value and gradient per neighbour pair (less memory, same results; "
               "the stages evaluate the kernel instead)");
  app.add_option("--initial-density", o.initialDensity,
                 "the column's initial density over the rest density (particle mass R rho0 d^3); "
                 "0.8 is how SPlisHSPlasH's regular fluid blocks start")
      ->type_name("R")
      ->check(numberBetween(0.5, 1.0))
      ->capture_default_str();
  app.add_option("--out", o.out, "output folder")->type_name("DIR")->capture_default_str();
}

struct BenchResult {
  std::string solver;
  long particles = 0;
  long steps = 0;
  long rejected = 0;
  double simulatedTime = 0;       // [s]
  double meanDt = 0;              // [s]
  double meanIterations = 0;      // density-solve iterations per step
  double meanDivIterations = 0;   // divergence-solve iterations per step
  double wallSeconds = 0;         // [s] the time loop only (no scene set-up)
  long mostBeyondWalls = 0;       // largest number of particles past the walls after any step
  double deepestBeyondWalls = 0;  // [d] deepest such particle over the run
  std::vector<sim::StageTimers::Entry> stages;
};

// Particles whose centre lies past the tank's walls (beyond the inner box on a walled side, the
// open top excluded), and the deepest of them in particle spacings: what the walls let through.
struct BeyondWalls {
  long count = 0;
  double deepest = 0;  // [d]
};
BeyondWalls beyondWalls(const sim::DamBreakScene& scene) {
  const sim::World& world = *scene.world;
  const sim::Vec3 lo = scene.tank.innerMin, hi = scene.tank.innerMax;
  BeyondWalls b;
  for (const sim::Vec3& x : world.particles.x) {
    double depth = 0;  // [m]
    for (int k = 0; k < 3; ++k) {
      depth = std::max(depth, lo[k] - x[k]);
      if (k != 1 || scene.tank.closedTop) depth = std::max(depth, x[k] - hi[k]);
    }
    if (depth <= 0) continue;
    ++b.count;
    b.deepest = std::max(b.deepest, depth / world.particleSpacing());
  }
  return b;
}

// The registry entry of `solver` (the option's check has accepted the name).
const sim::SolverEntry& solverEntry(const std::string& solver) {
  const auto& entries = sim::solverRegistry();
  return *std::find_if(entries.begin(), entries.end(),
                       [&](const sim::SolverEntry& e) { return e.name == solver; });
}

BenchResult runOne(const std::string& solver, long targetParticles, const BenchOptions& o) {
  const double simTime = o.time;
  sim::DamBreakSpec spec;
  spec.columnWidth = 0.1;  // [m]
  spec.heightRatio = 2.0;
  spec.depth = spec.columnWidth;
  spec.solver = solver;
  spec.cachePairKernels = !o.noPairCache;
  spec.initialDensityRatio = o.initialDensity;
  // The column holds 2 (a/d)^3 particles.
  const long cells = std::lround(std::cbrt(static_cast<double>(targetParticles) / 2.0));
  spec.spacing = spec.columnWidth / static_cast<double>(cells);
  sim::DamBreakScene scene = sim::buildDamBreak(spec);
  const sim::SolverEntry& entry = solverEntry(solver);
  if (entry.setTolerance) entry.setTolerance(scene.options, o.tolerance);
  if (entry.setRelaxation && o.relaxation) entry.setRelaxation(scene.options, *o.relaxation);
  if (solver == "dfsph" && o.maxErrorFactor)
    scene.options.dfsph.maxErrorFactor =
        *o.maxErrorFactor > 0 ? *o.maxErrorFactor : std::numeric_limits<double>::infinity();
  sim::World& world = *scene.world;
  sim::Pipeline pipeline = sim::assemblePipeline(world, scene.options);
  pipeline.attach(world);

  BenchResult r;
  r.solver = solver;
  r.particles = static_cast<long>(world.particles.size());
  std::fprintf(stderr, "bench %s: %ld particles (d = %.3g mm), %.3g s simulated\n", solver.c_str(),
               r.particles, spec.spacing * 1e3, simTime);
  long iterations = 0, divIterations = 0;
  double nextReport = 0.1;
  const auto start = std::chrono::steady_clock::now();
  while (world.time < simTime) {
    pipeline.step(world);
    iterations += pipeline.solver().stats().densityIterations;
    divIterations += pipeline.solver().stats().divergenceIterations;
    const BeyondWalls beyond = beyondWalls(scene);
    r.mostBeyondWalls = std::max(r.mostBeyondWalls, beyond.count);
    r.deepestBeyondWalls = std::max(r.deepestBeyondWalls, beyond.deepest);
    if (world.time >= nextReport * simTime) {
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "  %3.0f %%  t = %.4f s  steps %ld  wall %.1f s\n",
                   100 * std::min(1.0, world.time / simTime), world.time, world.stepCount, wall);
      while (nextReport <= world.time / simTime) nextReport += 0.1;  // one line per 10 %
    }
  }
  r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.steps = world.stepCount;
  r.rejected = pipeline.rejectedSteps();
  r.simulatedTime = world.time;
  r.meanDt = world.time / static_cast<double>(r.steps);
  r.meanIterations = static_cast<double>(iterations) / static_cast<double>(r.steps);
  r.meanDivIterations = static_cast<double>(divIterations) / static_cast<double>(r.steps);
  r.stages = pipeline.timers().entries();
  return r;
}

void writeReports(const std::vector<BenchResult>& results, const BenchOptions& options) {
  const std::string& dir = options.out;
  std::filesystem::create_directories(dir);
  // Stage names differ per solver ("dfsph.solve", "wcsph.solve"): the CSV lists them in one
  // column as name=seconds pairs so the table stays rectangular.
  const std::string csvPath = dir + "/bench_engine.csv";
  std::ofstream csv(csvPath);
  if (!csv) throw std::runtime_error("cannot write " + csvPath);
  csv << "solver,particles,steps,rejected_steps,simulated_time_s,mean_dt_s,mean_density_iterations,"
         "mean_divergence_iterations,wall_s,wall_per_step_ms,particle_steps_per_s,threads,"
         "most_beyond_walls,deepest_beyond_walls_d,stage_seconds\n";
  const int threads = omp_get_max_threads();
  for (const BenchResult& r : results) {
    csv << r.solver << ',' << r.particles << ',' << r.steps << ',' << r.rejected << ','
        << r.simulatedTime << ',' << r.meanDt << ',' << r.meanIterations << ','
        << r.meanDivIterations << ',' << r.wallSeconds << ','
        << 1e3 * r.wallSeconds / static_cast<double>(r.steps) << ','
        << static_cast<double>(r.particles) * static_cast<double>(r.steps) / r.wallSeconds << ','
        << threads << ',' << r.mostBeyondWalls << ',' << r.deepestBeyondWalls << ',';
    for (std::size_t k = 0; k < r.stages.size(); ++k)
      csv << (k ? ";" : "") << r.stages[k].name << '=' << r.stages[k].seconds;
    csv << '\n';
  }
  const std::string mdPath = dir + "/bench_engine.md";
  std::ofstream md(mdPath);
  if (!md) throw std::runtime_error("cannot write " + mdPath);
  char line[512];
  md << "| solver | particles | steps (rejected) | mean dt [s] | iterations/step (density + "
        "divergence) "
        "| wall/step [ms] | particle-steps/s | past the walls: most particles (deepest [d]) "
        "|\n|---|---|---|---|---|---|---|---|\n";
  for (const BenchResult& r : results) {
    std::snprintf(line, sizeof line,
                  "| %s | %ld | %ld (%ld) | %.3g | %.1f + %.1f | %.2f | %.3g | %ld (%.2f) |\n",
                  r.solver.c_str(), r.particles, r.steps, r.rejected, r.meanDt, r.meanIterations,
                  r.meanDivIterations, 1e3 * r.wallSeconds / static_cast<double>(r.steps),
                  static_cast<double>(r.particles) * static_cast<double>(r.steps) / r.wallSeconds,
                  r.mostBeyondWalls, r.deepestBeyondWalls);
    md << line;
  }
  md << "\nIterative solvers stop at a mean density error of " << options.tolerance
     << (options.relaxation ? "; Jacobi relaxation " + std::to_string(*options.relaxation)
                            : std::string("; each solver's own Jacobi relaxation"))
     << ".\n";
  md << "\nTime per stage, % of the time loop (" << threads
     << " OpenMP threads; no output is "
        "written during the benchmark):\n\n";
  for (const BenchResult& r : results) {
    md << "- " << r.solver << ", " << r.particles << " particles:";
    for (const auto& e : r.stages) {
      std::snprintf(line, sizeof line, " %s %.1f %%", e.name.c_str(),
                    100 * e.seconds / r.wallSeconds);
      md << line << (&e == &r.stages.back() ? "" : ",");
    }
    md << '\n';
  }
  std::printf("wrote %s and %s\n", csvPath.c_str(), mdPath.c_str());
}

int runEngine(const BenchOptions& options) {
  std::vector<BenchResult> results;
  for (double n : options.particles)
    for (const std::string& solver : options.solvers)
      results.push_back(runOne(solver, std::lround(n), options));
  writeReports(results, options);
  std::ifstream md(options.out + "/bench_engine.md");
  std::printf("%s", std::string(std::istreambuf_iterator<char>(md), {}).c_str());
  return 0;
}

Subcommand addEngineCommand(CLI::App& bench) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* engine =
      addSubcommand(bench, "engine", "dam break speed", kEngineUsage, kEngineDescription);
  defineEngineOptions(*engine, *o);
  return {engine, [o] { return runEngine(*o); }};
}

}  // namespace

int runBench(Args args) {
  CLI::App app("", "tamponade bench");
  describeCommand(app, kBenchUsage, "Benchmarks of the engine, the solvers and the accuracy.\n");
  const Subcommand commands[] = {addEngineCommand(app), addBenchSolversCommand(app),
                                 addBenchAccuracyCommand(app)};
  if (const std::optional<int> exit = parseCommandLine(app, args)) return *exit;
  for (const Subcommand& c : commands)
    if (c.app->parsed()) return c.run();
  return usageError(app, "give a benchmark: engine, solvers or accuracy");
}

}  // namespace tools
