// Wendland C2 kernel in 3D (Wendland 1995; Dehnen & Aly 2012 for its use in SPH), support radius h:
// W(q) = 21/(2 pi h^3) (1-q)^4 (1+4q), q = r/h. Its positive Fourier transform avoids the pairing
// instability of the cubic spline at large neighbour counts.
#pragma once

#include <numbers>

#include "sim/core/types.h"

namespace sim {

struct WendlandC2 {
  explicit WendlandC2(Real supportRadius)
      : h(supportRadius),
        invH(1.0 / supportRadius),
        k(21.0 / (2.0 * std::numbers::pi * h * h * h)) {}

  Real W(Real r) const {
    const Real q = r * invH;
    if (q >= 1.0) return 0.0;
    const Real s = 1.0 - q;
    return k * s * s * s * s * (1.0 + 4.0 * q);
  }
  // dW/dr = -20 k q (1-q)^3 / h
  Real dWdr(Real r) const {
    const Real q = r * invH;
    if (q >= 1.0) return 0.0;
    const Real s = 1.0 - q;
    return -20.0 * k * q * s * s * s * invH;
  }
  // W(r) and dW/dr(r) from one q, with the same expressions as W and dWdr.
  void evaluate(Real r, Real& w, Real& dwdr) const {
    const Real q = r * invH;
    if (q >= 1.0) {
      w = 0.0, dwdr = 0.0;
      return;
    }
    const Real s = 1.0 - q;
    w = k * s * s * s * s * (1.0 + 4.0 * q);
    dwdr = -20.0 * k * q * s * s * s * invH;
  }

  Real h, invH, k;
};

}  // namespace sim
