// Measures of a closed triangle mesh that anatomy needs to report on the cavities it generates:
// enclosed volume, area, and a topological watertightness check. (Full validation and repair of
// imported meshes is meshing/'s job, with CGAL.)
#pragma once

#include <cstddef>

#include "meshing/triangle_mesh.h"

namespace anatomy {

struct MeshProperties {
  double signedVolume = 0.0;  // [unit^3] divergence theorem; > 0 when the faces point outward
  double area = 0.0;          // [unit^2]
  meshing::Vec3 boundsMin = meshing::Vec3::Zero();
  meshing::Vec3 boundsMax = meshing::Vec3::Zero();
  std::size_t boundaryEdges = 0;     // edges used by one face only (holes)
  std::size_t nonManifoldEdges = 0;  // edges used by more than two faces
  std::size_t misorientedEdges = 0;  // edges whose two faces traverse them the same way
  std::size_t degenerateFaces = 0;   // faces repeating a vertex index or out-of-range indices

  // Every edge shared by exactly two faces that traverse it in opposite directions.
  bool isWatertight() const {
    return boundaryEdges == 0 && nonManifoldEdges == 0 && misorientedEdges == 0 &&
           degenerateFaces == 0;
  }
};

MeshProperties measureMesh(const meshing::TriangleMesh& mesh);

}  // namespace anatomy
