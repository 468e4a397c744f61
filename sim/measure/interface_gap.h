// The "gap between phases" artefact of multiphase SPH (Wang et al. 2023, section 3.3 and Fig. 1):
// mass-weighted density over-estimates the density of a light particle next to heavy ones, the
// solver pushes the phases apart, and an interface layer opens. Measured as: for every particle of
// phase A that has a phase-B particle within the support radius, the distance to the nearest
// phase-B particle, averaged, divided by the particle spacing d. A lattice interface without gap
// reads 1.0 (nearest neighbour at d); a gap shows as a value clearly above it.
#pragma once

#include <limits>

#include "sim/core/reduction.h"
#include "sim/world/world.h"

namespace sim {

struct InterfaceGap {
  Real meanNearestDistance = 0;  // [1] mean nearest A-B distance / d (0 when no interface)
  Index interfaceParticles = 0;  // phase-A particles with a phase-B neighbour
};

// Phases are material indices. Uses the current fluid neighbour lists (call after a step).
inline InterfaceGap interfaceGap(const World& world, int materialA, int materialB) {
  const auto& p = world.particles;
  const NeighborList& nf = world.fluidNeighbors();
  const Index n = static_cast<Index>(p.size());
  std::vector<Real> nearest(n, 0.0);  // [m], 0 = not at the interface
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    if (p.material[i] != materialA) continue;
    Real best = std::numeric_limits<Real>::infinity();
    for (const Index* j = nf.begin(i); j != nf.end(i); ++j)
      if (p.material[*j] == materialB) best = std::min(best, (p.x[i] - p.x[*j]).norm());
    if (best < std::numeric_limits<Real>::infinity()) nearest[i] = best;
  }
  InterfaceGap gap;
  DeterministicReducer r;
  const Real sum = r.sum(n, [&](std::size_t i) { return nearest[i]; });
  for (Index i = 0; i < n; ++i) gap.interfaceParticles += nearest[i] > 0 ? 1 : 0;
  if (gap.interfaceParticles > 0)
    gap.meanNearestDistance = sum / gap.interfaceParticles / world.particleSpacing();
  return gap;
}

}  // namespace sim
