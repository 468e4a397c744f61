// SPH density summation with Akinci et al. 2012 wall contributions:
//   rho_i = m_i W_0 + sum_j m_j W_ij + sum_b rho0_i V_b W_ib        (Akinci 2012, eqs. 4-6)
// The wall term uses the fluid particle's own rest density, so a wall reads as "more of the same
// fluid" to every phase. This is the ordinary mass-weighted density of multiphase DFSPH/WCSPH.
#pragma once

#include "sim/world/world.h"

namespace sim {

void computeDensities(World& world, std::vector<Real>& density);

// Number of fluid plus wall neighbours of particle i (used to recognise free-surface particles).
inline Index neighborCount(const World& world, Index i) {
  return world.fluidNeighbors().count(i) + world.wallNeighbors().count(i);
}

}  // namespace sim
