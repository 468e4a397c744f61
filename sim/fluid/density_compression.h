// The explicit solvers' statistics (WCSPH, VSLSPH: no solve to iterate): the mean positive and
// the largest compression rho / rho0 - 1 of the mass-weighted densities this step.
#pragma once

#include <algorithm>
#include <cstddef>

#include "sim/core/reduction.h"
#include "sim/world/step_context.h"
#include "sim/world/world.h"

namespace sim {

inline void recordDensityCompression(const World& world, DeterministicReducer& reducer,
                                     SolverStats& stats) {
  const auto& p = world.particles;
  const std::size_t n = p.size();
  stats.densityIterations = 0;
  stats.averageCompression = reducer.sum(n, [&](std::size_t i) {
    return std::max(p.density[i] / world.restDensityOf(static_cast<Index>(i)) - 1.0, Real(0));
  }) / n;
  stats.maxCompression = DeterministicReducer::max(n, [&](std::size_t i) {
    return p.density[i] / world.restDensityOf(static_cast<Index>(i)) - 1.0;
  });
}

}  // namespace sim
