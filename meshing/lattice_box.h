// Internal to meshing/: the points origin + d*(i,j,k) inside an axis-aligned box, enumerated in a
// fixed order (x fastest) so that results do not depend on threads, and scanned column by column
// (lines parallel to z) for fast inside tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "meshing/mesh_error.h"
#include "meshing/triangle_mesh.h"

namespace meshing::detail {

class LatticeBox {
 public:
  LatticeBox(const Vec3& lo, const Vec3& hi, double spacing, const Vec3& origin,
             const std::string& who)
      : d_(spacing), origin_(origin) {
    double total = 1;
    for (int a = 0; a < 3; ++a) {
      first_[a] = static_cast<long long>(std::ceil((lo[a] - origin[a]) / d_));
      const long long last = static_cast<long long>(std::floor((hi[a] - origin[a]) / d_));
      n_[a] = std::max(0LL, last - first_[a] + 1);
      total *= static_cast<double>(n_[a]);
    }
    if (total > 2e8)
      throw MeshError(who,
                      "spacing too small for the mesh (" +
                          std::to_string(static_cast<long long>(total)) +
                          " lattice points in the bounding box)",
                      "increase the spacing or check the units");
  }
  size_t count() const { return static_cast<size_t>(n_[0] * n_[1] * n_[2]); }
  size_t columns() const { return static_cast<size_t>(n_[0] * n_[1]); }  // z-lines
  size_t columnLength() const { return static_cast<size_t>(n_[2]); }
  // Lattice index of point k of column c (so point(index(c, k)) walks up the column).
  size_t index(size_t c, size_t k) const { return c + k * columns(); }
  Vec3 point(size_t k) const {
    const long long kk = static_cast<long long>(k);
    const long long i = kk % n_[0], j = (kk / n_[0]) % n_[1], l = kk / (n_[0] * n_[1]);
    return origin_ + d_ * Vec3(static_cast<double>(first_[0] + i),
                               static_cast<double>(first_[1] + j),
                               static_cast<double>(first_[2] + l));
  }

 private:
  double d_;
  Vec3 origin_;
  long long first_[3] = {0, 0, 0};
  long long n_[3] = {0, 0, 0};
};

// Inside flags of one lattice column, from the parity of the column line's crossings with the
// surface (one AABB query per column instead of one ray per point, Side_of_triangle_mesh-style);
// columns whose line grazes an edge or vertex fall back to the per-point test.
template <class Query>
void insideColumn(const LatticeBox& box, const Query& query, size_t c,
                  std::vector<double>& crossings, std::vector<char>& inside) {
  const size_t n = box.columnLength();
  inside.assign(n, 0);
  if (n == 0) return;
  if (!query.lineCrossings(box.point(box.index(c, 0)), 2, crossings)) {
    for (size_t k = 0; k < n; ++k) inside[k] = query.isInside(box.point(box.index(c, k)));
    return;
  }
  size_t interval = 0;  // crossings[2m], crossings[2m+1] bound an inside interval
  for (size_t k = 0; k < n; ++k) {
    const double z = box.point(box.index(c, k)).z();
    while (interval + 1 < crossings.size() && crossings[interval + 1] < z) interval += 2;
    inside[k] =
        interval + 1 < crossings.size() && crossings[interval] <= z && z <= crossings[interval + 1];
  }
}

// Calls visit(c, inside) for every column c of `box`, with its inside flags, on all OpenMP threads
// (dynamic schedule: columns differ in cost). `visit` must only write to per-column storage.
template <class Query, class Visit>
void forEachColumn(const LatticeBox& box, const Query& query, Visit&& visit) {
#pragma omp parallel
  {
    std::vector<double> crossings;
    std::vector<char> inside;
#pragma omp for schedule(dynamic, 16)
    for (long long cl = 0; cl < static_cast<long long>(box.columns()); ++cl) {
      const size_t c = static_cast<size_t>(cl);
      insideColumn(box, query, c, crossings, inside);
      visit(c, inside);
    }
  }
}

}  // namespace meshing::detail
