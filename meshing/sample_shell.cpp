#include "meshing/sample_shell.h"

#include <algorithm>
#include <cmath>

#include "meshing/lattice_box.h"
#include "meshing/mesh_error.h"
#include "meshing/mesh_measures.h"
#include "meshing/mesh_query.h"

namespace meshing {

ShellSamples sampleShell(const TriangleMesh& mesh, double thickness, double spacing) {
  ShellSamplingOptions o;
  o.spacing = spacing;
  o.thickness = [thickness](const Vec3&) { return thickness; };
  return sampleShell(mesh, o);
}

ShellSamples sampleShell(const TriangleMesh& mesh, const ShellSamplingOptions& options) {
  const double d = options.spacing;  // [unit]
  if (!(d > 0) || !std::isfinite(d))
    throw MeshError("shell sampling", "spacing must be positive and finite", "give e.g. 0.4 mm");
  if (!options.thickness)
    throw MeshError("shell sampling", "no thickness given", "give a constant or a thickness function");
  const double gap = options.innerGap < 0 ? 0.5 * d : options.innerGap;  // [unit]
  // Largest thickness, for the lattice box.
  double tMax = 0;  // [unit]
  auto probe = [&](const Vec3& q) {
    const double t = options.thickness(q);
    if (!(t >= 0) || !std::isfinite(t))
      throw MeshError("shell sampling", "thickness function gave " + std::to_string(t) + " at a surface point",
                      "return a finite thickness >= 0");
    tMax = std::max(tMax, t);
  };
  for (const Vec3& v : mesh.vertices) probe(v);
  for (const Triangle& f : mesh.faces)
    probe((mesh.vertices[static_cast<size_t>(f[0])] + mesh.vertices[static_cast<size_t>(f[1])] +
           mesh.vertices[static_cast<size_t>(f[2])]) / 3.0);

  const MeshQuery query(mesh);
  const MeshMeasures m = measureMesh(mesh);
  const Vec3 grow = Vec3::Constant(tMax + d);
  const detail::LatticeBox box(m.boundsMin - grow, m.boundsMax + grow, d, options.latticeOrigin, "shell sampling");
  std::vector<double> depth(box.count(), -1.0);  // < 0: not in the shell
  std::vector<char> outer(box.count(), 0);
#pragma omp parallel for schedule(dynamic, 4096)
  for (long long k = 0; k < static_cast<long long>(box.count()); ++k) {
    const Vec3 p = box.point(static_cast<size_t>(k));
    const Vec3 q = query.closestPoint(p);
    const double r = (p - q).norm();  // [unit]
    if (r < gap || r > tMax) continue;
    const double t = options.thickness(q);
    if (r > t || query.isInside(p)) continue;
    depth[static_cast<size_t>(k)] = r;
    outer[static_cast<size_t>(k)] = r > t - d;
  }
  ShellSamples out;
  for (size_t k = 0; k < depth.size(); ++k)
    if (depth[k] >= 0) {
      out.points.push_back(box.point(k));
      out.depth.push_back(depth[k]);
      out.isOuter.push_back(outer[k]);
    }
  return out;
}

}  // namespace meshing
