// Writes a TriangleMesh as binary STL, ASCII OBJ or ASCII PLY, chosen by the file extension.
#pragma once

#include <string>

#include "meshing/triangle_mesh.h"

namespace meshing {

// `scale` multiplies every coordinate on the way out (e.g. 1000 to write metres as mm).
// Throws std::runtime_error naming the file when it cannot be written or the extension is unknown.
void writeMesh(const TriangleMesh& mesh, const std::string& path, double scale = 1.0);

}  // namespace meshing
