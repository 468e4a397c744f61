// Area, enclosed volume and bounding box of a triangle mesh, in the mesh's own units.
#pragma once

#include "meshing/triangle_mesh.h"

namespace meshing {

struct MeshMeasures {
  double area = 0;                // [unit^2] sum of triangle areas
  double signedVolume = 0;        // [unit^3] > 0 for a closed outward mesh (divergence theorem)
  Vec3 boundsMin = Vec3::Zero();  // [unit] axis-aligned bounding box of the vertices
  Vec3 boundsMax = Vec3::Zero();  // [unit]
  // [unit] largest extent of the bounding box ("size" in reports and the plausibility check)
  double size() const { return (boundsMax - boundsMin).maxCoeff(); }
  double diagonal() const { return (boundsMax - boundsMin).norm(); }  // [unit]
};

// Volume = sum over faces of the signed tetrahedron (origin, a, b, c): exact for closed meshes,
// meaningless for open ones (the caller checks closedness). Only the vertices referenced by
// faces count for the bounding box.
MeshMeasures measureMesh(const TriangleMesh& mesh);

}  // namespace meshing
