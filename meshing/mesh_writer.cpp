#include "meshing/mesh_writer.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace meshing {
namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void writeStl(const TriangleMesh& mesh, std::ofstream& out, double scale) {
  char header[80] = {};
  std::strncpy(header, "binary STL written by tamponade", sizeof(header) - 1);
  out.write(header, sizeof(header));
  const auto count = static_cast<std::uint32_t>(mesh.faces.size());
  out.write(reinterpret_cast<const char*>(&count), sizeof(count));
  for (const auto& f : mesh.faces) {
    const Vec3& a = mesh.vertices[static_cast<size_t>(f[0])];
    const Vec3& b = mesh.vertices[static_cast<size_t>(f[1])];
    const Vec3& c = mesh.vertices[static_cast<size_t>(f[2])];
    Vec3 n = (b - a).cross(c - a);
    if (n.norm() > 0) n.normalize();
    float record[12];
    for (int d = 0; d < 3; ++d) {
      record[d] = static_cast<float>(n[d]);
      record[3 + d] = static_cast<float>(a[d] * scale);
      record[6 + d] = static_cast<float>(b[d] * scale);
      record[9 + d] = static_cast<float>(c[d] * scale);
    }
    out.write(reinterpret_cast<const char*>(record), sizeof(record));
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), sizeof(attributes));
  }
}

}  // namespace

void writeMesh(const TriangleMesh& mesh, const std::string& path, double scale) {
  const std::string ext = lowerExtension(path);
  if (ext != ".stl" && ext != ".obj" && ext != ".ply")
    throw std::runtime_error(path + ": cannot write meshes with extension '" + ext +
                             "' (use .stl, .obj or .ply)");
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  out.precision(9);
  if (ext == ".stl") {
    writeStl(mesh, out, scale);
  } else if (ext == ".obj") {
    out << "# written by tamponade\n";
    for (const auto& v : mesh.vertices)
      out << "v " << v.x() * scale << ' ' << v.y() * scale << ' ' << v.z() * scale << '\n';
    for (const auto& f : mesh.faces)
      out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
  } else {
    out << "ply\nformat ascii 1.0\ncomment written by tamponade\nelement vertex "
        << mesh.vertices.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
        << "element face " << mesh.faces.size() << "\nproperty list uchar int vertex_indices\n"
        << "end_header\n";
    for (const auto& v : mesh.vertices)
      out << v.x() * scale << ' ' << v.y() * scale << ' ' << v.z() * scale << '\n';
    for (const auto& f : mesh.faces) out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
  }
  if (!out) throw std::runtime_error(path + ": write failed (disk full?)");
}

}  // namespace meshing
