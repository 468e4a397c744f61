// Shared helpers of the meshing tests: meshes built in code (no big
// files in the repository).
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "meshing/make_icosphere.h"
#include "meshing/triangle_mesh.h"

namespace meshing_test {

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// OFF is not among writeMesh()'s formats; the import test writes it by hand.
inline void writeOff(const meshing::TriangleMesh& m, const std::string& path, double scale) {
  std::ofstream out(path);
  out.precision(12);
  out << "OFF\n" << m.vertices.size() << ' ' << m.faces.size() << " 0\n";
  for (const auto& v : m.vertices)
    out << v.x() * scale << ' ' << v.y() * scale << ' ' << v.z() * scale << '\n';
  for (const auto& f : m.faces) out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
}

inline void writeAsciiStl(const meshing::TriangleMesh& m, const std::string& path, double scale) {
  std::ofstream out(path);
  out.precision(12);
  out << "solid test\n";
  for (const auto& f : m.faces) {
    const auto& a = m.vertices[static_cast<size_t>(f[0])];
    const meshing::Vec3 n = (m.vertices[static_cast<size_t>(f[1])] - a)
                                .cross(m.vertices[static_cast<size_t>(f[2])] - a)
                                .normalized();
    out << "facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\n outer loop\n";
    for (int v : f) {
      const auto& p = m.vertices[static_cast<size_t>(v)];
      out << "  vertex " << p.x() * scale << ' ' << p.y() * scale << ' ' << p.z() * scale << '\n';
    }
    out << " endloop\nendfacet\n";
  }
  out << "endsolid test\n";
}

// Icosphere of radius 12 mm in metres (an emmetropic cavity, roughly).
inline meshing::TriangleMesh eyeSphere(int subdivisions = 3) {
  return meshing::makeIcosphere(0.012, subdivisions);
}

// The cube [0, L]^3 with outward faces: exact coordinates, lattice-aligned edges.
inline meshing::TriangleMesh makeCube(double L) {
  meshing::TriangleMesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back(L * (k & 1), L * ((k >> 1) & 1), L * ((k >> 2) & 1));
  m.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
             {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

}  // namespace meshing_test
