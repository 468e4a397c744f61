// Shared scene set-ups for the engine's tests.
#pragma once

#include "sim/measure/diagnostics.h"
#include "sim/scenes/box_scene.h"
#include "sim/world/stage_registry.h"

namespace sim::testing {

inline Material water() {
  Material m;
  m.name = "water";
  m.restDensity = 1000.0;     // [kg/m^3]
  m.dynamicViscosity = 1e-3;  // [Pa s] water at 20 C
  return m;
}

// Gap between a surface-sampled wall and the first fluid particle, in spacings. The Akinci wall
// term over-estimates density at distance d (6 % on a face, 15 % in a corner for the cubic spline
// at h = 2d); at 1.2 d a lattice block starts at or below rest density everywhere, so a scene
// starts at rest instead of with a pressure shock.
inline constexpr Real kWallGap = 1.2;

// A tank of inner width `width` (x and z) with a water column of `height` on a lattice of spacing
// d that starts kWallGap d from the walls.
struct Tank {
  TankSpec spec;
  std::unique_ptr<World> world;
};

inline Tank hydrostaticTank(Real width, Real height, Real d, Real tankHeight = 0) {
  Tank t;
  const Real gap = (kWallGap - 0.5) * d;  // lattice cells are centred: the first particle is d/2 in
  t.spec.innerMin = Vec3::Zero();
  // Walls reach 1.5x above the fluid: a splash at the start must not fall over the rim.
  t.spec.innerMax =
      Vec3(width + 2 * gap, tankHeight > 0 ? tankHeight : 1.5 * height, width + 2 * gap);
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = tankDomain(t.spec, d);
  t.world = std::make_unique<World>(params);
  t.world->materials.add(water());
  addTankWalls(*t.world, t.spec, d);
  addFluidBlock(*t.world, Vec3::Constant(gap), Vec3(gap + width, gap + height, gap + width), d, 0);
  t.world->initialize();
  return t;
}

}  // namespace sim::testing
