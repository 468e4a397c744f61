#include "protocols/bench/solver_comparison.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "protocols/io/io_error.h"
#include "sim/core/error.h"
#include "sim/measure/diagnostics.h"
#include "sim/measure/interface_gap.h"

namespace protocols {
namespace {

constexpr int kGapEvery = 10;  // [steps] the gap costs a neighbour pass; every 10th step suffices

// The first reason the state counts as failed, or "".
std::string failureOf(const TwoPhaseDamBreak& scene, const sim::PressureSolver& solver,
                      const SolverComparisonLimits& limits) {
  const sim::World& w = *scene.world;
  if (!sim::allFinite(w)) return "non-finite position or velocity";
  const double d = scene.spec.spacing;
  for (const sim::Vec3& x : w.particles.x)
    if ((x.array() < scene.tank.innerMin.array() - d).any() ||
        (x.array() > scene.tank.innerMax.array() + d).any())
      return "a particle left the tank";
  const double kinetic = sim::kineticEnergy(w);
  if (kinetic > limits.energyFactor * scene.potentialEnergy) {
    char text[128];
    std::snprintf(text, sizeof text, "kinetic energy %.3g J, %.3gx the released %.3g J", kinetic,
                  kinetic / scene.potentialEnergy, scene.potentialEnergy);
    return text;
  }
  if (solver.stats().maxCompression > limits.maxCompression) {
    char text[96];
    std::snprintf(text, sizeof text, "compression %.3g above %.3g", solver.stats().maxCompression,
                  limits.maxCompression);
    return text;
  }
  return "";
}

std::string ratioText(double ratio) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", ratio);
  return text;
}

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out)
    throw IoError(path.string(), "", "cannot write the file",
                  "check the folder's permissions and free space");
}

}  // namespace

SolverComparisonRun runSolverComparison(const TwoPhaseDamBreakSpec& spec, double duration,
                                        const SolverComparisonLimits& limits) {
  SolverComparisonRun run;
  run.solver = spec.solver;
  run.densityRatio = spec.densityRatio;
  run.duration = duration;
  TwoPhaseDamBreak scene = buildTwoPhaseDamBreak(spec);
  sim::World& world = *scene.world;
  sim::Pipeline pipeline = sim::assemblePipeline(world, scene.options);
  pipeline.attach(world);
  run.particles = static_cast<long>(world.particles.size());

  long cumulative = 0;
  double gap = 0.0, gapSum = 0.0;  // [d]
  long gapSamples = 0;
  double ratioSum = 0.0;
  long ratioSamples = 0;
  double compressionSum = 0.0;  // [1 s] time integral of the average compression
  const auto start = std::chrono::steady_clock::now();
  while (world.time < duration) {
    try {
      pipeline.step(world);
    } catch (const sim::SimError& error) {
      run.stable = false;
      run.failedAt = world.time;
      run.failure = std::string("engine error: ") + error.what();
      break;
    }
    const sim::SolverStats& stats = pipeline.solver().stats();
    const long iterations = stats.densityIterations + stats.divergenceIterations;
    cumulative += iterations;
    if (world.stepCount % kGapEvery == 0 || run.series.empty()) {
      const sim::InterfaceGap measured = sim::interfaceGap(world, 1, 0);
      gap = measured.meanNearestDistance;
      gapSum += gap;
      ++gapSamples;
      if (measured.numberDensityRatio > 0) {
        ratioSum += measured.numberDensityRatio;
        ++ratioSamples;
      }
    }
    run.series.push_back({world.time, world.stepCount, stats.averageCompression,
                          stats.maxCompression, iterations, cumulative, gap});
    compressionSum += stats.averageCompression * world.lastTimeStep;
    run.maxCompression = std::max(run.maxCompression, stats.maxCompression);
    if (sim::allFinite(world))
      run.peakEnergyRatio =
          std::max(run.peakEnergyRatio, sim::kineticEnergy(world) / scene.potentialEnergy);
    const std::string failure = failureOf(scene, pipeline.solver(), limits);
    if (!failure.empty()) {
      run.stable = false;
      run.failedAt = world.time;
      run.failure = failure;
      break;
    }
  }
  run.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.simulatedTime = world.time;
  run.steps = static_cast<long>(run.series.size());
  if (run.steps > 0) {
    run.meanAverageCompression = world.time > 0 ? compressionSum / world.time : 0.0;
    run.meanIterations = static_cast<double>(cumulative) / static_cast<double>(run.steps);
  }
  if (gapSamples > 0) run.meanInterfaceGap = gapSum / static_cast<double>(gapSamples);
  run.finalInterfaceGap = gap;
  if (ratioSamples > 0)
    run.meanInterfaceDensityRatio = ratioSum / static_cast<double>(ratioSamples);
  return run;
}

