#include "protocols/run/plan_scenario.h"
#include "protocols/assembly/assemble_scenario.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace protocols {

namespace {

// [s] What a run simulates: the postures that are not at their equilibrium; for an equilibrium
// schedule, its nominal seconds.
double simulatedDuration(const Scenario& s) {
  double t = 0.0;
  bool simulates = false;
  for (const ScheduledPosture& p : s.schedule)
    if (!p.equilibrium) {
      t += p.duration;
      simulates = true;
    }
  return simulates ? t : s.totalDuration();
}

// What the scene holds and what its fields and neighbour lists take.
void describeScene(const Scenario& s, const sim::Pipeline& pipeline, ScenarioPlan& plan) {
  const sim::World& world = *s.world;
  plan.pipeline = pipeline.describe();
  plan.decisions = pipeline.decisions();
  plan.dynamicParticles = world.particles.size();
  plan.wallParticles = world.walls.size();
  plan.particleFieldBytes = world.particles.fields.bytes();
  plan.wallFieldBytes = world.walls.fields.bytes();
  const auto listBytes = [](const sim::NeighborList& l) {
    return (l.offsets.capacity() + l.indices.capacity()) * sizeof(sim::Index);
  };
  plan.neighborListBytes = listBytes(world.fluidNeighbors()) + listBytes(world.wallNeighbors());
  plan.simulatedDuration = simulatedDuration(s);
#ifdef _OPENMP
  plan.threads = omp_get_max_threads();
#endif
}

// One warm-up step (first-touch allocations), then the timed steps. Returns the first step's
// time-step choice.
sim::TimeStepInfo calibrate(Scenario& s, sim::Pipeline& pipeline, const PlanOptions& options,
                            ScenarioPlan& plan) {
  sim::World& world = *s.world;
  const auto addLimit = [&](std::string_view name, double limit) {
    if (std::isfinite(limit)) plan.stageTimeStepLimits.emplace_back(std::string(name), limit);
  };
  addLimit(pipeline.solver().name(), pipeline.solver().maxTimeStep(world));
  for (const auto& e : pipeline.effects()) addLimit(e->name(), e->maxTimeStep(world));
  const sim::TimeStepInfo first = pipeline.chooseTimeStep(world);
  requireStartTimeStep(s, first);
  plan.firstTimeStep = first.dt;
  plan.timeStepLimitedBy = first.limitedBy;
  pipeline.step(world);
  const long rejectedBefore = pipeline.rejectedSteps();
  // Each step timed on its own; the cost is the fastest one. The machine is shared (and OpenMP
  // threads spin-wait when cores are oversubscribed), so the slower steps measure the other
  // processes; the fastest is the closest to this scene's own cost.
  double fastest = 1e300;  // [s]
  for (int k = 0; k < options.calibrationSteps; ++k) {
    const auto start = std::chrono::steady_clock::now();
    pipeline.step(world);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    plan.calibrationSeconds += seconds;
    fastest = std::min(fastest, seconds);
  }
  plan.calibrationSteps = options.calibrationSteps;
  plan.peakResidentBytes = peakResidentBytes().value_or(0.0);
  plan.rejectedSteps = pipeline.rejectedSteps() - rejectedBefore;
  plan.secondsPerParticleStep =
      (options.calibrationSteps > 0 ? fastest : 0.0) /
      static_cast<double>(std::max<std::size_t>(1, plan.dynamicParticles));
  return first;
}

// Each preset's particles, time step and run time, scaled from this scene's spacing and first
// step by what limited that step.
void estimatePresets(double spacing, const sim::TimeStepInfo& first, ScenarioPlan& plan) {
  for (std::size_t k = 0; k < kAccuracyPresets.size(); ++k) {
    const AccuracyPresetValues& v = kAccuracyPresets[k];
    PresetEstimate& e = plan.presets[k];
    e.preset = std::string(v.name);
    e.particleSpacing = v.particleSpacing;
    const double ratio = spacing / v.particleSpacing;  // [1]
    e.particles = static_cast<double>(plan.dynamicParticles) * ratio * ratio * ratio;
    double dt = first.dt;
    if (first.limitedBy == "max")
      dt = v.maxTimeStep;
    else if (first.limitedBy == "min")
      dt = v.minTimeStep;
    else if (first.limitedBy == "viscosity")
      dt = first.dt / (ratio * ratio);
    else
      dt = first.dt / ratio;  // cfl, solver's acoustic limit
    e.timeStep = std::clamp(dt, v.minTimeStep, v.maxTimeStep);
    e.steps = std::ceil(plan.simulatedDuration / e.timeStep);
    e.seconds = e.steps * e.particles * plan.secondsPerParticleStep;
  }
}

}  // namespace

ScenarioPlan planScenario(Scenario& s, const PlanOptions& options) {
  sim::Pipeline pipeline = sim::assemblePipeline(*s.world, s.pipelineOptions);
  pipeline.attach(*s.world);
  ScenarioPlan plan;
  describeScene(s, pipeline, plan);
  const sim::TimeStepInfo first = calibrate(s, pipeline, options, plan);
  estimatePresets(s.accuracy.particleSpacing, first, plan);
  return plan;
}

}  // namespace protocols
