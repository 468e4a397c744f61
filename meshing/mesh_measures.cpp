#include "meshing/mesh_measures.h"

#include <limits>

namespace meshing {

MeshMeasures measureMesh(const TriangleMesh& mesh) {
  MeshMeasures m;
  if (mesh.faces.empty()) return m;
  m.boundsMin = Vec3::Constant(std::numeric_limits<double>::infinity());
  m.boundsMax = -m.boundsMin;
  // Relative to the first vertex, to keep round-off small for meshes far from the origin.
  const Vec3 o = mesh.vertices[static_cast<size_t>(mesh.faces.front()[0])];
  for (const Triangle& f : mesh.faces) {
    const Vec3& a = mesh.vertices[static_cast<size_t>(f[0])];
    const Vec3& b = mesh.vertices[static_cast<size_t>(f[1])];
    const Vec3& c = mesh.vertices[static_cast<size_t>(f[2])];
    m.area += 0.5 * (b - a).cross(c - a).norm();
    m.signedVolume += (a - o).dot((b - o).cross(c - o)) / 6.0;
    for (const Vec3* p : {&a, &b, &c}) {
      m.boundsMin = m.boundsMin.cwiseMin(*p);
      m.boundsMax = m.boundsMax.cwiseMax(*p);
    }
  }
  return m;
}

}  // namespace meshing
