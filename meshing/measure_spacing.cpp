#include "meshing/measure_spacing.h"

#include <cmath>
#include <limits>

#include "meshing/mesh_error.h"
#include "meshing/point_index.h"

namespace meshing {

SpacingStatistics measureSpacing(const std::vector<Vec3>& points, double searchRadius) {
  if (!(searchRadius > 0))
    throw MeshError("spacing statistics", "search radius must be positive", "");
  SpacingStatistics s;
  if (points.empty()) return s;
  const PointIndex index(points, searchRadius);
  std::vector<double> nearest(points.size(), std::numeric_limits<double>::infinity());
#pragma omp parallel for schedule(static)
  for (long long il = 0; il < static_cast<long long>(points.size()); ++il) {
    const size_t i = static_cast<size_t>(il);
    double best = std::numeric_limits<double>::infinity();
    index.forEachNear(points[i], searchRadius, [&](size_t j) {
      if (j != i) best = std::min(best, (points[j] - points[i]).squaredNorm());
    });
    if (best <= searchRadius * searchRadius) nearest[i] = std::sqrt(best);
  }
  s.minimum = std::numeric_limits<double>::infinity();
  double sum = 0;
  size_t found = 0;
  for (double r : nearest) {
    if (!std::isfinite(r)) {
      ++s.isolated;
      continue;
    }
    s.minimum = std::min(s.minimum, r);
    s.maximum = std::max(s.maximum, r);
    sum += r;
    ++found;
  }
  s.mean = found ? sum / static_cast<double>(found) : 0.0;
  if (!found) s.minimum = 0;
  return s;
}

}  // namespace meshing
