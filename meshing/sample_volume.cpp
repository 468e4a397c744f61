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
  const detail::LatticeBox box(m.boundsMin, m.boundsMax, d, options.latticeOrigin, "volume sampling");
  const double gap2 = gap * gap;
  std::vector<char> keep(box.count(), 0);
#pragma omp parallel for schedule(dynamic, 4096)
  for (long long k = 0; k < static_cast<long long>(box.count()); ++k) {
    const Vec3 p = box.point(static_cast<size_t>(k));
    if (options.keep && !options.keep(p)) continue;
    if (gap > 0 && query.squaredDistance(p) < gap2) continue;
    keep[static_cast<size_t>(k)] = query.isInside(p);
  }
  std::vector<Vec3> points;
  for (size_t k = 0; k < keep.size(); ++k)
    if (keep[k]) points.push_back(box.point(k));
  return points;
}

}  // namespace meshing
