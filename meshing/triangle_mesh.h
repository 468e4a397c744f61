// The plain triangle mesh every layer above meshing/ sees: no CGAL types here (CGAL stays inside
// meshing/ .cpp files, docs/developer-guide.md). Units are whatever the caller declared; inside the
// toolkit, m.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross(): declared in Core but defined here (else: link errors)
#include <array>
#include <vector>

namespace meshing {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;  // vertex indices, counter-clockwise seen from outside

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> faces;

  bool empty() const { return faces.empty(); }
};

}  // namespace meshing
