#include "sim/scenes/dam_break.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/core/error.h"

namespace sim {

namespace {

// Gap between a surface-sampled wall and the first lattice particle centre, in spacings (as
// tests/sim/scene_fixtures.h kWallGap): at exactly d the Akinci wall term over-estimates the
// density by 6 % on a face and 15 % in a corner, and the column would start with a pressure shock.
constexpr Real kWallGap = 1.2;

// Water at 20 C (reference-data.md): the experiment's liquid.
Material damBreakWater() {
  Material m;
  m.name = "water";
  m.restDensity = 998.2;        // [kg/m^3]
  m.dynamicViscosity = 1.0e-3;  // [Pa s]
  return m;
}

}  // namespace

DamBreakScene buildDamBreak(const DamBreakSpec& spec) {
  const Real a = spec.columnWidth, d = spec.spacing;
  require(std::isfinite(a) && a > 0,
          "dam break: column width a must be > 0 m (got " + std::to_string(a) + ")");
  require(
      std::isfinite(d) && d > 0 && d <= a / 4,
      "dam break: spacing must be in (0, a/4] so the column is at least 4 particles wide (got " +
          std::to_string(d) + " m for a = " + std::to_string(a) + " m)");
  require(spec.heightRatio > 0, "dam break: height ratio n^2 must be > 0");
  require(spec.tankLengthRatio > 1.5, "dam break: the tank must be longer than 1.5 a");
  require(spec.depth >= 0, "dam break: depth must be >= 0 m (0 = quasi-2D slab)");
  require(spec.gravity > 0, "dam break: gravity must be > 0 m/s^2");
  // Rejects unknown solver names before building anything.
  bool known = false;
  for (const auto& s : solverRegistry()) known = known || s.name == spec.solver;
  require(known, "dam break: unknown solver '" + spec.solver + "' (see sim::solverRegistry())");

  DamBreakScene scene;
  scene.spec = spec;
  const Real depth = spec.depth > 0 ? spec.depth : 4 * d;
  const Real height = spec.heightRatio * a;
  const Real gap = (kWallGap - 0.5) * d;  // lattice cells are centred: first particle at min + d/2

  // The column occupies x in [backWall + gap, backWall + gap + a]: its front face is at Z = 1 +
  // gap/a, within d/a of the experiment's Z = 1.
  scene.tank.innerMin = Vec3::Zero();
  scene.tank.innerMax = Vec3(spec.tankLengthRatio * a, 1.5 * height, depth + 2 * gap);
  scene.backWall = 0.0;

  WorldParameters params;
  params.particleSpacing = d;
  params.kernel = spec.kernel;
  params.cachePairKernels = spec.cachePairKernels;
  params.gravity = Vec3(0, -spec.gravity, 0);
  params.domain = tankDomain(scene.tank, d);
  scene.world = std::make_unique<World>(params);
  World& world = *scene.world;
  world.materials.add(damBreakWater());
  addTankWalls(world, scene.tank, d);
  addFluidBlock(world, Vec3::Constant(gap), Vec3(gap + a, gap + height, gap + depth), d, 0,
                spec.initialDensityRatio);
  world.initialize();

  scene.options.solver = spec.solver;
  // Free-slip walls: see the header (2D experiment in a wide channel, boundary layer << d).
  scene.options.wallFriction = false;
  // Fastest flow: the Ritter (1892) shallow-water front speed 2 sqrt(g H) bounds the surge;
  // c = 10 u_max keeps WCSPH density errors near 1 % (Becker & Teschner 2007, section 4).
  scene.options.wcsph.speedOfSound = 10 * 2 * std::sqrt(spec.gravity * height);
  scene.timeScale = 1.0 / (std::sqrt(spec.heightRatio) * std::sqrt(spec.gravity / a));
  return scene;
}

Real surgeFront(const DamBreakScene& scene, Index minNeighbors) {
  const World& world = *scene.world;
  const NeighborList& nb = world.fluidNeighbors();
  const auto& x = world.particles.x;
  Real front = -std::numeric_limits<Real>::infinity();
  for (Index i = 0; i < static_cast<Index>(x.size()); ++i)
    if (static_cast<Index>(nb.end(i) - nb.begin(i)) >= minNeighbors)
      front = std::max(front, x[i].x());
  const Real d = world.particleSpacing();
  return (front + 0.5 * d - scene.backWall) / scene.spec.columnWidth;
}

}  // namespace sim
