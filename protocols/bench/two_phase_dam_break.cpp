#include "protocols/bench/two_phase_dam_break.h"

#include <cmath>

#include "sim/core/error.h"

namespace protocols {
namespace {

constexpr double kWallGap = 1.2;  // [d] as sim/scenes/dam_break.cpp

sim::Material fluid(const char* name, double density) {
  sim::Material m;
  m.name = name;
  m.restDensity = density;    // [kg/m^3]
  m.dynamicViscosity = 1e-3;  // [Pa s] water-like for both: the comparison is about density
  return m;
}

}  // namespace

TwoPhaseDamBreak buildTwoPhaseDamBreak(const TwoPhaseDamBreakSpec& spec) {
  const double a = spec.columnWidth, d = spec.spacing;
  if (!(a > 0) || !(d > 0) || d > a / 4 || !(spec.depth >= 4 * d) || !(spec.densityRatio >= 1) ||
      !(spec.heavyDensity > 0))
    throw sim::SimError(
        "two-phase dam break: need a > 0, 0 < d <= a/4, depth >= 4 d, density "
        "ratio >= 1 (got a = " +
        std::to_string(a) + " m, d = " + std::to_string(d) + " m, depth = " +
        std::to_string(spec.depth) + " m, ratio = " + std::to_string(spec.densityRatio) + ")");
  bool known = false;
  for (const auto& s : sim::solverRegistry()) known = known || s.name == spec.solver;
  if (!known) throw sim::SimError("two-phase dam break: unknown solver '" + spec.solver + "'");

  TwoPhaseDamBreak scene;
  scene.spec = spec;
  const double gap = (kWallGap - 0.5) * d;  // [m] lattice cells are centred
  const double height = 2 * a;              // [m]
  scene.tank.innerMin = sim::Vec3::Zero();
  scene.tank.innerMax = sim::Vec3(4 * a + 2 * gap, 3 * a, spec.depth + 2 * gap);
  scene.tank.closedTop = true;  // the light phase is thrown high at 1:75; a lid keeps it in
  sim::WorldParameters params;
  params.particleSpacing = d;
  params.gravity = sim::Vec3(0, -spec.gravity, 0);
  params.domain = sim::tankDomain(scene.tank, d);
  scene.world = std::make_unique<sim::World>(params);
  sim::World& world = *scene.world;
  world.materials.add(fluid("heavy", spec.heavyDensity));
  world.materials.add(fluid("light", spec.heavyDensity / spec.densityRatio));
  sim::addTankWalls(world, scene.tank, d);
  sim::addFluidBlock(world, sim::Vec3::Constant(gap),
                     sim::Vec3(gap + a, gap + height, gap + spec.depth), d, 0);
  sim::addFluidBlock(world, sim::Vec3(gap + a, gap, gap),
                     sim::Vec3(gap + 2 * a, gap + height, gap + spec.depth), d, 1);
  world.initialize();
  for (std::size_t i = 0; i < world.particles.size(); ++i)
    scene.potentialEnergy += world.particles.mass[i] * spec.gravity * world.particles.x[i].y();

  scene.options.solver = spec.solver;
  // Ritter's front speed 2 sqrt(g H) bounds the flow; c = 10 u_max keeps WCSPH's (and the
  // number-density baseline's) density error near 1 % (Becker & Teschner 2007, section 4).
  scene.options.wcsph.speedOfSound = 10 * 2 * std::sqrt(spec.gravity * height);
  return scene;
}

}  // namespace protocols
