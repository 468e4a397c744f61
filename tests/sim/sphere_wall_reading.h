// The coverage read below the spacing (sim/measure/wall_oil_extended.h) on the wall of a spherical
// cavity of radius R about the origin: the voxel grid of the fluid region (half a spacing), its
// fluid fractions and the wall points with their normals are built once per cavity and reused for
// every reading. Shared by the reader's test (test_wall_oil_extended.cpp) and the hand-run readings
// of cavity runs (tools/bench/interface_bench.cpp, tools/bench/sphere_run_reading.cpp).
#pragma once

#include <cstdint>
#include <cstdio>
#include <vector>

#include "sim/equilibrium/voxel_grid.h"
#include "sim/measure/wall_oil_extended.h"
#include "sphere_points.h"

namespace testref {

class SphereWallReading {
 public:
  static constexpr int kWallPoints = 20000;

  // `radius` [m] of the surface the fluid fills, `spacing` [m] the particles'.
  SphereWallReading(double radius, double spacing)
      : grid_(sim::equilibrium::gridAround(sim::Vec3::Constant(-radius),
                                           sim::Vec3::Constant(radius), 0.5 * spacing, 2)),
        fluid_(sim::equilibrium::fluidFractionsFromDistance(
            grid_, [radius](const sim::Vec3& y) { return y.norm() - radius; })),
        normals_(sphereNormals(kWallPoints)),
        spacing_(spacing) {
    for (const sim::Vec3& n : normals_) wall_.push_back(radius * n);
  }

  // Per wall point, 1 where the extended interface leaves it on the oil side. `particles` [m]
  // relative to the cavity's centre, `isOil` 1 oil, 0 aqueous.
  std::vector<std::uint8_t> covered(const std::vector<sim::Vec3>& particles,
                                    const std::vector<std::uint8_t>& isOil,
                                    const sim::ExtendedWallReadingOptions& options) const {
    return sim::wallOilByExtendedInterface(grid_, fluid_, particles, isOil, wall_, normals_,
                                           options);
  }

  // [1] The oil-covered share of the wall (equal areas per wall point).
  double coverage(const std::vector<sim::Vec3>& particles, const std::vector<std::uint8_t>& isOil,
                  const sim::ExtendedWallReadingOptions& options) const {
    double sum = 0.0;
    for (const std::uint8_t c : covered(particles, isOil, options)) sum += c;
    return sum / static_cast<double>(wall_.size());
  }

  // Prints the coverage with the interface taken 1.25, 2, 2.5, 3 and 4 spacings from the wall
  // and extended to it at `contactAngle` [rad] through the aqueous (colour support 1.5 spacings):
  // the hand-run benches' line for a run in a spherical cavity.
  void printCoverageByOffset(const std::vector<sim::Vec3>& particles,
                             const std::vector<std::uint8_t>& isOil, double contactAngle) const {
    std::printf("coverage read below the spacing, interface taken at");
    for (const double offset : {1.25, 2.0, 2.5, 3.0, 4.0}) {
      sim::ExtendedWallReadingOptions o;
      o.supportRadius = 1.5 * spacing_;
      o.offset = offset * spacing_;
      o.contactAngle = contactAngle;
      std::printf(" %.2f d: %.4f%s", offset, coverage(particles, isOil, o),
                  offset < 4 ? "," : "\n");
    }
  }

  const std::vector<sim::Vec3>& wallPoints() const { return wall_; }  // [m]

 private:
  sim::equilibrium::VoxelGrid grid_;
  std::vector<double> fluid_;
  std::vector<sim::Vec3> normals_, wall_;
  double spacing_;  // [m] the particles'
};

}  // namespace testref
