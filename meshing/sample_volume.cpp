#include "meshing/sample_volume.h"

#include <cmath>
#include <limits>

#include "meshing/lattice_box.h"
#include "meshing/mesh_error.h"
#include "meshing/mesh_measures.h"

namespace meshing {

std::vector<Vec3> sampleVolume(const TriangleMesh& mesh, const VolumeSamplingOptions& options) {
  const MeshQuery query(mesh);
  return sampleVolume(mesh, query, options);
}

std::vector<Vec3> sampleVolume(const TriangleMesh& mesh, const MeshQuery& query,
                               const VolumeSamplingOptions& options) {
  const double d = options.spacing;  // [unit]
  if (!(d > 0) || !std::isfinite(d))
    throw MeshError("volume sampling", "spacing must be positive and finite", "give e.g. 0.4 mm");
  const double gap = options.wallGap < 0 ? 0.5 * d : options.wallGap;  // [unit]
  const MeshMeasures m = measureMesh(mesh);
  const detail::LatticeBox box(m.boundsMin, m.boundsMax, d, options.latticeOrigin, "volume sampling");
  // Per column (parallel, dynamic: columns differ in cost): inside flags from crossings, then
  // the wall distance. The distance is 1-Lipschitz, so a point at distance r from the wall
  // vouches for every point up the column within r - gap of it: one query skips ahead
  // floor((r - gap) / d) points and a column costs O(log(R/d)) distance queries, not O(R/d).
  std::vector<std::vector<Vec3>> perColumn(box.columns());
#pragma omp parallel
  {
    std::vector<double> crossings;
    std::vector<char> inside;
#pragma omp for schedule(dynamic, 16)
    for (long long cl = 0; cl < static_cast<long long>(box.columns()); ++cl) {
      const size_t c = static_cast<size_t>(cl);
      detail::insideColumn(box, query, c, crossings, inside);
      double clearUpTo = -std::numeric_limits<double>::infinity();  // [unit] z up to which points are >= gap away
      for (size_t k = 0; k < inside.size(); ++k) {
        if (!inside[k]) continue;
        const Vec3 p = box.point(box.index(c, k));
        if (gap > 0 && p.z() > clearUpTo) {
          const double r = std::sqrt(query.squaredDistance(p));
          if (r < gap) continue;
          clearUpTo = p.z() + (r - gap);
        }
        if (options.keep && !options.keep(p)) continue;
        perColumn[c].push_back(p);
      }
    }
  }
  std::vector<Vec3> points;
  for (const auto& column : perColumn) points.insert(points.end(), column.begin(), column.end());
  return points;
}

}  // namespace meshing
