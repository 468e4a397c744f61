// The smoothing kernel chosen for a scene. Selected by name; dispatch is a switch on a member that
// never changes during a run, so the branch predicts perfectly in the pair loops.
#pragma once

#include <string>
#include <string_view>

#include "sim/core/error.h"
#include "sim/core/types.h"
#include "sim/kernels/cubic_spline.h"
#include "sim/kernels/wendland_c2.h"

namespace sim {

enum class KernelKind { kCubicSpline, kWendlandC2 };

inline KernelKind kernelKindFromName(std::string_view name) {
  if (name == "cubic_spline") return KernelKind::kCubicSpline;
  if (name == "wendland_c2") return KernelKind::kWendlandC2;
  throw SimError("unknown kernel '" + std::string(name) + "' (known: cubic_spline, wendland_c2)");
}
inline const char* kernelName(KernelKind kind) {
  return kind == KernelKind::kCubicSpline ? "cubic_spline" : "wendland_c2";
}

class Kernel {
 public:
  Kernel(KernelKind kind, Real supportRadius)
      : kind_(kind), cubic_(supportRadius), wendland_(supportRadius) {
    require(supportRadius > 0.0, "kernel support radius must be > 0 m");
  }

  KernelKind kind() const { return kind_; }
  Real supportRadius() const { return cubic_.h; }

  Real W(Real r) const { return kind_ == KernelKind::kCubicSpline ? cubic_.W(r) : wendland_.W(r); }
  Real W(const Vec3& xij) const { return W(xij.norm()); }
  Real W0() const { return W(0.0); }

  // Gradient with respect to x_i of W(|x_i - x_j|), given xij = x_i - x_j.
  Vec3 gradW(const Vec3& xij) const { return gradW(xij, xij.norm()); }
  // Same, with r = |xij| already known (the neighbour pass also needs W(r)).
  Vec3 gradW(const Vec3& xij, Real r) const {
    if (r <= gradientCutoff()) return Vec3::Zero();
    const Real d = kind_ == KernelKind::kCubicSpline ? cubic_.dWdr(r) : wendland_.dWdr(r);
    return xij * (d / r);
  }
  // The two kernels themselves, for loops that hoist the choice of kernel out of the pair loop.
  const CubicSpline& cubicSpline() const { return cubic_; }
  const WendlandC2& wendlandC2() const { return wendland_; }
  // Below this distance gradW is zero (coincident points have no direction).
  Real gradientCutoff() const { return 1e-12 * cubic_.h; }

 private:
  KernelKind kind_;
  CubicSpline cubic_;
  WendlandC2 wendland_;
};

}  // namespace sim
