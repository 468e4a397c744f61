// Pressure jump across a droplet's interface (Young-Laplace check, docs/methods/interface.md
// validation 1): mean pressure of the droplet's particles well inside minus the mean pressure of
// the other particles in a shell outside, both away from the diffuse interface (|r - R| > margin)
// and from walls (particles with a wall neighbour are left out: the wall term perturbs their
// pressure). The outer shell (R + margin < r < outerRadius) keeps the sample near the droplet: with
// the current one-layer Akinci walls the pressure of a closed box at rest is not uniform within a
// few h of the walls and corners (engine-notes KNOWN PROBLEM), which is not the droplet's doing.
#pragma once

#include <limits>
#include <vector>

#include "sim/world/world.h"

namespace sim {

struct DropletRegion {
  Vec3 centre = Vec3::Zero();  // [m]
  Real radius = 0.0;           // [m]
  Real margin = 0.0;           // [m] half-width of the band around r = R that is left out
  int material = -1;           // the droplet's material
  Real outerRadius = std::numeric_limits<Real>::infinity();  // [m] outer edge of the outside shell
};

struct PressureJump {
  Real inside = 0.0;   // [Pa] mean p of droplet particles with r < R - margin
  Real outside = 0.0;  // [Pa] mean p of other particles with R + margin < r < outerRadius
  Real jump = 0.0;     // [Pa] inside - outside
  int insideCount = 0, outsideCount = 0;
};

// `pressure` is the solver's pressure field (one value per dynamic particle). Throws SimError if
// either region holds no particle.
PressureJump measureDropletPressureJump(const World& world, const std::vector<Real>& pressure,
                                        const DropletRegion& region);

// Centre of mass of the particles of one material [m].
Vec3 centreOfMaterial(const World& world, int material);

}  // namespace sim
