// Builders for box-shaped test and benchmark scenes (hydrostatic tank, dam break): walls sampled as
// layers of static particles around an axis-aligned tank, fluid blocks on a cubic lattice.
// Eye scenes come from meshing/ and anatomy/ instead; these exist so the engine can be validated
// on its own.
#pragma once

#include "sim/boundary/wall_layers.h"
#include "sim/world/world.h"

namespace sim {

struct TankSpec {
  Vec3 innerMin = Vec3::Zero();  // [m] the fluid side of the walls
  Vec3 innerMax = Vec3::Zero();  // [m]
  bool closedTop = false;        // a lid at innerMax.y (the up axis is +y)
};

// Domain that contains the tank, its walls and a margin (for WorldParameters::domain).
Box tankDomain(const TankSpec& tank, Real spacing);
// Adds the wall particles of the tank: one layer sampled on the tank's inner surface at spacing d,
// with outward normals (into the wall) and Akinci et al. 2012 volumes computed by the World. This
// is how mesh walls are sampled too. (A multi-layer lattice wall would be "permeable" to the
// clamped pressure solvers: a particle between lattice wall particles sees rest density and
// no force; a single surface layer is a density barrier. See docs/methods/solvers.md.)
void addTankWalls(World& world, const TankSpec& tank, Real spacing, int tag = 0);
// Layered walls (sim/boundary/wall_layers.h): the tank's walls as `layers.count` layers of a
// lattice continuing the fluid lattice of addFluidBlock (cell centres at d/2, 3d/2, ... behind
// each inner face, edges and corners filled), each particle of volume d^3 (the lattice cell; the
// tank size is rounded to whole cells per axis as above) and its layer index: 0 for the layer
// touching the tank's inside (faces, edges and corners), k for the cells k spacings further out.
// These are the static particles of Wang et al. 2023 eq. 21.
void addTankWalls(World& world, const TankSpec& tank, Real spacing, int tag,
                  const WallLayers& layers);
// Fills [min, max] with particles on a lattice of spacing d (cell-centred: first at min + d/2),
// mass densityRatio rho0 d^3 of material `materialIndex`: the lattice's kernel sum is d^-3 within
// 0.003 % (cubic spline, support 2d), so it starts at densityRatio times the rest density.
// Returns the number added.
std::size_t addFluidBlock(World& world, const Vec3& min, const Vec3& max, Real spacing,
                          int materialIndex, Real densityRatio = 1.0);

}  // namespace sim
