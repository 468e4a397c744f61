// Validation and safe repair of a triangle mesh meant to bound a cavity: closed, manifold,
// consistently and outward oriented, no self-intersections, no degenerate faces, one connected
// component. CGAL Polygon Mesh Processing does the work inside check_mesh.cpp.
#pragma once

#include <string>
#include <vector>

#include "meshing/mesh_measures.h"
#include "meshing/triangle_mesh.h"

namespace meshing {

struct MeshCheckOptions {
  int maxHoleEdges = 8;              // holes with at most this many boundary edges are filled
  bool keepLargestComponent = true;  // false: several components are refused instead
};

struct MeshReport {
  // Each entry is one sentence naming the problem and where (face indices refer to the input
  // mesh, points are in the mesh's units).
  std::vector<std::string> repairs;   // what was changed, e.g. "reversed all 1280 faces ..."
  std::vector<std::string> refusals;  // what could not be repaired safely; the mesh is unusable
  TriangleMesh mesh;                  // the repaired mesh (empty when refused)
  MeshMeasures measures;              // of the repaired mesh (of the input when refused)
  int inputVertices = 0, inputFaces = 0;

  bool isUsable() const { return refusals.empty(); }
  bool wasRepaired() const { return !repairs.empty(); }
};

// Never throws for geometric problems (they go to `refusals`); throws MeshError only for a
// structurally broken mesh object (face index out of range, no faces).
MeshReport checkMesh(const TriangleMesh& mesh, const MeshCheckOptions& options = {});

// checkMesh, then throws MeshError naming `source` and every refusal if the mesh is unusable.
MeshReport requireUsableMesh(const TriangleMesh& mesh, const std::string& source,
                             const MeshCheckOptions& options = {});

}  // namespace meshing
