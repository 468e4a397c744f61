// Shared scene set-ups for the engine's tests.
#pragma once

#include "sim/measure/diagnostics.h"
#include "sim/scenes/box_scene.h"
#include "sim/world/stage_registry.h"

namespace sim::testing {

inline Material water() {
  Material m;
  m.name = "water";
  m.restDensity = 1000.0;      // [kg/m^3]
  m.dynamicViscosity = 1e-3;   // [Pa s] water at 20 C
  return m;
}

// A tank of width `width` (x and z) filled with water to `height`, spacing d.
struct Tank {
  TankSpec spec;
  std::unique_ptr<World> world;
};

inline Tank hydrostaticTank(Real width, Real height, Real d, Real tankHeight = 0) {
  Tank t;
  t.spec.innerMin = Vec3::Zero();
  t.spec.innerMax = Vec3(width, tankHeight > 0 ? tankHeight : height, width);
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = tankDomain(t.spec, d);
  t.world = std::make_unique<World>(params);
  t.world->materials.add(water());
  addTankWalls(*t.world, t.spec, d);
  addFluidBlock(*t.world, Vec3::Zero(), Vec3(width, height, width), d, 0);
  t.world->initialize();
  return t;
}

}  // namespace sim::testing
