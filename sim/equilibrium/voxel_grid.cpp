#include "sim/equilibrium/voxel_grid.h"

#include <algorithm>
#include <cmath>

#include "sim/core/error.h"

namespace sim::equilibrium {

VoxelGrid gridAround(const Vec3& lo, const Vec3& hi, double spacing, int margin) {
  require(spacing > 0.0 && std::isfinite(spacing), "equilibrium: voxel spacing must be > 0");
  VoxelGrid g;
  g.spacing = spacing;
  const Vec3 extent = hi - lo;
  int n[3];
  for (int a = 0; a < 3; ++a) {
    n[a] = static_cast<int>(std::ceil(extent[a] / spacing)) + 2 * margin;
    require(n[a] > 0 && n[a] < 4096, "equilibrium: the voxel grid would have " +
                                         std::to_string(n[a]) + " voxels along one axis");
  }
  g.nx = n[0];
  g.ny = n[1];
  g.nz = n[2];
  const Vec3 centre = 0.5 * (lo + hi);
  g.origin = centre - 0.5 * spacing * Vec3(g.nx, g.ny, g.nz);
  return g;
}

std::vector<double> fluidFractionsFromDistance(const VoxelGrid& grid,
                                               const std::function<double(const Vec3&)>& distance) {
  std::vector<double> f(grid.size());
  const double h = grid.spacing;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < grid.nz; ++k)
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i)
        f[grid.index(i, j, k)] = std::clamp(0.5 - distance(grid.centre(i, j, k)) / h, 0.0, 1.0);
  return f;
}

namespace {

// The 8 voxel centres around x and their trilinear weights (clamped at the grid's edge).
template <class F>
void forCorners(const VoxelGrid& grid, const Vec3& x, F&& visit) {
  const Vec3 u = (x - grid.origin) / grid.spacing - Vec3::Constant(0.5);
  int i0[3];
  double w[3];
  const int n[3] = {grid.nx, grid.ny, grid.nz};
  for (int a = 0; a < 3; ++a) {
    const double c = std::clamp(u[a], 0.0, static_cast<double>(n[a] - 1));
    i0[a] = std::min(static_cast<int>(std::floor(c)), n[a] - 2);
    w[a] = c - i0[a];
  }
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx)
        visit(grid.index(i0[0] + dx, i0[1] + dy, i0[2] + dz),
              (dx ? w[0] : 1 - w[0]) * (dy ? w[1] : 1 - w[1]) * (dz ? w[2] : 1 - w[2]));
}

}  // namespace

double weightedInterpolate(const VoxelGrid& grid, const std::vector<double>& field,
                           const std::vector<double>& weight, const Vec3& x) {
  double value = 0.0, total = 0.0;
  forCorners(grid, x, [&](std::size_t v, double c) {
    value += c * weight[v] * field[v];
    total += c * weight[v];
  });
  return total > 0.0 ? value / total : 0.0;
}

}  // namespace sim::equilibrium
