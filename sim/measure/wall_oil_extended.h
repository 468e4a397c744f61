// Which wall points the oil covers, read below the particle spacing (docs/methods/interface.md,
// "Coverage below the spacing"). Next to a wall that the aqueous wets (18 deg through the aqueous
// at the retina) the aqueous wedge between oil and wall is thinner than a particle over several
// spacings, so a reading of the particles next to the wall calls that wedge oil. Here the
// particles' colour (oil 1, aqueous 0) is interpolated onto a voxel grid of the fluid region
// (Shepard-normalised cubic spline over `supportRadius`), and the equilibrium's wall reader
// (sim/equilibrium/wall_oil.h) reconstructs the interface where it is resolved, `offset` from
// the wall, and extends it to the wall at the contact angle, as volume-of-fluid codes do at a
// wetting boundary.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/core/types.h"
#include "sim/equilibrium/voxel_grid.h"
#include "sim/equilibrium/wall_oil.h"

namespace sim {

struct ExtendedWallReadingOptions {
  Real supportRadius = 0.0;  // [m] of the colour interpolation (> the particle spacing)
  Real contactAngle = 0.0;   // [rad] through the aqueous
  Real offset = 0.0;         // [m] where the interface is read before it is extended
  // How the interface runs from the offset to the wall (sim/equilibrium/wall_oil.h).
  equilibrium::WallExtension extension = equilibrium::WallExtension::kArc;
};

// `fluidFraction`: per voxel of `grid`, the share inside the fluid region. `particles` [m] with
// `isOil` (1 oil, 0 aqueous); `wallPoints` [m] with their outward unit `wallNormals`. Returns 1
// for each wall point the extended interface leaves on the oil side, else 0.
std::vector<std::uint8_t> wallOilByExtendedInterface(const equilibrium::VoxelGrid& grid,
                                                     const std::vector<double>& fluidFraction,
                                                     const std::vector<Vec3>& particles,
                                                     const std::vector<std::uint8_t>& isOil,
                                                     const std::vector<Vec3>& wallPoints,
                                                     const std::vector<Vec3>& wallNormals,
                                                     const ExtendedWallReadingOptions& options);

}  // namespace sim
