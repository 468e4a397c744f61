// Internal to meshing/: the points origin + d*(i,j,k) inside an axis-aligned box, enumerated in a
// fixed order (x fastest) so that results do not depend on threads.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "meshing/mesh_error.h"
#include "meshing/triangle_mesh.h"

namespace meshing::detail {

class LatticeBox {
 public:
  LatticeBox(const Vec3& lo, const Vec3& hi, double spacing, const Vec3& origin, const std::string& who)
      : d_(spacing), origin_(origin) {
    double total = 1;
    for (int a = 0; a < 3; ++a) {
      first_[a] = static_cast<long long>(std::ceil((lo[a] - origin[a]) / d_));
      const long long last = static_cast<long long>(std::floor((hi[a] - origin[a]) / d_));
      n_[a] = std::max(0LL, last - first_[a] + 1);
      total *= static_cast<double>(n_[a]);
    }
    if (total > 2e8)
      throw MeshError(who, "spacing too small for the mesh (" + std::to_string(static_cast<long long>(total)) +
                               " lattice points in the bounding box)",
                      "increase the spacing or check the units");
  }
  size_t count() const { return static_cast<size_t>(n_[0] * n_[1] * n_[2]); }
  Vec3 point(size_t k) const {
    const long long kk = static_cast<long long>(k);
    const long long i = kk % n_[0], j = (kk / n_[0]) % n_[1], l = kk / (n_[0] * n_[1]);
    return origin_ + d_ * Vec3(static_cast<double>(first_[0] + i), static_cast<double>(first_[1] + j),
                               static_cast<double>(first_[2] + l));
  }

 private:
  double d_;
  Vec3 origin_;
  long long first_[3] = {0, 0, 0};
  long long n_[3] = {0, 0, 0};
};

}  // namespace meshing::detail
