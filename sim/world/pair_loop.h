// One loop over a particle's cached neighbour pairs: the neighbour's index, the pair's kernel
// gradient gradW(x_i - x_j) and (when the lambda asks for it) the pair's slot in the list, in list
// order. Every solver and effect that sums over pairs with the cached gradients goes through it, so
// the cache is read in one place. The neighbour search stores each pair's scale (dW/dr)/r, 8 bytes
// instead of the 24 of the vector (sim/neighbors/neighbor_search.h); the gradient is formed here as
// (x_i - x_j) * scale, the same product Kernel::gradW computes, from the positions the lists were
// built from (they do not move before the step's end). The lambda inlines: the loop is the
// hand-written one (docs/benchmarks.md, Engine).
//
//   const PairLoop fluid = fluidPairs(world), walls = wallPairs(world);
//   fluid.forEach(i, [&](Index j, const Vec3& gradW) { ... });
//   walls.forEach(i, [&](Index b, const Vec3& gradW, Index slot) { ... });
#pragma once

#include <type_traits>

#include "sim/world/world.h"

namespace sim {

class PairLoop {
 public:
  // `queries`: the positions of the list's query points (the dynamic particles); `points`: those
  // of their neighbours (the dynamic particles again, or the walls).
  PairLoop(const NeighborList& list, const std::vector<Real>& gradientScales,
           const std::vector<Vec3>& queries, const std::vector<Vec3>& points)
      : offsets_(list.offsets.data()),
        indices_(list.indices.data()),
        scales_(gradientScales.data()),
        queries_(queries.data()),
        points_(points.data()) {}

  // f(j, gradW) or f(j, gradW, slot) for each neighbour j of i, in list order.
  template <class F>
  void forEach(Index i, F&& f) const {
    const Vec3 xi = queries_[i];
    for (Index k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      const Index j = indices_[k];
      const Vec3 gradW = (xi - points_[j]).eval() * scales_[k];
      if constexpr (std::is_invocable_v<F&, Index, const Vec3&, Index>)
        f(j, gradW, k);
      else
        f(j, gradW);
    }
  }
  // gradW(x_i - x_j) of the pair (i, j) in list slot k (for loops that visit the pairs in another
  // order, e.g. a wall particle's fluid neighbours).
  Vec3 gradient(Index k, Index i, Index j) const {
    return (queries_[i] - points_[j]).eval() * scales_[k];
  }
  Index count(Index i) const { return offsets_[i + 1] - offsets_[i]; }

 private:
  const Index* offsets_;
  const Index* indices_;
  const Real* scales_;
  const Vec3* queries_;
  const Vec3* points_;
};

// Dynamic particle i's dynamic neighbours j, with gradW(x_i - x_j).
inline PairLoop fluidPairs(const World& world) {
  return {world.fluidNeighbors(), world.fluidGradientScales(), world.particles.x,
          world.particles.x};
}
// Dynamic particle i's wall neighbours b, with gradW(x_i - x_b).
inline PairLoop wallPairs(const World& world) {
  return {world.wallNeighbors(), world.wallGradientScales(), world.particles.x, world.walls.x};
}

}  // namespace sim
