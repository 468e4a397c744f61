// Points spread evenly over the unit sphere (Fibonacci lattice), for tests that read a spherical
// cavity's wall: multiplied by R they are wall points, and they are their own outward normals.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/core/types.h"

namespace testref {

inline std::vector<sim::Vec3> sphereNormals(int count) {
  std::vector<sim::Vec3> n;
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count, r = std::sqrt(1.0 - z * z);
    const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
    n.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return n;
}

}  // namespace testref
