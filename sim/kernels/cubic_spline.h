// Cubic spline kernel (Monaghan 1992) in 3D, written with the support radius h (W = 0 for r >= h),
// the convention of Bender & Koschier 2015/2017. Normalisation 8/(pi h^3).
#pragma once

#include <numbers>

#include "sim/core/types.h"

namespace sim {

struct CubicSpline {
  explicit CubicSpline(Real supportRadius)
      : h(supportRadius),
        invH(1.0 / supportRadius),
        k(8.0 / (std::numbers::pi * h * h * h)),
        l(48.0 / (std::numbers::pi * h * h * h)) {}

  Real W(Real r) const {
    const Real q = r * invH;
    if (q >= 1.0) return 0.0;
    if (q <= 0.5) return k * (6.0 * q * q * q - 6.0 * q * q + 1.0);
    const Real s = 1.0 - q;
    return k * 2.0 * s * s * s;
  }
  // dW/dr; the gradient is dWdr(r) * xij / r.
  Real dWdr(Real r) const {
    const Real q = r * invH;
    if (q >= 1.0) return 0.0;
    if (q <= 0.5) return l * q * (3.0 * q - 2.0) * invH;
    const Real s = 1.0 - q;
    return -l * s * s * invH;
  }
  // W(r) and dW/dr(r) from one q and one branch, with the same expressions as W and dWdr (the
  // neighbour search evaluates both for every pair it stores).
  void evaluate(Real r, Real& w, Real& dwdr) const {
    const Real q = r * invH;
    if (q >= 1.0) {
      w = 0.0, dwdr = 0.0;
    } else if (q <= 0.5) {
      w = k * (6.0 * q * q * q - 6.0 * q * q + 1.0);
      dwdr = l * q * (3.0 * q - 2.0) * invH;
    } else {
      const Real s = 1.0 - q;
      w = k * 2.0 * s * s * s;
      dwdr = -l * s * s * invH;
    }
  }

  Real h, invH, k, l;
};

}  // namespace sim
