// A uniform hash grid over a fixed point set for "nearest point within r" queries, used when the
// scenario places walls and tissue next to each other (tissue_particles.cpp): the brute-force
// pair loops cost N x M distance checks, ~1e8 at the draft preset and 64x that at d/2.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include "sim/core/types.h"

namespace protocols {

class PointGrid {
 public:
  // `cell` [m] should be about the largest query radius (each query visits 27 cells or more).
  PointGrid(const std::vector<sim::Vec3>& points, double cell) : points_(points), cell_(cell) {
    for (std::size_t k = 0; k < points_.size(); ++k)
      cells_[key(coordinates(points_[k]))].push_back(k);
  }

  // Index of the point nearest to x within `radius` [m], or -1 when there is none.
  long nearest(const sim::Vec3& x, double radius) const {
    const auto c = coordinates(x);
    const auto reach = static_cast<std::int64_t>(std::ceil(radius / cell_));
    double best = radius * radius;
    long found = -1;
    for (std::int64_t i = -reach; i <= reach; ++i)
      for (std::int64_t j = -reach; j <= reach; ++j)
        for (std::int64_t k = -reach; k <= reach; ++k) {
          const auto it = cells_.find(key({c[0] + i, c[1] + j, c[2] + k}));
          if (it == cells_.end()) continue;
          for (const std::size_t p : it->second) {
            const double d2 = (points_[p] - x).squaredNorm();
            if (d2 <= best) best = d2, found = static_cast<long>(p);
          }
        }
    return found;
  }
  bool anyWithin(const sim::Vec3& x, double radius) const { return nearest(x, radius) >= 0; }
  // Indices of every point within `radius` of x (any order).
  std::vector<std::size_t> within(const sim::Vec3& x, double radius) const {
    std::vector<std::size_t> out;
    const auto c = coordinates(x);
    const auto reach = static_cast<std::int64_t>(std::ceil(radius / cell_));
    for (std::int64_t i = -reach; i <= reach; ++i)
      for (std::int64_t j = -reach; j <= reach; ++j)
        for (std::int64_t k = -reach; k <= reach; ++k) {
          const auto it = cells_.find(key({c[0] + i, c[1] + j, c[2] + k}));
          if (it == cells_.end()) continue;
          for (const std::size_t p : it->second)
            if ((points_[p] - x).squaredNorm() <= radius * radius) out.push_back(p);
        }
    return out;
  }
  const sim::Vec3& point(std::size_t k) const { return points_[k]; }

 private:
  struct Coordinates {
    std::int64_t v[3];
    std::int64_t operator[](int a) const { return v[a]; }
  };
  Coordinates coordinates(const sim::Vec3& x) const {
    return {{static_cast<std::int64_t>(std::floor(x.x() / cell_)),
             static_cast<std::int64_t>(std::floor(x.y() / cell_)),
             static_cast<std::int64_t>(std::floor(x.z() / cell_))}};
  }
  static std::uint64_t key(const Coordinates& c) {
    // 21 bits per axis: cells of >= 1e-5 m cover +-10 m, far beyond any eye scene.
    const auto part = [](std::int64_t v) {
      return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1FFFFFu;
    };
    return part(c[0]) | (part(c[1]) << 21) | (part(c[2]) << 42);
  }

  std::vector<sim::Vec3> points_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

}  // namespace protocols
