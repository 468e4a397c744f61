// The floating-block scene shared by the buoyancy test, the neutral-block test and the buoyancy
// bench: a square tank of water (1000 kg/m^3) with an elastic block (E = 100 kPa, nu = 0.3) in
// its middle, the water the block displaces left out.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "scene_fixtures.h"
#include "sim/scenes/box_scene.h"
#include "sim/world/stage_registry.h"
#include "solid_fixtures.h"

namespace sim::testing {

struct FloatingBlockSpec {
  Real d = 0.01;               // [m] particle spacing
  Real specificGravity = 0.5;  // [1] block density / water density
  int tankWidth = 16;          // [d] inner width in x and z
  int waterDepth = 10;         // [d]
  int blockWidth = 6;          // [d] in x and z
  int blockLayers = 6;         // [d] the block's height H
  // [d] the block's lower face above the water lattice's floor; unset: at its Archimedes draft
  // (waterDepth - specificGravity H), so that it starts at rest.
  std::optional<Real> blockBottom;
  // Layered walls: the tank's inner faces are the water lattice's cell faces (the first particle
  // d/2 from a face, as in the bulk). Otherwise single-layer (Akinci) walls with the lattice
  // kWallGap d from them.
  bool layeredWalls = true;
  std::string solver = "indsph";
};

struct FloatingBlock {
  std::unique_ptr<World> world;
  std::unique_ptr<Pipeline> pipeline;  // attached to *world
  int block = 0;                       // the block's material index
  Vec3 blockMin;                       // [m] the block's lower corner at the start
  Real halfWidth = 0;                  // [m] half the block's width
  Vec3 footprintCentre;                // [m] the centre of the block's lower face at the start
};

// Builds the scene, initialized and with its pipeline attached.
inline FloatingBlock floatingBlock(const FloatingBlockSpec& spec) {
  const Real d = spec.d;
  const Real gap = spec.layeredWalls ? 0.0 : (kWallGap - 0.5) * d;  // [m]
  TankSpec tank;
  // Headroom of the block's height plus 4 d above the water: room for a splash at the start.
  tank.innerMax = Vec3(spec.tankWidth * d + 2 * gap, (spec.waterDepth + spec.blockLayers + 4) * d,
                       spec.tankWidth * d + 2 * gap);
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = tankDomain(tank, d);
  params.domain.extend(tank.innerMin - Vec3::Constant(4 * d));
  FloatingBlock scene;
  scene.world = std::make_unique<World>(params);
  World& world = *scene.world;
  world.materials.add(water());
  scene.block = world.materials.add(
      elasticMaterial("block", 1000 * spec.specificGravity, 1e5, 0.3));  // E [Pa], nu
  if (spec.layeredWalls)
    addTankWalls(world, tank, d, 0, WallLayers{});
  else
    addTankWalls(world, tank, d);
  const Real height = spec.blockLayers * d;  // [m]
  const Real width = spec.blockWidth * d;    // [m]
  const Real bottom = spec.blockBottom ? *spec.blockBottom * d
                                       : spec.waterDepth * d - spec.specificGravity * height;
  const Real side = gap + (spec.tankWidth - spec.blockWidth) * d / 2;  // [m]
  scene.blockMin = Vec3(side, gap + bottom, side);
  const Vec3& lo = scene.blockMin;
  for (int i = 0; i < spec.tankWidth; ++i)
    for (int j = 0; j < spec.waterDepth; ++j)
      for (int k = 0; k < spec.tankWidth; ++k) {
        const Vec3 x = Vec3::Constant(gap) + d * Vec3(i + 0.5, j + 0.5, k + 0.5);
        const bool inside = x.x() > lo.x() && x.x() < lo.x() + width && x.z() > lo.z() &&
                            x.z() < lo.z() + width && x.y() > lo.y() - 0.25 * d &&
                            x.y() < lo.y() + height;
        if (!inside) world.particles.add(x, Vec3::Zero(), 1000 * d * d * d, 0);
      }
  addLattice(world, lo, Eigen::Vector3i(spec.blockWidth, spec.blockLayers, spec.blockWidth), d,
             scene.block);
  world.initialize();
  PipelineOptions options;
  options.solver = spec.solver;
  scene.pipeline = std::make_unique<Pipeline>(assemblePipeline(world, options));
  scene.pipeline->attach(world);
  scene.halfWidth = 0.5 * width;
  scene.footprintCentre = lo + scene.halfWidth * Vec3(1, 0, 1);
  return scene;
}

}  // namespace sim::testing
