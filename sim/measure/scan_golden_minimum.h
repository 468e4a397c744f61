// The minimum of a one-dimensional cost that may have several local minima, as the contact-angle
// fits have (a cap or outline fitted to a noisy point cloud): a coarse scan finds the basin, a
// golden-section search then narrows the bracket of the best sample. Shared by the volume-
// constrained cap fit (sessile_contact_angle.h) and the Young-Laplace outline fit
// (sessile_young_laplace.h).
#pragma once

#include <algorithm>
#include <cmath>

#include "sim/core/types.h"

namespace sim {

struct ScanGoldenSearch {
  Real first = 0, last = 0, step = 1;  // samples first, first + step, ... while <= last
  Real lower = 0, upper = 0;           // the bracket (best sample +- step) is kept inside these
  int iterations = 60;                 // golden-section iterations (each shrinks by 0.618)
};

// The argument of the smallest cost found: the centre of the final bracket.
template <class Cost>
Real scanGoldenMinimum(const Cost& cost, const ScanGoldenSearch& search) {
  Real best = search.first, bestCost = cost(best);
  for (int k = 1;; ++k) {
    const Real x = search.first + k * search.step;
    if (x > search.last) break;
    const Real c = cost(x);
    if (c < bestCost) {
      bestCost = c;
      best = x;
    }
  }
  Real lo = std::max(search.lower, best - search.step);
  Real hi = std::min(search.upper, best + search.step);
  const Real g = 0.5 * (std::sqrt(5.0) - 1);
  Real a = hi - g * (hi - lo), b = lo + g * (hi - lo);
  Real ca = cost(a), cb = cost(b);
  for (int k = 0; k < search.iterations; ++k) {
    if (ca < cb) {
      hi = b;
      b = a;
      cb = ca;
      a = hi - g * (hi - lo);
      ca = cost(a);
    } else {
      lo = a;
      a = b;
      ca = cb;
      b = lo + g * (hi - lo);
      cb = cost(b);
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace sim
