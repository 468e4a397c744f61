#include "anatomy/mesh_properties.h"

#include <Eigen/Geometry>  // cross products
#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace anatomy {

MeshProperties measureMesh(const meshing::TriangleMesh& mesh) {
  MeshProperties result;
  if (!mesh.vertices.empty()) {
    result.boundsMin = result.boundsMax = mesh.vertices.front();
    for (const auto& v : mesh.vertices) {
      result.boundsMin = result.boundsMin.cwiseMin(v);
      result.boundsMax = result.boundsMax.cwiseMax(v);
    }
  }
  struct EdgeUse {
    int faces = 0;
    int direction = 0;  // +1 per use low->high, -1 per use high->low
  };
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(mesh.faces.size() * 2);
  const auto vertexCount = static_cast<long long>(mesh.vertices.size());
  for (const auto& f : mesh.faces) {
    bool valid = f[0] != f[1] && f[1] != f[2] && f[0] != f[2];
    for (int k = 0; k < 3; ++k)
      valid = valid && f[static_cast<size_t>(k)] >= 0 && f[static_cast<size_t>(k)] < vertexCount;
    if (!valid) {
      ++result.degenerateFaces;
      continue;
    }
    const auto& a = mesh.vertices[static_cast<size_t>(f[0])];
    const auto& b = mesh.vertices[static_cast<size_t>(f[1])];
    const auto& c = mesh.vertices[static_cast<size_t>(f[2])];
    // Signed tetrahedron volume against the origin; the sum is exact for a closed surface.
    result.signedVolume += a.dot(b.cross(c)) / 6.0;
    result.area += 0.5 * (b - a).cross(c - a).norm();
    for (int k = 0; k < 3; ++k) {
      const auto u = static_cast<std::uint32_t>(f[static_cast<size_t>(k)]);
      const auto v = static_cast<std::uint32_t>(f[static_cast<size_t>((k + 1) % 3)]);
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(u, v)) << 32) | std::max(u, v);
      EdgeUse& use = edges[key];
      ++use.faces;
      use.direction += u < v ? 1 : -1;
    }
  }
  for (const auto& [key, use] : edges) {
    if (use.faces == 1)
      ++result.boundaryEdges;
    else if (use.faces > 2)
      ++result.nonManifoldEdges;
    else if (use.direction != 0)
      ++result.misorientedEdges;
  }
  return result;
}

}  // namespace anatomy
