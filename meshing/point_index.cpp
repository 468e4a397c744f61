#include "meshing/point_index.h"

#include <utility>

namespace meshing {

PointIndex::PointIndex(std::vector<Vec3> points, double cell)
    : cell_(cell), points_(std::move(points)) {
  for (std::size_t k = 0; k < points_.size(); ++k) cells_[cellOf(points_[k])].push_back(k);
}

std::size_t PointIndex::insert(const Vec3& p) {
  const std::size_t k = points_.size();
  points_.push_back(p);
  cells_[cellOf(p)].push_back(k);
  return k;
}

long PointIndex::nearest(const Vec3& x, double radius) const {
  double best = radius * radius;
  long found = -1;
  forEachCell(x, radius, [&](const std::vector<std::size_t>& ids) {
    for (const std::size_t k : ids) {
      const double d2 = (points_[k] - x).squaredNorm();
      if (d2 <= best) best = d2, found = static_cast<long>(k);
    }
    return true;
  });
  return found;
}

bool PointIndex::anyWithin(const Vec3& x, double radius) const {
  const double r2 = radius * radius;
  return !forEachCell(x, radius, [&](const std::vector<std::size_t>& ids) {
    for (const std::size_t k : ids)
      if ((points_[k] - x).squaredNorm() <= r2) return false;
    return true;
  });
}

std::vector<std::size_t> PointIndex::within(const Vec3& x, double radius) const {
  std::vector<std::size_t> out;
  const double r2 = radius * radius;
  forEachCell(x, radius, [&](const std::vector<std::size_t>& ids) {
    for (const std::size_t k : ids)
      if ((points_[k] - x).squaredNorm() <= r2) out.push_back(k);
    return true;
  });
  return out;
}

}  // namespace meshing
