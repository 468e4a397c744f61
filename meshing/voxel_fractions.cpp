#include "meshing/voxel_fractions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace meshing {
namespace {

Vec3 centreOf(const VoxelBox& b, int i, int j, int k) {
  return b.origin + b.spacing * Vec3(i + 0.5, j + 0.5, k + 0.5);
}

// Inside flags of one row of voxels along x: from the line's crossings, or per voxel when the
// line grazes the surface (lineCrossings then cannot be trusted).
void insideRow(const MeshQuery& q, const VoxelBox& b, int j, int k, std::uint8_t* row) {
  std::vector<double> crossings;
  if (!q.lineCrossings(centreOf(b, 0, j, k), 0, crossings)) {
    for (int i = 0; i < b.nx; ++i) row[i] = q.isInside(centreOf(b, i, j, k)) ? 1 : 0;
    return;
  }
  for (int i = 0; i < b.nx; ++i) {
    const double x = centreOf(b, i, j, k).x();
    const auto before = std::upper_bound(crossings.begin(), crossings.end(), x) - crossings.begin();
    row[i] = before % 2 == 1 ? 1 : 0;
  }
}

}  // namespace

std::vector<double> voxelInsideFractions(const MeshQuery& query, const VoxelBox& b) {
  const std::size_t nx = static_cast<std::size_t>(b.nx), nxy = nx * static_cast<std::size_t>(b.ny);
  const std::size_t n = nxy * static_cast<std::size_t>(b.nz);
  std::vector<std::uint8_t> inside(n, 0);
#pragma omp parallel for schedule(dynamic, 4) collapse(2)
  for (int k = 0; k < b.nz; ++k)
    for (int j = 0; j < b.ny; ++j) insideRow(query, b, j, k, &inside[j * nx + k * nxy]);

  std::vector<double> fraction(n, 0.0);
#pragma omp parallel for schedule(dynamic, 4)
  for (int k = 0; k < b.nz; ++k)
    for (int j = 0; j < b.ny; ++j)
      for (int i = 0; i < b.nx; ++i) {
        const std::size_t v = i + j * nx + k * nxy;
        bool straddles = false;
        for (int dk = -1; dk <= 1 && !straddles; ++dk)
          for (int dj = -1; dj <= 1 && !straddles; ++dj)
            for (int di = -1; di <= 1 && !straddles; ++di) {
              const int a = i + di, c = j + dj, e = k + dk;
              if (a < 0 || c < 0 || e < 0 || a >= b.nx || c >= b.ny || e >= b.nz) continue;
              straddles = inside[a + c * nx + e * nxy] != inside[v];
            }
        if (!straddles) {
          fraction[v] = inside[v];
          continue;
        }
        const double distance = std::sqrt(query.squaredDistance(centreOf(b, i, j, k)));
        const double signedDistance = inside[v] ? -distance : distance;
        fraction[v] = std::clamp(0.5 - signedDistance / b.spacing, 0.0, 1.0);
      }
  return fraction;
}

}  // namespace meshing