std::string runFileStem(const SolverComparisonRun& run) {
  return run.solver + "_1-" + ratioText(run.densityRatio);
}

std::string solverComparisonCsv(const std::vector<SolverComparisonRun>& runs) {
  std::ostringstream csv;
  csv.precision(6);
  csv << "solver,density_ratio,particles,stable,failed_at_s,failure,simulated_s,steps,"
         "mean_average_compression,max_compression,mean_iterations,mean_interface_gap_d,"
         "final_interface_gap_d,interface_density_ratio,peak_kinetic_over_potential,wall_s,"
         "wall_per_simulated_s\n";
  for (const SolverComparisonRun& r : runs) {
    std::string failure = r.failure;  // CSV-safe: no commas or quotes inside the field
    for (char& c : failure)
      if (c == ',' || c == '"') c = ';';
    csv << r.solver << ",1:" << ratioText(r.densityRatio) << ',' << r.particles << ','
        << (r.stable ? "yes" : "no") << ',' << (r.stable ? std::string() : ratioText(r.failedAt))
        << ',' << failure << ',' << r.simulatedTime << ',' << r.steps << ','
        << r.meanAverageCompression << ',' << r.maxCompression << ',' << r.meanIterations << ','
        << r.meanInterfaceGap << ',' << r.finalInterfaceGap << ',' << r.meanInterfaceDensityRatio
        << ',' << r.peakEnergyRatio << ',' << r.wallSeconds << ',' << r.wallPerSimulatedSecond()
        << '\n';
  }
  return csv.str();
}

std::string solverComparisonMarkdown(const std::vector<SolverComparisonRun>& runs) {
  std::ostringstream md;
  md << "| solver | ratio | stable (failed at) | mean / max compression | iterations/step | "
        "interface gap mean / end [d] | interface density ratio | peak KE / released PE | "
        "wall s per simulated s |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
  char line[512];
  for (const SolverComparisonRun& r : runs) {
    const std::string stability =
        r.stable
            ? "yes"
            : "no (" + ratioText(std::round(r.failedAt * 1e4) / 1e4) + " s: " + r.failure + ")";
    std::snprintf(line, sizeof line,
                  "| %s | 1:%s | %s | %.2e / %.2e | %.1f | %.2f / %.2f | %.3f | %.2g | %.3g |\n",
                  r.solver.c_str(), ratioText(r.densityRatio).c_str(), stability.c_str(),
                  r.meanAverageCompression, r.maxCompression, r.meanIterations, r.meanInterfaceGap,
                  r.finalInterfaceGap, r.meanInterfaceDensityRatio, r.peakEnergyRatio,
                  r.wallPerSimulatedSecond());
    md << line;
  }
  return md.str();
}

std::string compressionSeriesCsv(const SolverComparisonRun& run) {
  std::ostringstream csv;
  csv.precision(9);
  csv << "time_s,step,average_compression,max_compression\n";
  for (const auto& s : run.series)
    csv << s.time << ',' << s.step << ',' << s.averageCompression << ',' << s.maxCompression
        << '\n';
  return csv.str();
}

std::string iterationSeriesCsv(const SolverComparisonRun& run) {
  std::ostringstream csv;
  csv.precision(9);
  csv << "time_s,step,iterations,cumulative_iterations,interface_gap_d\n";
  for (const auto& s : run.series)
    csv << s.time << ',' << s.step << ',' << s.iterations << ',' << s.cumulativeIterations << ','
        << s.interfaceGap << '\n';
  return csv.str();
}

void writeSolverComparison(const std::vector<SolverComparisonRun>& runs,
                           const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec)
    throw IoError(folder.string(), "", "cannot create the folder: " + ec.message(),
                  "choose another --out");
  writeText(folder / "solvers.csv", solverComparisonCsv(runs));
  writeText(folder / "solvers.md", solverComparisonMarkdown(runs));
  for (const SolverComparisonRun& r : runs) {
    writeText(folder / ("compression_" + runFileStem(r) + ".csv"), compressionSeriesCsv(r));
    writeText(folder / ("iterations_" + runFileStem(r) + ".csv"), iterationSeriesCsv(r));
  }
}

}  // namespace protocols
