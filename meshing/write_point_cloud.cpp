#include "meshing/write_point_cloud.h"

#include <cstdio>
#include <filesystem>

#include "meshing/mesh_error.h"

namespace meshing {

void writePointCloud(const std::string& path, const std::vector<Vec3>& points,
                     const std::vector<int>& labels, double scale) {
  if (std::filesystem::path(path).extension() != ".ply")
    throw MeshError(path, "point clouds are written as PLY", "name the output file *.ply");
  if (!labels.empty() && labels.size() != points.size())
    throw MeshError(path, "labels and points differ in number", "");
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out)
    throw MeshError(path, "cannot open for writing", "check the directory exists and is writable");
  std::fprintf(out,
               "ply\nformat ascii 1.0\ncomment written by tamponade\nelement vertex %zu\n"
               "property float x\nproperty float y\nproperty float z\n%send_header\n",
               points.size(), labels.empty() ? "" : "property int label\n");
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i] * scale;
    if (labels.empty())
      std::fprintf(out, "%.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    else
      std::fprintf(out, "%.9g %.9g %.9g %d\n", p.x(), p.y(), p.z(), labels[i]);
  }
  const bool failed = std::ferror(out) != 0;
  if (std::fclose(out) != 0 || failed) throw MeshError(path, "write failed (disk full?)", "");
}

}  // namespace meshing
