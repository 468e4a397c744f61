// The cavity wall as layers cut from the fluid's own lattice (docs/methods/solvers.md "Eye
// cavities", item (b)): every lattice point outside the cavity mesh within `layers` d of it is a
// wall particle of volume d^3, in layer floor(distance / d). The fluid fills the lattice points
// inside the mesh (meshing::sampleVolume with no wall gap, same origin), so fluid and walls start
// as one lattice at rest number density everywhere, and a fluid particle next to the wall sees a
// full kernel support, as on the flat layered walls where the contact angle is validated
// (docs/methods/interface.md, validation 3). The wall surface the fluid meets is then a staircase
// about the mesh, not the mesh itself; where the retina is, and how much area it has, stays the
// mesh's (the scenario's retina samples, scenario.cpp).
#pragma once

#include <cstddef>
#include <vector>

#include "meshing/triangle_mesh.h"
#include "sim/core/types.h"

namespace protocols {

struct LayeredCavityWalls {
  // Wall particles, surface layer first (indices [0, surfaceCount)), then the deeper layers.
  std::vector<sim::Vec3> positions;  // [m] lattice points
  std::vector<sim::Vec3> normals;    // [1] unit, into the wall (away from the cavity)
  std::vector<int> layer;            // 0 = surface layer
  std::size_t surfaceCount = 0;
};

// `mesh` closed and outward [m]; `spacing` d [m]; lattice points origin + d (i, j, k) with the
// origin at 0, as meshing::VolumeSamplingOptions' default. Deterministic (column order).
LayeredCavityWalls sampleLayeredCavityWalls(const meshing::TriangleMesh& mesh, double spacing,
                                            int layers);

}  // namespace protocols
