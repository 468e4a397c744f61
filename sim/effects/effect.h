// A non-pressure physical effect (gravity, viscosity, surface tension, adhesion, elasticity...):
// one pipeline stage that adds accelerations to the dynamic particles.
//
// An effect registers the per-particle fields it owns in attach(), so an absent effect allocates
// nothing (docs/developer-guide.md principle 1), and reports its own time-step limit.
#pragma once

#include <limits>
#include <string_view>

#include "sim/world/step_context.h"
#include "sim/world/world.h"

namespace sim {

class Effect {
 public:
  // kExplicit effects add accelerations before the velocity prediction v* = v + dt a;
  // kImplicit effects (implicit viscosity, implicit elasticity) then act on v* directly.
  enum class Kind { kExplicit, kImplicit };

  virtual ~Effect() = default;
  virtual std::string_view name() const = 0;
  virtual Kind kind() const { return Kind::kExplicit; }
  // Registers fields, precomputes what stays fixed. Called once, after World::initialize().
  virtual void attach(World&) {}
  // kExplicit: adds this effect's acceleration [m/s^2] to world.particles.a; kImplicit: updates
  // the predicted velocities world.particles.v. Neighbour lists and densities are current.
  virtual void apply(World& world, const StepContext& context) = 0;
  // Largest stable time step this effect allows [s] (infinity if it imposes none).
  virtual Real maxTimeStep(const World&) const { return std::numeric_limits<Real>::infinity(); }
};

}  // namespace sim
