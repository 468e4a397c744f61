// The "gap between phases" artefact of multiphase SPH (Wang et al. 2023, section 3.3 and Fig. 1):
// mass-weighted density over-estimates the density of a light particle next to heavy ones, the
// solver pushes the phases apart, and an interface layer opens. Measured as: for every particle of
// phase A that has a phase-B particle within the support radius, the distance to the nearest
// phase-B particle, averaged, divided by the particle spacing d. A lattice interface without gap
// reads 1.0 (nearest neighbour at d); a gap shows as a value clearly above it.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "sim/core/reduction.h"
#include "sim/world/world.h"

namespace sim {

struct InterfaceGap {
  Real meanNearestDistance = 0;  // [1] mean nearest A-B distance / d (0 when no interface)
  Index interfaceParticles = 0;  // phase-A particles with a phase-B neighbour
  // [1] mean kernel number density sum_j W_ij (fluid and walls, walls weighted by their Akinci
  // volume over d^3) of the interface particles of both phases, over the same mean of the other
  // particles; both only over particles with at least kFullNeighbourhood fluid neighbours at a
  // non-zero kernel weight, so that free-surface particles do not enter. A gap is a layer of
  // missing particles and lowers it below 1; a gap-free interface reads 1 within ~1 % whatever the
  // disorder (the nearest- distance measure above counts the second layer too and reads ~1.3 d even
  // without a gap). 0 when there is no interface.
  Real numberDensityRatio = 0;
};

// Of 26 on a cubic lattice and ~32 in a disordered fluid for h = 2d; a free-surface particle has
// 17-20. Pairs at exactly r = h (lattice points 2d away, kept or not by round-off) have zero
// weight and are not counted.
inline constexpr int kFullNeighbourhood = 22;

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

  // Number density at the interface against the bulk (both phases).
  const NeighborList& nw = world.wallNeighbors();
  const Real d3 = std::pow(world.particleSpacing(), 3);
  std::vector<Real> delta(n, 0.0);  // [1/m^3], 0 = not counted
  std::vector<Real> atInterface(n, 0.0);
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const int mi = p.material[i];
    if (mi != materialA && mi != materialB) continue;
    const int other = mi == materialA ? materialB : materialA;
    const Real negligible = 1e-9 * world.kernel.W0();
    Real sumW = world.kernel.W0();
    int weighted = 0;
    bool interface = false;
    for (const Index* j = nf.begin(i); j != nf.end(i); ++j) {
      const Real wij = world.kernel.W(p.x[i] - p.x[*j]);
      sumW += wij;
      weighted += wij > negligible ? 1 : 0;
      interface = interface || (p.material[*j] == other && wij > negligible);
    }
    if (weighted < kFullNeighbourhood) continue;
    for (const Index* b = nw.begin(i); b != nw.end(i); ++b)
      sumW += world.walls.volume[*b] / d3 * world.kernel.W(p.x[i] - world.walls.x[*b]);
    delta[i] = sumW;
    atInterface[i] = interface ? 1.0 : 0.0;
  }
  const Real interfaceSum = r.sum(n, [&](std::size_t i) { return delta[i] * atInterface[i]; });
  const Real interfaceCount =
      r.sum(n, [&](std::size_t i) { return delta[i] > 0 ? atInterface[i] : 0.0; });
  const Real bulkSum = r.sum(n, [&](std::size_t i) { return delta[i] * (1.0 - atInterface[i]); });
  const Real bulkCount =
      r.sum(n, [&](std::size_t i) { return delta[i] > 0 ? 1.0 - atInterface[i] : 0.0; });
  if (interfaceCount > 0 && bulkCount > 0 && bulkSum > 0)
    gap.numberDensityRatio = (interfaceSum / interfaceCount) / (bulkSum / bulkCount);
  return gap;
}

}  // namespace sim
