// Checked key=value options of the hand-run interface benchmarks (interface_bench.cpp,
// interface_laplace_bench.cpp): a value that is not what the key takes stops the run with a message
// naming the option and what it accepts, instead of running a scene nobody asked for (atof reads
// "abc" as 0; an unknown surface-stress name would fall back to auto).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "sim/effects/interfacial_tension_hu_adams2006.h"

namespace sim::testing {

// The number in `value`, required in [lo, hi]; throws std::invalid_argument otherwise.
inline Real benchNumber(const std::string& key, const std::string& value, Real lo, Real hi) {
  char* end = nullptr;
  const Real v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi) {
    char range[64];
    std::snprintf(range, sizeof range, "[%g, %g]", lo, hi);
    throw std::invalid_argument(key + "=" + value + ": expected a number in " + range);
  }
  return v;
}

// auto, corrected or symmetric; throws std::invalid_argument otherwise.
inline SurfaceStressForm benchSurfaceStressForm(const std::string& value) {
  if (value != "auto" && value != "corrected" && value != "symmetric")
    throw std::invalid_argument("form=" + value + ": expected auto, corrected or symmetric");
  return surfaceStressFormFromName(value);
}

}  // namespace sim::testing
