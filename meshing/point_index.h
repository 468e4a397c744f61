// A uniform hash grid over a point set for fixed-radius queries: the nearest point, any point or
// every point within a radius, or every stored point in the cells around a position. The one
// point index of meshing/ and the layers above it (sim/ keeps its own neighbour search, as it may
// not include meshing/).
//
// Cells are cubes of edge `cell` at floor(x / cell), stored sparsely (only occupied cells cost
// memory), so any extent works and points may lie anywhere. A query visits the cells within
// ceil(radius / cell) of the query's cell, x outermost and z innermost, and the points of a cell
// in insertion order: neighbour sums over the visits come out the same on every run and thread
// count. The cell should be about the largest query radius (a query visits 27 cells or more).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "meshing/triangle_mesh.h"

namespace meshing {

class PointIndex {
 public:
  // An empty index; fill it with insert().
  explicit PointIndex(double cell) : cell_(cell) {}
  // Point k of `points` gets index k.
  PointIndex(std::vector<Vec3> points, double cell);

  // Adds p with the next index (0, 1, 2, ...) and returns that index.
  std::size_t insert(const Vec3& p);
  std::size_t size() const { return points_.size(); }
  const Vec3& point(std::size_t k) const { return points_[k]; }

  // Calls visit(k) for every stored point k in the cells within reach of x's cell: a superset of
  // the points within `radius` of x (the caller tests the distance).
  template <class Visit>
  void forEachNear(const Vec3& x, double radius, Visit&& visit) const {
    forEachCell(x, radius, [&](const std::vector<std::size_t>& ids) {
      for (const std::size_t k : ids) visit(k);
      return true;
    });
  }
  // Index of the point nearest to x within `radius` (distance <= radius), or -1 when there is
  // none. Of equally near points, the one visited last wins (see the visiting order above).
  long nearest(const Vec3& x, double radius) const;
  bool anyWithin(const Vec3& x, double radius) const;
  // Indices of every point within `radius` of x, in visiting order.
  std::vector<std::size_t> within(const Vec3& x, double radius) const;

 private:
  struct Cell {
    std::int64_t x, y, z;
    bool operator==(const Cell&) const = default;
  };
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      return static_cast<std::size_t>((static_cast<std::uint64_t>(c.x) * 73856093u) ^
                                      (static_cast<std::uint64_t>(c.y) * 19349663u) ^
                                      (static_cast<std::uint64_t>(c.z) * 83492791u));
    }
  };

  Cell cellOf(const Vec3& x) const {
    return {static_cast<std::int64_t>(std::floor(x.x() / cell_)),
            static_cast<std::int64_t>(std::floor(x.y() / cell_)),
            static_cast<std::int64_t>(std::floor(x.z() / cell_))};
  }
  // Calls f(ids of one occupied cell) in visiting order until f returns false; returns false
  // when stopped early.
  template <class F>
  bool forEachCell(const Vec3& x, double radius, F&& f) const {
    if (cells_.empty()) return true;
    const Cell c = cellOf(x);
    const auto reach = static_cast<std::int64_t>(std::ceil(radius / cell_));
    for (std::int64_t i = -reach; i <= reach; ++i)
      for (std::int64_t j = -reach; j <= reach; ++j)
        for (std::int64_t k = -reach; k <= reach; ++k) {
          const auto it = cells_.find({c.x + i, c.y + j, c.z + k});
          if (it != cells_.end() && !f(it->second)) return false;
        }
    return true;
  }

  double cell_;  // [unit]
  std::vector<Vec3> points_;
  std::unordered_map<Cell, std::vector<std::size_t>, CellHash> cells_;
};

}  // namespace meshing
