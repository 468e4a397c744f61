// The sums over a particle's neighbours that the density forms share: the mass-weighted density
// and the number density (sim/fluid/density.h, without cached kernel values) and VSLSPH's density
// with per-particle supports (sim/fluid/vslsph_li2023.cpp). One loop, so that the three add their
// terms in the same order and a change to it reaches all of them.
#pragma once

#include <type_traits>

#include "sim/world/world.h"

namespace sim {

// sum_b V_b f(x_i - x_b) over particle i's wall neighbours b, in list order, added to `sum`.
// f(x_i - x_b) or f(x_i - x_b, k), k the pair's slot in the wall list (for its cached kernel).
template <class T, class F>
T wallVolumeSum(const World& world, Index i, T sum, F f) {
  const auto& walls = world.walls;
  const NeighborList& nw = world.wallNeighbors();
  const Vec3& xi = world.particles.x[i];
  for (Index k = nw.offsets[i]; k < nw.offsets[i + 1]; ++k) {
    const Index b = nw.indices[k];
    if constexpr (std::is_invocable_v<F&, const Vec3&, Index>)
      sum += walls.volume[b] * f(xi - walls.x[b], k);
    else
      sum += walls.volume[b] * f(xi - walls.x[b]);
  }
  return sum;
}

// For every dynamic particle i:
//   fluid_i = self(i) + sum_j pair(i, j, x_i - x_j),   wall_i = sum_b V_b wallPair(i, x_i - x_b),
// then sink(i, fluid_i, wall_i). The neighbours are taken in list order. pair and wallPair may
// take the pair's list slot k as a last argument (for the cached kernel values).
template <class Self, class Pair, class WallPair, class Sink>
void neighborSums(const World& world, Self self, Pair pair, WallPair wallPair, Sink sink) {
  const auto& x = world.particles.x;
  const NeighborList& nf = world.fluidNeighbors();
  const Index n = static_cast<Index>(x.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Real fluid = self(i);
    for (Index k = nf.offsets[i]; k < nf.offsets[i + 1]; ++k) {
      const Index j = nf.indices[k];
      if constexpr (std::is_invocable_v<Pair&, Index, Index, const Vec3&, Index>)
        fluid += pair(i, j, x[i] - x[j], k);
      else
        fluid += pair(i, j, x[i] - x[j]);
    }
    Real wall;
    if constexpr (std::is_invocable_v<WallPair&, Index, const Vec3&, Index>)
      wall = wallVolumeSum(world, i, Real(0),
                           [&](const Vec3& xib, Index k) { return wallPair(i, xib, k); });
    else
      wall = wallVolumeSum(world, i, Real(0), [&](const Vec3& xib) { return wallPair(i, xib); });
    sink(i, fluid, wall);
  }
}

}  // namespace sim
