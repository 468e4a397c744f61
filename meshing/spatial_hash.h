// Internal to meshing/: a uniform-grid bucket index of points for fixed-radius neighbour loops
// (cell size = the search radius, so a query visits the 27 surrounding cells).
#pragma once

#include <cmath>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "meshing/triangle_mesh.h"

namespace meshing::detail {

class SpatialHash {
 public:
  explicit SpatialHash(double cellSize) : cell_(cellSize) {}

  void insert(int id, const Vec3& p) { cells_[key(cellOf(p))].push_back(id); }

  // Calls visit(id) for every stored id in the 27 cells around p (a superset of those within
  // one cell size of p).
  template <class Visit>
  void forEachNear(const Vec3& p, Visit&& visit) const {
    const std::array<std::int64_t, 3> c = cellOf(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == cells_.end()) continue;
          for (int id : it->second) visit(id);
        }
  }

 private:
  std::array<std::int64_t, 3> cellOf(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / cell_)),
            static_cast<std::int64_t>(std::floor(p.y() / cell_)),
            static_cast<std::int64_t>(std::floor(p.z() / cell_))};
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    // 21 bits per axis: unique for |cell index| < 2^20, far beyond any eye at any spacing.
    const auto m = [](std::int64_t v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1FFFFFu; };
    return (m(c[0]) << 42) | (m(c[1]) << 21) | m(c[2]);
  }
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

}  // namespace meshing::detail
