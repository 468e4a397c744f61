// Deterministic parallel reductions: the sum is formed over fixed blocks of indices, each block
// summed in index order, then the block sums in block order. The result depends neither on the
// thread count nor on scheduling (docs/developer-guide.md principle 7), and the buffer is reused
// (no allocation in the time-step loop once warmed up).
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "sim/core/types.h"

namespace sim {

class DeterministicReducer {
 public:
  static constexpr std::size_t kBlock = 2048;

  template <class F>
  Real sum(std::size_t n, F&& valueOf) {
    const std::size_t blocks = (n + kBlock - 1) / kBlock;
    partial_.resize(blocks);
#pragma omp parallel for schedule(static)
    for (std::size_t b = 0; b < blocks; ++b) {
      Real s = 0;
      const std::size_t end = std::min(n, (b + 1) * kBlock);
      for (std::size_t i = b * kBlock; i < end; ++i) s += valueOf(i);
      partial_[b] = s;
    }
    Real total = 0;
    for (Real s : partial_) total += s;
    return total;
  }

  template <class F>
  Vec3 sumVec(std::size_t n, F&& valueOf) {
    const std::size_t blocks = (n + kBlock - 1) / kBlock;
    partialVec_.resize(blocks);
#pragma omp parallel for schedule(static)
    for (std::size_t b = 0; b < blocks; ++b) {
      Vec3 s = Vec3::Zero();
      const std::size_t end = std::min(n, (b + 1) * kBlock);
      for (std::size_t i = b * kBlock; i < end; ++i) s += valueOf(i);
      partialVec_[b] = s;
    }
    Vec3 total = Vec3::Zero();
    for (const Vec3& s : partialVec_) total += s;
    return total;
  }

  // Maximum is order-independent, so a plain OpenMP reduction is deterministic.
  template <class F>
  static Real max(std::size_t n, F&& valueOf) {
    Real m = -std::numeric_limits<Real>::infinity();
#pragma omp parallel for schedule(static) reduction(max : m)
    for (std::size_t i = 0; i < n; ++i) m = std::max(m, valueOf(i));
    return m;
  }

 private:
  std::vector<Real> partial_;
  std::vector<Vec3> partialVec_;
};

}  // namespace sim
