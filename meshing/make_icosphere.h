// A closed, outward-oriented sphere mesh by icosahedron subdivision: the reference shape of the
// tests (closed forms for area, volume, caps) and a quick test cavity.
#pragma once

#include "meshing/triangle_mesh.h"

namespace meshing {

// 20 * 4^subdivisions faces, vertices on the sphere |x - centre| = radius [unit].
// subdivisions 3: 1280 faces, volume 0.86 % below 4/3 pi r^3; 5: 20480 faces, 0.05 % below.
TriangleMesh makeIcosphere(double radius, int subdivisions, const Vec3& centre = Vec3::Zero());

}  // namespace meshing
