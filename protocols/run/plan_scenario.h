// What `tamponade plan` reports for an assembled scenario: particle counts, the pipeline and why
// each stage is there, memory, and run-time estimates per accuracy preset from a cost model.
//
// Cost model: run time = (particle-steps) x (seconds per particle-step), with
//  * seconds per particle-step measured on this machine by a calibration run: the scenario's own
//    world stepped `calibrationSteps` times after one warm-up step (the first step builds
//    caches), each step timed, the fastest step's wall-clock time over the dynamic particles
//    (the machine is shared: slower steps measure the other processes), rejected-and-redone
//    steps included, at the current OpenMP thread count;
//  * particle count of another preset: N (d / d_preset)^3 (fluid fills a volume);
//  * time step of another preset: the calibration's first step length, scaled by what limited it:
//    the CFL or the solver's acoustic limit ~ d, a viscous limit ~ d^2 (explicit viscosity,
//    Monaghan 2005), the preset's bound when that was the limit; clamped to the preset's bounds;
//  * steps = the schedule's simulated duration / that time step.
// Known biases: the fluid starts at rest, so the CFL limit is at its loosest (flows shorten the
// step); the pressure solver's iteration count grows with resolution. Both make the estimate a
// lower bound, more so for finer presets.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "protocols/scenario/scenario.h"

namespace protocols {

struct PlanOptions {
  int calibrationSteps = 5;  // timed steps after one warm-up step
};

struct PresetEstimate {
  std::string preset;
  double particleSpacing = 0.0;  // [m]
  double particles = 0.0;        // dynamic particles (estimate unless it is the scenario's own)
  double timeStep = 0.0;         // [s]
  double steps = 0.0;
  double seconds = 0.0;  // [s] wall-clock estimate
};

struct ScenarioPlan {
  std::string pipeline;  // sim::Pipeline::describe()
  std::vector<sim::StageDecision> decisions;
  std::size_t dynamicParticles = 0;
  std::size_t wallParticles = 0;
  std::size_t particleFieldBytes = 0;  // [B] dynamic particle fields incl. the stages' fields
  std::size_t wallFieldBytes = 0;      // [B]
  std::size_t neighborListBytes = 0;   // [B] CSR lists as built at the start
  std::size_t totalBytes() const { return particleFieldBytes + wallFieldBytes + neighborListBytes; }
  // [B] this process's peak resident size after assembly and calibration (0 where it cannot be
  // read): a run of the scene peaks up to ~10 % higher (memory_estimate.h).
  double peakResidentBytes = 0.0;
  // Calibration.
  int calibrationSteps = 0;
  int threads = 1;
  double calibrationSeconds = 0.0;      // [s] wall-clock of all timed steps
  double secondsPerParticleStep = 0.0;  // [s]
  double firstTimeStep = 0.0;           // [s]
  std::string timeStepLimitedBy;
  // Every stage's own time-step limit at the start [s] (stages without one are left out), so
  // users see what each effect costs in steps (e.g. the capillary or elastic-wave limit).
  std::vector<std::pair<std::string, double>> stageTimeStepLimits;
  long rejectedSteps = 0;
  // [s] the simulated postures' durations; an equilibrium schedule's nominal seconds (what
  // simulating them would cost, shown beside the solve)
  double simulatedDuration = 0.0;
  std::array<PresetEstimate, 3> presets;  // draft, standard, fine
};

// Assembles the pipeline, attaches it, and runs the calibration steps on the scenario's world
// (which is left advanced by those steps: plan on a scenario you will not run).
ScenarioPlan planScenario(Scenario& scenario, const PlanOptions& options = {});

}  // namespace protocols
