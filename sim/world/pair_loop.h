// One loop over a particle's neighbour pairs: the neighbour's index, the pair's kernel gradient
// gradW(x_i - x_j) and (when the lambda asks for it) the pair's slot in the list, in list order.
// Every solver and effect that sums over pairs with kernel gradients goes through it, so the
// per-pair cache is read in one place (sim/neighbors/neighbor_search.h). The gradient is the one
// the neighbour search stored (single precision, widened here), or, when the world keeps no pair
// cache (WorldParameters::cachePairKernels = false), Kernel::gradW evaluated here and rounded as
// the cache rounds it (sim/neighbors/pair_precision.h): the same value bit for bit, so a run does
// not depend on the choice. The lambda inlines: the loop is the
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
  // Pairs (i, j) of `list`, i a point of `queryX`, j a point of `pointX`; `gradients` aligned
  // with the list, or empty to evaluate `kernel` per pair.
  PairLoop(const NeighborList& list, const std::vector<PairGradient>& gradients,
           const std::vector<Vec3>& queryX, const std::vector<Vec3>& pointX, const Kernel& kernel)
      : offsets_(list.offsets.data()),
        indices_(list.indices.data()),
        gradients_(gradients.size() == list.indices.size() && !gradients.empty() ? gradients.data()
                                                                                 : nullptr),
        queryX_(queryX.data()),
        pointX_(pointX.data()),
        kernel_(&kernel) {}

  // f(j, gradW) or f(j, gradW, slot) for each neighbour j of i, in list order.
  template <class F>
  void forEach(Index i, F&& f) const {
    if (gradients_ != nullptr) {
      for (Index k = offsets_[i]; k < offsets_[i + 1]; ++k)
        call(f, indices_[k], gradients_[k].cast<Real>(), k);
      return;
    }
    const Vec3 xi = queryX_[i];
    for (Index k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      const Index j = indices_[k];
      call(f, j, cachedPrecision(kernel_->gradW(xi - pointX_[j])), k);
    }
  }
  // gradW of the pair (i, j) in list slot k (for loops that visit the pairs in another order,
  // e.g. a wall particle's fluid neighbours).
  Vec3 gradient(Index k, Index i, Index j) const {
    return pairGradient(gradients_, k, [&] { return kernel_->gradW(queryX_[i] - pointX_[j]); });
  }

 private:
  template <class F>
  static void call(F& f, Index j, const Vec3& gradW, Index k) {
    if constexpr (std::is_invocable_v<F&, Index, const Vec3&, Index>)
      f(j, gradW, k);
    else
      f(j, gradW);
  }

  const Index* offsets_;
  const Index* indices_;
  const PairGradient* gradients_;  // null: no cache, evaluate the kernel
  const Vec3* queryX_;
  const Vec3* pointX_;
  const Kernel* kernel_;
};

// Dynamic particle i's dynamic neighbours j, with gradW(x_i - x_j).
inline PairLoop fluidPairs(const World& world) {
  return {world.fluidNeighbors(), world.fluidGradients(), world.particles.x, world.particles.x,
          world.kernel};
}
// Dynamic particle i's wall neighbours b, with gradW(x_i - x_b).
inline PairLoop wallPairs(const World& world) {
  return {world.wallNeighbors(), world.wallGradients(), world.particles.x, world.walls.x,
          world.kernel};
}

}  // namespace sim
