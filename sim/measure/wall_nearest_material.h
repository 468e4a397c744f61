// Material of the fluid particle nearest to each wall particle (docs/methods/interface.md
// validation 5): the coverage definition "wall area whose nearest fluid is oil", which unlike the
// Shepard fraction (wall_phase_fraction.h) also classifies wall particles with no fluid within the
// kernel support (a gap opened between the fluid and the wall).
#pragma once

#include <vector>

#include "sim/world/world.h"

namespace sim {

// One material index per wall particle (-1 if there is no fluid particle at all). Brute force,
// O(#walls x #fluid) with OpenMP over the walls: a measurement for small validation scenes.
std::vector<int> wallNearestMaterial(const World& world);

}  // namespace sim
