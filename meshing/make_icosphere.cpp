#include "meshing/make_icosphere.h"

#include <cmath>
#include <map>

#include "meshing/mesh_error.h"

namespace meshing {

TriangleMesh makeIcosphere(double radius, int subdivisions, const Vec3& centre) {
  if (!(radius > 0) || subdivisions < 0 || subdivisions > 8)
    throw MeshError("icosphere", "radius must be > 0 and subdivisions in [0, 8]", "");
  // Icosahedron: the 12 cyclic permutations of (0, +-1, +-phi).
  const double phi = 0.5 * (1 + std::sqrt(5.0));
  TriangleMesh m;
  m.vertices = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  m.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Vec3& v : m.vertices) v.normalize();
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      m.vertices.push_back(
          (m.vertices[static_cast<size_t>(a)] + m.vertices[static_cast<size_t>(b)]).normalized());
      return midpoint[key] = static_cast<int>(m.vertices.size() - 1);
    };
    std::vector<Triangle> faces;
    faces.reserve(4 * m.faces.size());
    for (const Triangle& t : m.faces) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      faces.push_back({t[0], ab, ca});
      faces.push_back({t[1], bc, ab});
      faces.push_back({t[2], ca, bc});
      faces.push_back({ab, bc, ca});
    }
    m.faces = std::move(faces);
  }
  for (Vec3& v : m.vertices) v = centre + radius * v;
  return m;
}

}  // namespace meshing
