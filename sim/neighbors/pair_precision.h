// The precision of the per-pair kernel cache: each pair's kernel gradient and value are stored in
// single precision (12 + 4 bytes instead of 24 + 8) and widened to Real where a stage reads them.
// The cache is most of a particle's memory: 1.21 KiB per particle in the 298k dam break instead
// of 1.73 with doubles, and DFSPH, which reads every pair's gradient in each iteration, steps in
// 0.92-0.94x the time (docs/benchmarks.md, "Memory"). Arithmetic stays in double precision: only
// the stored values are rounded (a relative 6e-8, far below any solver tolerance), and rounding
// keeps gradW(x_j - x_i) = -gradW(x_i - x_j) exact, so pair forces still cancel.
//
// A stage that evaluates the kernel itself instead of reading the cache (the pair-cache-free mode,
// WorldParameters::cachePairKernels = false) rounds the same way through cachedPrecision, so a run
// gives the same state bit for bit with or without the cache; pairValue and pairGradient make that
// choice for one pair.
#pragma once

#include <Eigen/Core>

#include "sim/core/types.h"

namespace sim {

using PairGradient = Eigen::Vector3f;  // [1/m^4] as stored in the pair cache
using PairValue = float;               // [1/m^3] as stored in the pair cache

// A kernel value as the pair cache holds it. The float passes through memory the compiler cannot
// see into: GCC 12's SLP vectorizer drops a double -> float -> double round trip at -O2 (a
// miscompilation; the cached path stores floats and is not affected), and the no-cache mode would
// then differ from the cached one in the last bits.
inline Real cachedPrecision(Real w) {
  PairValue rounded = static_cast<PairValue>(w);
  asm("" : "+m"(rounded));
  return static_cast<Real>(rounded);
}
// A kernel gradient as the pair cache holds it.
inline Vec3 cachedPrecision(const Vec3& g) {
  return {cachedPrecision(g.x()), cachedPrecision(g.y()), cachedPrecision(g.z())};
}

// The kernel value of the pair in list slot k: the cached one when `cache` is not null, else
// evaluate() rounded as the cache rounds it (evaluated only then).
template <class Evaluate>
Real pairValue(const PairValue* cache, Index k, Evaluate evaluate) {
  return cache != nullptr ? Real(cache[k]) : cachedPrecision(Real(evaluate()));
}
// Same for the pair's kernel gradient.
template <class Evaluate>
Vec3 pairGradient(const PairGradient* cache, Index k, Evaluate evaluate) {
  return cache != nullptr ? Vec3(cache[k].cast<Real>()) : cachedPrecision(Vec3(evaluate()));
}

}  // namespace sim
