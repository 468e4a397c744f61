// Internal to meshing/: a dense uniform grid of point ids for fixed-radius neighbour loops. The
// cell is at least the search radius, so a query visits the 27 surrounding cells; points are
// chained per cell (head + next arrays), so inserting while querying costs no allocation per cell.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "meshing/triangle_mesh.h"

namespace meshing::detail {

class SpatialHash {
 public:
  // All points later inserted must lie in [lo, hi]. The cell grows beyond `radius` if needed to
  // keep the grid under ~8 million cells (the query stays correct, only slower).
  SpatialHash(const Vec3& lo, const Vec3& hi, double radius) : lo_(lo) {
    const double extent = (hi - lo).maxCoeff();
    cell_ = std::max(radius, extent / 200.0);
    if (!(cell_ > 0)) cell_ = 1;
    for (int a = 0; a < 3; ++a)
      n_[a] = static_cast<std::int64_t>(std::floor((hi[a] - lo[a]) / cell_)) + 1;
    head_.assign(static_cast<size_t>(n_[0] * n_[1] * n_[2]), -1);
  }

  // ids must be 0, 1, 2, ... in insertion order or any distinct values below the next_ size.
  void insert(int id, const Vec3& p) {
    if (static_cast<size_t>(id) >= next_.size()) next_.resize(static_cast<size_t>(id) + 1, -1);
    int& h = head_[flat(cellOf(p))];
    next_[static_cast<size_t>(id)] = h;
    h = id;
  }

  // Calls visit(id) for every stored id in the 27 cells around p (a superset of those within
  // the radius of p).
  template <class Visit>
  void forEachNear(const Vec3& p, Visit&& visit) const {
    const std::array<std::int64_t, 3> c = cellOf(p);
    for (std::int64_t z = std::max<std::int64_t>(c[2] - 1, 0); z <= std::min(c[2] + 1, n_[2] - 1);
         ++z)
      for (std::int64_t y = std::max<std::int64_t>(c[1] - 1, 0); y <= std::min(c[1] + 1, n_[1] - 1);
           ++y)
        for (std::int64_t x = std::max<std::int64_t>(c[0] - 1, 0);
             x <= std::min(c[0] + 1, n_[0] - 1); ++x)
          for (int id = head_[flat({x, y, z})]; id >= 0; id = next_[static_cast<size_t>(id)])
            visit(id);
  }

 private:
  std::array<std::int64_t, 3> cellOf(const Vec3& p) const {
    std::array<std::int64_t, 3> c{};
    for (int a = 0; a < 3; ++a)
      c[static_cast<size_t>(a)] =
          std::clamp(static_cast<std::int64_t>(std::floor((p[a] - lo_[a]) / cell_)),
                     std::int64_t{0}, n_[a] - 1);
    return c;
  }
  size_t flat(const std::array<std::int64_t, 3>& c) const {
    return static_cast<size_t>(c[0] + n_[0] * (c[1] + n_[1] * c[2]));
  }
  Vec3 lo_;
  double cell_ = 1;
  std::int64_t n_[3] = {1, 1, 1};
  std::vector<int> head_;
  std::vector<int> next_;
};

}  // namespace meshing::detail
