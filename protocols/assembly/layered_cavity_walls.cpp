#include "protocols/assembly/layered_cavity_walls.h"

#include <algorithm>
#include <cmath>

#include "meshing/mesh_query.h"
#include "meshing/sample_shell.h"

namespace protocols {

LayeredCavityWalls sampleLayeredCavityWalls(const meshing::TriangleMesh& mesh, double d,
                                            int layers) {
  meshing::ShellSamplingOptions o;
  o.spacing = d;
  o.innerGap = 0.0;  // every lattice point outside the mesh: sampleVolume takes the inside ones
  o.thickness = [d, layers](const sim::Vec3&) { return layers * d; };
  const meshing::ShellSamples shell = meshing::sampleShell(mesh, o);
  const meshing::MeshQuery query(mesh);

  const std::size_t n = shell.points.size();
  std::vector<sim::Vec3> normal(n);
  std::vector<int> layer(n);
#pragma omp parallel for schedule(static)
  for (long k = 0; k < static_cast<long>(n); ++k) {
    const sim::Vec3& x = shell.points[static_cast<std::size_t>(k)];
    int face = -1;
    const sim::Vec3 q = query.closestPoint(x, &face);
    sim::Vec3 m = x - q;
    // A lattice point (almost) on the surface: the face's outward normal instead.
    if (m.norm() < 1e-6 * d) {
      const auto& f = mesh.faces[static_cast<std::size_t>(face)];
      const sim::Vec3& a = mesh.vertices[static_cast<std::size_t>(f[0])];
      m = (mesh.vertices[static_cast<std::size_t>(f[1])] - a)
              .cross(mesh.vertices[static_cast<std::size_t>(f[2])] - a);
    }
    normal[static_cast<std::size_t>(k)] = m.normalized();
    layer[static_cast<std::size_t>(k)] =
        std::min(static_cast<int>(shell.depth[static_cast<std::size_t>(k)] / d), layers - 1);
  }

  LayeredCavityWalls out;
  for (int l = 0; l < layers; ++l)
    for (std::size_t k = 0; k < n; ++k) {
      if (layer[k] != l) continue;
      out.positions.push_back(shell.points[k]);
      out.normals.push_back(normal[k]);
      out.layer.push_back(l);
      if (l == 0) ++out.surfaceCount;
    }

  return out;
}

}  // namespace protocols
