// One loop over a particle's cached neighbour pairs: the neighbour's index, the pair's kernel
// gradient gradW(x_i - x_j) as the neighbour search stored it, and (when the lambda asks for it)
// the pair's slot in the list, in list order. Every solver and effect that sums over pairs with
// the cached gradients goes through it, so the cache is read in one place
// (sim/neighbors/neighbor_search.h). The lambda inlines: the loop is the hand-written one
// (docs/benchmarks.md, Engine).
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
  PairLoop(const NeighborList& list, const std::vector<Vec3>& gradients)
      : offsets_(list.offsets.data()),
        indices_(list.indices.data()),
        gradients_(gradients.data()) {}

  // f(j, gradW) or f(j, gradW, slot) for each neighbour j of i, in list order.
  template <class F>
  void forEach(Index i, F&& f) const {
    for (Index k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      if constexpr (std::is_invocable_v<F&, Index, const Vec3&, Index>)
        f(indices_[k], gradients_[k], k);
      else
        f(indices_[k], gradients_[k]);
    }
  }
  // gradW of the pair in list slot k (for loops that visit the pairs in another order, e.g. a
  // wall particle's fluid neighbours).
  const Vec3& gradient(Index k) const { return gradients_[k]; }

 private:
  const Index* offsets_;
  const Index* indices_;
  const Vec3* gradients_;
};

// Dynamic particle i's dynamic neighbours j, with gradW(x_i - x_j).
inline PairLoop fluidPairs(const World& world) {
  return {world.fluidNeighbors(), world.fluidGradients()};
}
// Dynamic particle i's wall neighbours b, with gradW(x_i - x_b).
inline PairLoop wallPairs(const World& world) {
  return {world.wallNeighbors(), world.wallGradients()};
}

}  // namespace sim
