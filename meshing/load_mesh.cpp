#include "meshing/load_mesh.h"

namespace meshing {

LoadedMesh loadMesh(const std::string& path, LengthUnit unit, const MeshCheckOptions& options) {
  ImportResult imported = importMesh(path, unit);
  LoadedMesh out;
  out.report = requireUsableMesh(imported.mesh, path, options);
  out.mesh = std::move(out.report.mesh);
  out.report.mesh = TriangleMesh{};  // one copy is enough
  out.warnings = std::move(imported.warnings);
  out.unit = imported.unit;
  return out;
}

}  // namespace meshing
