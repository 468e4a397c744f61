#include "sim/measure/wall_oil_extended.h"

#include "sim/core/error.h"
#include "sim/equilibrium/threshold_dynamics_xu2017.h"
#include "sim/equilibrium/wall_oil.h"
#include "sim/kernels/kernel.h"
#include "sim/neighbors/neighbor_search.h"

namespace sim {
namespace {

// The colour u at every voxel centre with fluid: sum_j W c_j / sum_j W over the particles within
// the support (the voxel centres are the search's static points, the particles its dynamic
// ones); 0 where no particle is near.
std::vector<double> colourAtVoxels(const equilibrium::VoxelGrid& grid,
                                   const std::vector<double>& fluidFraction,
                                   const std::vector<Vec3>& particles,
                                   const std::vector<std::uint8_t>& isOil, Real supportRadius) {
  std::vector<Vec3> centres;
  std::vector<std::size_t> voxelOf;
  for (std::size_t v = 0; v < grid.size(); ++v)
    if (fluidFraction[v] > 0.0) centres.push_back(grid.centre(v)), voxelOf.push_back(v);
  Box domain(grid.origin, grid.origin + grid.spacing * Vec3(grid.nx, grid.ny, grid.nz));
  for (const Vec3& x : particles) domain.extend(x);
  domain.min() -= Vec3::Constant(supportRadius);
  domain.max() += Vec3::Constant(supportRadius);
  NeighborSearch search(domain, supportRadius);
  search.setStatic(centres);
  search.update(particles);
  const Kernel kernel(KernelKind::kCubicSpline, supportRadius);
  std::vector<double> weighted(centres.size(), 0.0), weights(centres.size(), 0.0);
  const NeighborList& near = search.dynamicStatic();
  for (std::size_t i = 0; i < particles.size(); ++i)
    near.forEach(static_cast<Index>(i), [&](Index c) {
      const double w = kernel.W(particles[i] - centres[c]);
      weighted[c] += w * isOil[i];
      weights[c] += w;
    });
  std::vector<double> u(grid.size(), 0.0);
  for (std::size_t c = 0; c < centres.size(); ++c)
    if (weights[c] > 0.0) u[voxelOf[c]] = weighted[c] / weights[c];
  return u;
}

}  // namespace

std::vector<std::uint8_t> wallOilByExtendedInterface(const equilibrium::VoxelGrid& grid,
                                                     const std::vector<double>& fluidFraction,
                                                     const std::vector<Vec3>& particles,
                                                     const std::vector<std::uint8_t>& isOil,
                                                     const std::vector<Vec3>& wallPoints,
                                                     const std::vector<Vec3>& wallNormals,
                                                     const ExtendedWallReadingOptions& options) {
  require(fluidFraction.size() == grid.size(), "one fluid fraction per voxel is needed");
  require(isOil.size() == particles.size(), "one colour per particle is needed");
  require(wallNormals.size() == wallPoints.size(), "one normal per wall point is needed");
  require(options.supportRadius > 0.0 && options.offset > 0.0,
          "the colour support and the reading offset must be > 0 m");
  equilibrium::EquilibriumSolution colour;
  colour.grid = grid;
  colour.fluidFraction = fluidFraction;
  colour.oil = colourAtVoxels(grid, fluidFraction, particles, isOil, options.supportRadius);
  const equilibrium::WallOilReader reader(colour, options.contactAngle,
                                          options.offset / grid.spacing, options.extension);
  std::vector<std::uint8_t> oil(wallPoints.size(), 0);
#pragma omp parallel for schedule(static)
  for (std::size_t w = 0; w < wallPoints.size(); ++w)
    oil[w] = reader.oilCovered(wallPoints[w], wallNormals[w]) ? 1 : 0;
  return oil;
}

}  // namespace sim
