// SPH density summation with Akinci et al. 2012 wall contributions:
//   rho_i = m_i W_0 + sum_j m_j W_ij + sum_b rho0_i V_b W_ib        (Akinci 2012, eqs. 4-6)
// The wall term uses the fluid particle's own rest density, so a wall reads as "more of the same
// fluid" to every phase. This is the ordinary mass-weighted density of multiphase DFSPH/WCSPH.
#pragma once

#include "sim/fluid/neighbor_sums.h"
#include "sim/world/world.h"

namespace sim {

void computeDensities(World& world, std::vector<Real>& density);

// The kernel sums both density forms are made of: for every dynamic particle i,
//   fluid_i = weight(i) W_0 + sum_j weight(j) W_ij,   wall_i = sum_b V_b W_ib,
// and out[i] = combine(i, fluid_i, wall_i). Mass-weighted density (weight = m) and number
// density (weight = 1, Wang et al. 2023 eq. 6) differ only in weight and combine.
template <class Weight, class Combine>
void kernelSums(const World& world, std::vector<Real>& out, Weight weight, Combine combine) {
  const auto& walls = world.walls;
  const NeighborList& nf = world.fluidNeighbors();
  const NeighborList& nw = world.wallNeighbors();
  const Kernel& kernel = world.kernel;
  const Real w0 = kernel.W0();
  const Index n = static_cast<Index>(world.particles.size());
  out.resize(n);
  // The neighbour pass caches W per pair with the same arithmetic as kernel.W(x_i - x_j), in single
  // precision; without a cache (lists built without a kernel) evaluate W and round it the same
  // way (sim/neighbors/pair_precision.h), so the sums are bit-identical.
  const std::vector<PairValue>& wf = world.fluidKernelValues();
  const std::vector<PairValue>& ww = world.wallKernelValues();
  if (wf.size() == nf.indices.size() && ww.size() == nw.indices.size() &&
      (!wf.empty() || nf.indices.empty())) {
    const PairValue* wfd = wf.data();
    const PairValue* wwd = ww.data();
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
      Real fluid = weight(i) * w0;
      for (Index k = nf.offsets[i]; k < nf.offsets[i + 1]; ++k)
        fluid += weight(nf.indices[k]) * Real(wfd[k]);
      Real wall = 0;
      for (Index k = nw.offsets[i]; k < nw.offsets[i + 1]; ++k)
        wall += walls.volume[nw.indices[k]] * Real(wwd[k]);
      out[i] = combine(i, fluid, wall);
    }
    return;
  }
  neighborSums(
      world, [&](Index i) { return weight(i) * w0; },
      [&](Index, Index j, const Vec3& xij) { return weight(j) * cachedPrecision(kernel.W(xij)); },
      [&](Index, const Vec3& xib) { return cachedPrecision(kernel.W(xib)); },
      [&](Index i, Real fluid, Real wall) { out[i] = combine(i, fluid, wall); });
}

// Number of fluid plus wall neighbours of particle i (used to recognise free-surface particles).
inline Index neighborCount(const World& world, Index i) {
  return world.fluidNeighbors().count(i) + world.wallNeighbors().count(i);
}

}  // namespace sim
