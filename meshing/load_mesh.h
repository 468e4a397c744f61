// The usual way into the toolkit for a mesh file: import (units, size checks), then validate
// and repair, refusing what cannot be repaired.
#pragma once

#include <string>
#include <vector>

#include "meshing/check_mesh.h"
#include "meshing/import_mesh.h"

namespace meshing {

struct LoadedMesh {
  TriangleMesh mesh;                  // [m] closed, manifold, outward, one component
  MeshReport report;                  // repairs done and measures (in m)
  std::vector<std::string> warnings;  // from the import (e.g. guessed units)
  LengthUnit unit = LengthUnit::unknown;
};

// importMesh() + requireUsableMesh(): throws MeshError naming `path` for unreadable files and
// for meshes that cannot be repaired safely.
LoadedMesh loadMesh(const std::string& path, LengthUnit unit = LengthUnit::unknown,
                    const MeshCheckOptions& options = {});

}  // namespace meshing
