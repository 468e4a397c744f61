// A box of cubic voxels, x fastest: the discretisation of the static equilibrium solver
// (threshold_dynamics_xu2017.h). Voxel (i, j, k) is centred at origin + h (i + 1/2, j + 1/2,
// k + 1/2).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "sim/core/types.h"

namespace sim::equilibrium {

struct VoxelGrid {
  Vec3 origin = Vec3::Zero();  // [m] corner of voxel (0, 0, 0)
  double spacing = 0.0;        // [m] edge h of a voxel
  int nx = 0, ny = 0, nz = 0;

  std::size_t size() const {
    return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) *
           static_cast<std::size_t>(nz);
  }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(nx) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(ny) * k);
  }
  Vec3 centre(int i, int j, int k) const {
    return origin + spacing * Vec3(i + 0.5, j + 0.5, k + 0.5);
  }
  Vec3 centre(std::size_t v) const {
    const auto i = static_cast<int>(v % nx), j = static_cast<int>((v / nx) % ny),
               k = static_cast<int>(v / (static_cast<std::size_t>(nx) * ny));
    return centre(i, j, k);
  }
  double voxelVolume() const { return spacing * spacing * spacing; }  // [m^3]
};

// The grid of spacing h that holds the box [lo, hi] with `margin` empty voxels on every side.
VoxelGrid gridAround(const Vec3& lo, const Vec3& hi, double spacing, int margin);

// Fluid volume fraction of each voxel from a signed distance to the cavity wall (negative
// inside) [m]: clamp(1/2 - s/h, 0, 1), the exact fraction for a wall parallel to a voxel face
// and within 0.1 of it for any other orientation (a plane through the voxel at any angle).
std::vector<double> fluidFractionsFromDistance(const VoxelGrid& grid,
                                               const std::function<double(const Vec3&)>& distance);

// Trilinear interpolation of a voxel field at x [m] (values at voxel centres; clamped at the
// grid's edge) with each voxel weighted by `weight` as well: sum w_k c_k a_k / sum w_k c_k (c the
// trilinear weights); 0 where every weight is 0.
double weightedInterpolate(const VoxelGrid& grid, const std::vector<double>& field,
                           const std::vector<double>& weight, const Vec3& x);

}  // namespace sim::equilibrium
