#include "anatomy/orbital_fat.h"

#include <algorithm>
#include <cmath>

#include "anatomy/anatomy_error.h"
#include "anatomy/mesh_properties.h"

namespace anatomy {

OrbitalFat makeOrbitalFat(const ScleraShell& sclera, const OrbitalFatParameters& p) {
  require(p.thickness >= 0.5e-3 && p.thickness <= 30e-3,
          "orbital fat thickness " + mmText(p.thickness) + " is out of range (0.5..30 mm)");
  const double degree = std::numbers::pi / 180.0;
  require(p.polarExtent >= 10.0 * degree && p.polarExtent <= 90.0 * degree,
          "orbital fat polar extent " + std::to_string(p.polarExtent / degree) +
              " deg is out of range (10..90 deg from the posterior pole)");
  require(p.resolution >= 8 && p.resolution <= 4096,
          "orbital fat resolution " + std::to_string(p.resolution) + " is out of range (8..4096)");
  const CavityShape& cavity = sclera.eye().cavity();
  const double extent = std::min(p.polarExtent, cavity.rimTheta());
  const int n = p.resolution;
  const int rings = std::max(3, static_cast<int>(std::ceil(n * extent / (2.0 * std::numbers::pi))));

  // Vertices: inner pole, inner rings 1..rings, outer pole, outer rings 1..rings.
  OrbitalFat fat;
  auto& vertices = fat.mesh.vertices;
  const auto addSurface = [&](bool outer) {
    for (int i = 0; i <= rings; ++i)
      for (int j = 0; j < (i == 0 ? 1 : n); ++j) {
        const WallCoordinate w{extent * i / rings, 2.0 * std::numbers::pi * j / n};
        Vec3 v = sclera.outerPoint(w);
        if (outer) v += p.thickness * cavity.ellipsoidNormal(w);
        vertices.push_back(v);
      }
  };
  addSurface(false);
  const int outerBase = static_cast<int>(vertices.size());
  addSurface(true);
  const auto index = [n](int base, int ring, int j) {
    return ring == 0 ? base : base + 1 + (ring - 1) * n + (j % n);
  };
  auto& faces = fat.mesh.faces;
  // Outer face: oriented like the cavity wall (outward = away from the globe); inner face
  // reversed (its outward points into the globe); ring face at the edge points toward +theta.
  for (int base : {outerBase, 0}) {
    const bool flip = base == 0;
    const auto add = [&](int a, int b, int c) {
      faces.push_back(flip ? meshing::Triangle{a, c, b} : meshing::Triangle{a, b, c});
    };
    for (int j = 0; j < n; ++j) add(index(base, 0, 0), index(base, 1, j + 1), index(base, 1, j));
    for (int i = 1; i < rings; ++i)
      for (int j = 0; j < n; ++j) {
        add(index(base, i, j), index(base, i, j + 1), index(base, i + 1, j + 1));
        add(index(base, i, j), index(base, i + 1, j + 1), index(base, i + 1, j));
      }
  }
  for (int j = 0; j < n; ++j) {
    const int innerJ = index(0, rings, j), innerNext = index(0, rings, j + 1);
    const int outerJ = index(outerBase, rings, j), outerNext = index(outerBase, rings, j + 1);
    faces.push_back({innerJ, outerJ, outerNext});
    faces.push_back({innerJ, outerNext, innerNext});
  }
  fat.volume = measureMesh(fat.mesh).signedVolume;
  return fat;
}

}  // namespace anatomy
