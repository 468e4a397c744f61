// The sums over a particle's neighbours that the density forms share: the mass-weighted density
// and the number density (sim/fluid/density.h, without cached kernel values) and VSLSPH's density
// with per-particle supports (sim/fluid/vslsph_li2023.cpp). One loop, so that the three add their
// terms in the same order and a change to it reaches all of them.
#pragma once

#include "sim/world/world.h"

namespace sim {

// sum_b V_b f(x_i - x_b) over particle i's wall neighbours b, in list order, added to `sum`.
template <class T, class F>
T wallVolumeSum(const World& world, Index i, T sum, F f) {
  const auto& walls = world.walls;
  const NeighborList& nw = world.wallNeighbors();
  const Vec3& xi = world.particles.x[i];
  for (const Index* b = nw.begin(i); b != nw.end(i); ++b)
    sum += walls.volume[*b] * f(xi - walls.x[*b]);
  return sum;
}

// For every dynamic particle i:
//   fluid_i = self(i) + sum_j pair(i, j, x_i - x_j),   wall_i = sum_b V_b wallPair(i, x_i - x_b),
// then sink(i, fluid_i, wall_i). The neighbours are taken in list order.
template <class Self, class Pair, class WallPair, class Sink>
void neighborSums(const World& world, Self self, Pair pair, WallPair wallPair, Sink sink) {
  const auto& x = world.particles.x;
  const NeighborList& nf = world.fluidNeighbors();
  const Index n = static_cast<Index>(x.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Real fluid = self(i);
    for (const Index* j = nf.begin(i); j != nf.end(i); ++j) fluid += pair(i, *j, x[i] - x[*j]);
    const Real wall =
        wallVolumeSum(world, i, Real(0), [&](const Vec3& xib) { return wallPair(i, xib); });
    sink(i, fluid, wall);
  }
}

}  // namespace sim
