// Writes particles as an ASCII PLY point cloud for viewing (ParaView, MeshLab): x y z and an
// integer label per point (e.g. 0 wall, 1 interior). HDF5 output belongs to protocols/.
#pragma once

#include <string>
#include <vector>

#include "meshing/triangle_mesh.h"

namespace meshing {

// `labels` is empty or one per point; `scale` multiplies coordinates (1000 writes m as mm).
// Throws MeshError naming the file if it cannot be written or the extension is not .ply.
void writePointCloud(const std::string& path, const std::vector<Vec3>& points,
                     const std::vector<int>& labels = {}, double scale = 1.0);

}  // namespace meshing
