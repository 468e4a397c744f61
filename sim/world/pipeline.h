// The effect pipeline (docs/developer-guide.md principle 1): the pressure solver and the effects a
// scene calls for, assembled from the scene by the registries in world/stage_registry.h, each stage
// timed.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sim/core/stage_timer.h"
#include "sim/effects/effect.h"
#include "sim/fluid/pressure_solver.h"
#include "sim/world/world.h"

namespace sim {

// Why a stage is (or is not) in the pipeline, for `tamponade plan` and the run record.
struct StageDecision {
  std::string name;
  bool active = false;
  bool forced = false;  // the protocol forced it on/off against the scene's rule
  std::string reason;
};

// What limited the last time step (for diagnostics and the plan).
struct TimeStepInfo {
  Real dt = 0;            // [s]
  std::string limitedBy;  // "cfl", "max", "min", or the stage name
  // With limitedBy == "min": the step the stages asked for [s] and which one asked (below the
  // minimum, so the minimum was taken instead).
  Real wanted = 0;
  std::string wantedBy;
};

class Pipeline {
 public:
  Pipeline(std::unique_ptr<PressureSolver> solver, std::vector<std::unique_ptr<Effect>> effects,
           std::vector<StageDecision> decisions);

  // Registers every stage's fields. Call once, after World::initialize().
  void attach(World& world);
  // Advances the world by one adaptive time step; returns the step length [s].
  Real step(World& world);
  // The step length the next step would take given the current state [s].
  TimeStepInfo chooseTimeStep(const World& world) const;

  const PressureSolver& solver() const { return *solver_; }
  const std::vector<std::unique_ptr<Effect>>& effects() const { return effects_; }
  const std::vector<StageDecision>& decisions() const { return decisions_; }
  bool hasStage(std::string_view name) const;
  const StageTimers& timers() const { return timers_; }
  StageTimers& timers() { return timers_; }
  const TimeStepInfo& lastTimeStep() const { return lastStep_; }
  // Steps redone with a shorter time step because the pressure solve produced velocities that
  // would move a particle more than WorldParameters::maxDisplacement (see step()).
  long rejectedSteps() const { return rejectedSteps_; }
  // Human-readable pipeline: stages in execution order with the reason each is there.
  std::string describe() const;

 private:
  std::unique_ptr<PressureSolver> solver_;
  std::vector<std::unique_ptr<Effect>> effects_;
  std::vector<StageDecision> decisions_;
  StageTimers timers_;
  int neighborSlot_ = 0, pairKernelSlot_ = 0, solverBeginSlot_ = 0, solverSlot_ = 0,
      integrateSlot_ = 0;
  std::vector<int> effectSlots_;
  // Non-pressure effects, velocity prediction and pressure solve for one step length.
  void advanceVelocities(World& world, const StepContext& context);
  // Throws SimError when `step` had to be raised to the minimum and the world's parameters say
  // to stop then (WorldParameters::stopBelowMinTimeStep).
  void requireAboveMinimum(const World& world, const TimeStepInfo& step) const;
  // chooseTimeStep() into an existing record, reusing its strings' buffers.
  void chooseTimeStep(const World& world, TimeStepInfo& info) const;
  // Anchored particles back to velocity 0 after the pressure solve (see pipeline.cpp).
  void constrainFixed(World& world);

  TimeStepInfo lastStep_;
  std::vector<Vec3> velocityAtStart_;  // [m/s] for redoing a rejected step
  TimeStepInfo previousStep_;          // the step before the last retry (Pipeline::step)
  // [m/s] background_pressure's transport correction dv (x += dt (v + dv)); nullptr without it
  const std::vector<Vec3>* transportShift_ = nullptr;
  long rejectedSteps_ = 0;
  bool attached_ = false;
};

}  // namespace sim
