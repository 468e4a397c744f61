#include "meshing/sample_volume.h"

#include <cmath>

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
  const detail::LatticeBox box(m.boundsMin, m.boundsMax, d, options.latticeOrigin,
                               "volume sampling");
  // Per column (parallel, dynamic: columns differ in cost): inside flags from crossings, then
  // "is the wall within the gap?" as a ball query on the AABB tree, which prunes well even deep
  // inside, where exact distance queries visit most of the tree.
  std::vector<std::vector<Vec3>> perColumn(box.columns());
  detail::forEachColumn(box, query, [&](size_t c, const std::vector<char>& inside) {
    for (size_t k = 0; k < inside.size(); ++k) {
      if (!inside[k]) continue;
      const Vec3 p = box.point(box.index(c, k));
      // Strictly closer than the gap is rejected; the ball query is closed, so shrink it by a
      // relative 1e-12 to keep points exactly at the gap, as documented.
      if (gap > 0 && query.isWithin(p, gap * (1 - 1e-12))) continue;
      if (options.keep && !options.keep(p)) continue;
      perColumn[c].push_back(p);
    }
  });
  std::vector<Vec3> points;
  for (const auto& column : perColumn) points.insert(points.end(), column.begin(), column.end());
  return points;
}

}  // namespace meshing
