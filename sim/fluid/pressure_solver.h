// The interface every pressure solver implements (WCSPH, DFSPH, IISPH, number-density, INDSPH),
// so that they can be swapped on the same scene for comparison (docs/developer-guide.md principle
// 3).
//
// A step is: neighbour update; beginStep (densities, solver factors, and for DFSPH-like solvers the
// divergence-free solve); non-pressure effects add accelerations; the time step is chosen;
// velocities are predicted v* = v + dt a; correctVelocities makes v* satisfy the solver's
// incompressibility (or adds the explicit pressure acceleration); positions advance x += dt v.
#pragma once

#include <limits>
#include <string_view>

#include "sim/world/step_context.h"
#include "sim/world/world.h"

namespace sim {

class PressureSolver {
 public:
  virtual ~PressureSolver() = default;
  virtual std::string_view name() const = 0;
  // Registers fields (e.g. warm-start pressures, which are checkpointed). Called once.
  virtual void attach(World& world) = 0;
  // Called after the neighbour update with the previous step's dt in context (0 on the first).
  virtual void beginStep(World& world, const StepContext& context) = 0;
  virtual void correctVelocities(World& world, const StepContext& context) = 0;
  // Largest stable time step the solver allows (e.g. the acoustic limit of WCSPH) [s].
  virtual Real maxTimeStep(const World&) const { return std::numeric_limits<Real>::infinity(); }
  const SolverStats& stats() const { return stats_; }

 protected:
  SolverStats stats_;
};

}  // namespace sim
