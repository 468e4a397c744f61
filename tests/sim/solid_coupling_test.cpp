// Elastic solids coupled with the fluids: anchors under a pressure solve, fluid-only
// effects that leave the solid alone, buoyancy (INDSPH, Wang et al. 2023 Figure 8), an
// elastic-elastic drop at density ratio 1:60 (§5.2) and fluid-solid momentum exchange.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

#include "floating_block.h"
#include "scene_fixtures.h"
#include "sim/effects/viscosity_monaghan2005.h"
#include "sim/effects/viscosity_weiler2018.h"
#include "sim/effects/xsph_monaghan1989.h"
#include "solid_fixtures.h"

using namespace sim;
using namespace sim::testing;

namespace {

// Positions per particle id (the pipeline re-sorts the arrays).
std::map<std::int32_t, Vec3> positionsById(const World& world, int material) {
  std::map<std::int32_t, Vec3> out;
  const auto& p = world.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.material[i] == material) out[p.id[i]] = p.x[i];
  return out;
}

// Angular momentum about the centre of mass [kg m^2/s] of the particles of one material.
Vec3 angularMomentum(const World& world, int material) {
  const auto& p = world.particles;
  Vec3 c = Vec3::Zero(), momentum = Vec3::Zero();
  Real m = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.material[i] == material) {
      c += p.mass[i] * p.x[i];
      m += p.mass[i];
    }
  c /= m;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.material[i] == material) momentum += p.mass[i] * (p.x[i] - c).cross(p.v[i]);
  return momentum;
}

}  // namespace

TEST_CASE("anchored elastic particles stay put under a water column", "[unit][elasticity]") {
  // A block of elastic particles, all anchored, on the floor of a tank under 8 d of water: the
  // pressure solve pushes on it every step, the constrain step after it must undo that, so the
  // block's positions are bit-identical after 0.1 s (a pressure-driven velocity of even 1e-12 m/s
  // would show).
  const Real d = 0.01;
  Tank tank = hydrostaticTank(8 * d, 12 * d, d);
  World& world = *tank.world;
  // Re-build with the block: the tank fixture has one fluid; add the block material and flag the
  // lowest 4 layers of the water column as the anchored elastic block.
  const int mat = world.materials.add(elasticMaterial("anchor", 1000, 1e5, 0.3));
  const Real fifthLayer = (kWallGap - 0.5 + 4) * d;  // [m] lattice layers sit at (kWallGap + k) d
  for (std::size_t i = 0; i < world.particles.size(); ++i)
    if (world.particles.x[i].y() < fifthLayer) {
      world.particles.material[i] = mat;
      setFixed(world.particles, static_cast<Index>(i));
    }
  PipelineOptions options;
  options.solver = "indsph";
  Pipeline pipeline = assemblePipeline(world, options);
  pipeline.attach(world);
  REQUIRE(pipeline.hasStage("elasticity"));
  const auto before = positionsById(world, mat);
  REQUIRE(before.size() == 4 * 8 * 8);
  while (world.time < 0.1) pipeline.step(world);
  REQUIRE(allFinite(world));
  CHECK(positionsById(world, mat) == before);
  // The water above did move (the test is not vacuous: the solver acted in this scene).
  CHECK(maxSpeed(world) > 0);
}

TEST_CASE("XSPH and viscosity leave a rotating elastic block alone", "[unit][elasticity]") {
  // A free elastic block spinning at 10 rad/s with no gravity, with XSPH, explicit viscosity and
  // implicit viscosity all in the pipeline and a (non-physical) viscosity of 1 Pa s on the solid's
  // material: the fluid-only effects must skip it, so the run is bit-identical to the same run
  // with the elastic stage alone. Without the skip XSPH alone (eps 0.05) removes angular momentum
  // at a rate of order eps/dt x the surface fraction — percents per step here.
  const Real d = 0.01, omega = 10;  // [m], [rad/s]
  auto run = [&](bool withFluidEffects) {
    World world(solidWorldParameters(d, Box(Vec3::Constant(-1), Vec3::Constant(1)), Vec3::Zero()));
    Material m = elasticMaterial("spinner", 1000, 1e5, 0.3);
    m.dynamicViscosity = 1.0;  // [Pa s]
    const int mat = world.materials.add(m);
    addLattice(world, Vec3(-3 * d, -3 * d, -2 * d), Eigen::Vector3i(6, 6, 4), d, mat);
    for (std::size_t i = 0; i < world.particles.size(); ++i)
      world.particles.v[i] = Vec3(0, 0, omega).cross(world.particles.x[i]);
    world.initialize();
    // No pressure solver here sets p.density, which the fluid effects read: give it the value
    // every solver gives a particle at rest spacing.
    for (auto& rho : world.particles.density) rho = m.restDensity;
    std::vector<std::unique_ptr<Effect>> effects;
    if (withFluidEffects) {
      effects.push_back(std::make_unique<XsphMonaghan1989>(0.05));
      effects.push_back(std::make_unique<ViscosityMonaghan2005>(true));
    }
    effects.push_back(std::make_unique<ElasticityPeer2018>());
    if (withFluidEffects) effects.push_back(std::make_unique<ViscosityWeiler2018>());
    Pipeline pipeline(std::make_unique<NoPressureSolver>(), std::move(effects), {});
    pipeline.attach(world);
    const Vec3 start = angularMomentum(world, mat);
    while (world.time < 0.05) pipeline.step(world);
    REQUIRE(allFinite(world));
    return std::make_pair(start, angularMomentum(world, mat));
  };
  const auto alone = run(false);
  const auto coupled = run(true);
  CHECK(coupled.second == alone.second);
  // The elastic stage itself keeps the spin: within 1 % over 0.05 s (its pair forces are central
  // in the reference frame only; backward Euler with a lagged rotation loses a little).
  CHECK(alone.second.z() == Approx(alone.first.z()).epsilon(0.01));
}

namespace {

struct BodyState {
  Real minY = 1e30, maxY = -1e30;  // [m] lowest and highest particle centre
  Vec3 centre = Vec3::Zero();      // [m] centre of mass
  Real mass = 0;                   // [kg]
};

BodyState bodyState(const World& world, int material) {
  BodyState s;
  const auto& p = world.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.material[i] == material) {
      s.minY = std::min(s.minY, p.x[i].y());
      s.maxY = std::max(s.maxY, p.x[i].y());
      s.centre += p.mass[i] * p.x[i];
      s.mass += p.mass[i];
    }
  s.centre /= s.mass;
  return s;
}

// A closed-floor tank without fluid, inner size `inner` [m], for solids-only scenes on INDSPH.
std::unique_ptr<World> emptyTank(const Vec3& inner, Real d) {
  TankSpec spec;
  spec.innerMax = inner;
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = tankDomain(spec, d);
  auto world = std::make_unique<World>(params);
  addTankWalls(*world, spec, d);
  return world;
}

}  // namespace

TEST_CASE("elastic cuboid dropped on another at density ratio 1:60 settles",
          "[stability][elasticity]") {
  // Wang et al. 2023 §5.2: two elastic cuboids (E = 500 kPa) coupled only through the INDSPH
  // pressure solve reach a density ratio of 60. The paper does not say which is on top; here the
  // light one (1000 kg/m^3) falls 3 d onto the heavy one (60000) resting on the floor, upper body
  // 6 x 4 x 6, lower 8 x 4 x 8 particles. The other order is the next test (it needs an anchored
  // pad and the coupling time-step limit, docs/methods/elasticity.md "Heavy onto light").
  const Real d = 0.01, E = 5e5, nu = 0.3, drop = 3 * d;  // [m], [Pa], [1], [m]
  const Real gap = (kWallGap - 0.5) * d;                 // [m] lattice start from a wall
  {
    const Real rhoTop = 1000, rhoBottom = 60000;  // [kg/m^3]
    auto world = emptyTank(Vec3(14 * d, 20 * d, 14 * d), d);
    world->gravity = Vec3(0, -9.81, 0);
    const int bottom = world->materials.add(elasticMaterial("bottom", rhoBottom, E, nu));
    const int top = world->materials.add(elasticMaterial("top", rhoTop, E, nu));
    addLattice(*world, Vec3(3 * d, gap, 3 * d), Eigen::Vector3i(8, 4, 8), d, bottom);
    addLattice(*world, Vec3(4 * d, gap + 4 * d + drop, 4 * d), Eigen::Vector3i(6, 4, 6), d, top);
    world->initialize();
    PipelineOptions options;
    options.solver = "indsph";
    Pipeline pipeline = assemblePipeline(*world, options);
    pipeline.attach(*world);
    const BodyState top0 = bodyState(*world, top), bottom0 = bodyState(*world, bottom);
    Real minGap = 1e30, maxEnergyRatio = 0;  // [m], [1]
    while (world->time < 0.5) {
      pipeline.step(*world);
      REQUIRE(allFinite(*world));
      const BodyState t = bodyState(*world, top), b = bodyState(*world, bottom);
      minGap = std::min(minGap, t.minY - b.maxY);
      // Energy the fall released so far (both bodies, the lower one settles too) plus the
      // potential energy of the drop itself, which bounds the kinetic energy at every instant.
      const Real released = t.mass * 9.81 * (top0.centre.y() - t.centre.y()) +
                            b.mass * 9.81 * (bottom0.centre.y() - b.centre.y());
      maxEnergyRatio =
          std::max(maxEnergyRatio, kineticEnergy(*world) / (t.mass * 9.81 * drop + released));
    }
    const BodyState t = bodyState(*world, top), b = bodyState(*world, bottom);
    CAPTURE(minGap / d, maxEnergyRatio, t.centre.y() - top0.centre.y(), kineticEnergy(*world));
    // No explosion: the kinetic energy never exceeds what gravity released (ratio <= 1 exactly
    // for a dissipative scheme; 1.05 allows for the pressure solver's 1e-3 residual compression).
    CHECK(maxEnergyRatio < 1.05);
    // No interpenetration: the upper body's lowest particle never gets below the lower body's
    // highest one, i.e. no particle is more than d/2 inside the other body's volume (particles
    // stand for cubes of side d).
    CHECK(minGap > 0);
    // Settled: resting on the lower body (gap about one spacing) and kinetic energy below 1 % of
    // the drop's potential energy.
    CHECK(t.minY - b.maxY == Approx(d).margin(0.3 * d));
    CHECK(kineticEnergy(*world) < 0.01 * t.mass * 9.81 * drop);
  }
}

TEST_CASE("a dam break does not push water through an anchored elastic plate",
          "[stability][elasticity]") {
  // Momentum exchange without leaks: a water column (8 x 8 x 6 d) collapses onto an elastic plate
  // 2 d thick spanning the tank's width, anchored by its two lowest layers, 20 d tall (the run-up
  // of an 8 d column stays below 2 x 8 d). Contact is only the INDSPH pressure solve (no penalty
  // force), so a leak would show as a water particle beyond the plate's far face.
  const Real d = 0.01;  // [m]
  const Real gap = (kWallGap - 0.5) * d;
  auto world = emptyTank(Vec3(24 * d, 24 * d, 6 * d + 2 * gap), d);
  world->gravity = Vec3(0, -9.81, 0);
  const int water = world->materials.add(sim::testing::water());
  const int plate = world->materials.add(elasticMaterial("plate", 1000, 1e6, 0.3));
  addLattice(*world, Vec3(gap, gap, gap), Eigen::Vector3i(8, 8, 6), d, water);
  addLattice(*world, Vec3(14 * d, gap, gap), Eigen::Vector3i(2, 20, 6), d, plate);
  world->initialize();
  for (std::size_t i = 0; i < world->particles.size(); ++i)
    if (world->particles.material[i] == plate && world->particles.x[i].y() < gap + 2 * d)
      setFixed(world->particles, static_cast<Index>(i));
  PipelineOptions options;
  options.solver = "indsph";
  Pipeline pipeline = assemblePipeline(*world, options);
  pipeline.attach(*world);
  Real maxPlateX = 0, maxWaterBeyond = -1e30, maxBend = 0;  // [m]
  const Real plateFace0 = 16 * d - 0.5 * d;                 // [m] far particle layer at rest
  while (world->time < 0.4) {
    pipeline.step(*world);
    REQUIRE(allFinite(*world));
    Real face = -1e30, waterFront = -1e30;
    const auto& p = world->particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.material[i] == plate)
        face = std::max(face, p.x[i].x());
      else
        waterFront = std::max(waterFront, p.x[i].x());
    }
    maxPlateX = std::max(maxPlateX, face);
    maxWaterBeyond = std::max(maxWaterBeyond, waterFront - face);
    maxBend = std::max(maxBend, face - plateFace0);
  }
  CAPTURE(maxWaterBeyond / d, maxBend / d);
  // The water reached the plate (the test is not vacuous): its front came within 1.5 d of the
  // plate's near face at 14.5 d.
  CHECK(maxWaterBeyond > -3.5 * d);
  // No water particle ever got past the plate's far particle layer.
  CHECK(maxWaterBeyond < 0);
  // The plate bent (it is elastic) but stayed a plate: its far face moved less than 2 d.
  CHECK(maxBend < 2 * d);
}

TEST_CASE("a neutrally buoyant elastic block stays put in water", "[stability][elasticity]") {
  // An elastic block of the water's density (4 x 4 x 4, E = 100 kPa) in the middle of a water
  // column 12 d deep, 4 d below the surface, on INDSPH for 0.5 s. Zero net force: its height
  // relative to the water level (mean of the column tops) must stay put. Bound 1 d: the floating
  // blocks of the buoyancy benchmark sit 0.4-0.6 d too high (docs/methods/elasticity.md,
  // unexplained), so 1 d is that offset with a margin; a wrong momentum exchange (a missing or
  // one-sided pressure term) moves the block by many d in 0.5 s (free fall alone: 1.2 m). Sideways:
  // 0.5 d (the scene is symmetric; what remains is the solver's noise).
  FloatingBlockSpec spec;
  spec.d = 0.01;  // [m]
  spec.specificGravity = 1;
  spec.tankWidth = 12, spec.waterDepth = 12, spec.blockWidth = 4, spec.blockLayers = 4;  // [d]
  spec.blockBottom = 12 - 4 - 4;  // [d] its top 4 d below the surface
  spec.layeredWalls = false;
  FloatingBlock scene = floatingBlock(spec);
  const Real d = spec.d;
  World& world = *scene.world;
  Pipeline& pipeline = *scene.pipeline;
  const int water = 0, block = scene.block;
  auto relativeHeight = [&] {  // [m] block centre below the mean column top
    std::map<std::pair<int, int>, Real> top;
    const auto& p = world.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.material[i] != water) continue;
      const auto key = std::make_pair(static_cast<int>(std::floor(p.x[i].x() / d)),
                                      static_cast<int>(std::floor(p.x[i].z() / d)));
      top[key] = std::max(top.count(key) ? top[key] : -1e30, p.x[i].y());
    }
    Real level = 0;
    for (const auto& [key, y] : top) level += y;
    return bodyState(world, block).centre.y() - level / top.size();
  };
  const Vec3 centre0 = bodyState(world, block).centre;
  // The reference is taken after 0.1 s: in the first steps the lattice spreads into the 1.2 d gaps
  // left at the walls (kWallGap) and the level drops by ~1.3 d, which is the tank, not buoyancy.
  while (world.time < 0.1) pipeline.step(world);
  const Real start = relativeHeight();
  Real maxDrift = 0;  // [m]
  while (world.time < 0.5) {
    pipeline.step(world);
    REQUIRE(allFinite(world));
    maxDrift = std::max(maxDrift, std::abs(relativeHeight() - start));
  }
  const Vec3 centre = bodyState(world, block).centre;
  CAPTURE(maxDrift / d, (centre - centre0).transpose() / d);
  CHECK(maxDrift < d);
  CHECK(std::hypot(centre.x() - centre0.x(), centre.z() - centre0.z()) < 0.5 * d);
}

TEST_CASE(
    "a stiff anchored pad under a water column moves less than the suddenly loaded static bound",
    "[validation][elasticity]") {
  // A pad of tissue (6 x 3 x 6 particles, E = 500 kPa, nu = 0.45, the water's density) bonded to
  // the floor of a tank (its lowest layer anchored) under 9 d of water, INDSPH with the coupling
  // limit (couplingStepFactor 0.3), 0.15 s, d = 1 cm. Upper bound: the pad's top face moves at
  // most 2 p t / E, the uniaxial static compression under the pressure p on its top (t its
  // thickness) doubled for a suddenly applied load; a bonded, nearly incompressible layer loaded
  // on every free face moves much less (only the start-up settling of the single-layer walls
  // loads it unevenly). Measured: 0.53 p t / E. Why the limit: the elastic stage is solved before
  // the pressure solve, so a stiff layer answers the fluid's load as if softened by
  // 1 + (omega_1 dt)^2 (docs/methods/elasticity.md, "Heavy onto light"); without the limit (dt = 2
  // ms, (omega_1 dt)^2 ~ 140) this pad moves 9.5 p t / E, with it (dt = 0.17 ms) 0.53 p t / E.
  const Real d = 0.01, E = 5e5, nu = 0.45, g = 9.81;  // [m], [Pa], [1], [m/s^2]
  const Real gap = (kWallGap - 0.5) * d;
  const int width = 10, depth = 12, padSide = 6, padLayers = 3;
  TankSpec spec;
  spec.innerMax = Vec3(width * d + 2 * gap, (depth + 6) * d, width * d + 2 * gap);
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = tankDomain(spec, d);
  params.maxTimeStep = 2e-3;  // [s]
  World world(params);
  world.materials.add(sim::testing::water());
  const int pad = world.materials.add(elasticMaterial("pad", 1000, E, nu));
  addTankWalls(world, spec, d);
  const int lo = (width - padSide) / 2;
  for (int j = 0; j < depth; ++j)
    for (int k = 0; k < width; ++k)
      for (int i = 0; i < width; ++i) {
        const bool inPad =
            i >= lo && i < lo + padSide && k >= lo && k < lo + padSide && j < padLayers;
        world.particles.add(Vec3::Constant(gap) + d * Vec3(i + 0.5, j + 0.5, k + 0.5), Vec3::Zero(),
                            1000 * d * d * d, inPad ? pad : 0);
      }
  world.initialize();
  for (std::size_t i = 0; i < world.particles.size(); ++i)
    if (world.particles.material[i] == pad && world.particles.x[i].y() < gap + d)
      setFixed(world.particles, static_cast<Index>(i));
  PipelineOptions options;
  options.solver = "indsph";
  options.elasticity.couplingStepFactor = 0.3;
  Pipeline pipeline = assemblePipeline(world, options);
  pipeline.attach(world);
  const auto rest = positionsById(world, pad);
  Real maxDisplacement = 0;  // [m]
  while (world.time < 0.15) {
    pipeline.step(world);
    REQUIRE(allFinite(world));
    for (std::size_t i = 0; i < world.particles.size(); ++i)
      if (world.particles.material[i] == pad)
        maxDisplacement = std::max(maxDisplacement,
                                   (world.particles.x[i] - rest.at(world.particles.id[i])).norm());
  }
  const Real p = 1000 * g * (depth - padLayers) * d;  // [Pa] water on the pad's top face
  const Real bound = 2 * p * padLayers * d / E;       // [m]
  CAPTURE(maxDisplacement / d, bound / d, world.stepCount, pipeline.lastTimeStep().dt);
  CHECK(maxDisplacement < bound);
}

TEST_CASE("heavy elastic cuboid dropped on an anchored light one at 1:60 settles",
          "[validation][elasticity]") {
  // The other order of Wang et al. 2023 §5.2: a 60000 kg/m^3 cuboid (4 x 4 x 4) falls 1 d onto a
  // 1000 kg/m^3 pad (6 x 5 x 6), E = 500 kPa, nu = 0.3 for both, INDSPH, 0.8 s. Two things make
  // this order hard (docs/methods/elasticity.md, "Heavy onto light"):
  // - On a frictionless floor the pad is squeezed out sideways (an off-centre load lets the heavy
  //   body sink deeper near the pad's edge: the centred state is an unstable equilibrium, and
  //   round-off grows 1e-12 -> 0.5 d in two impacts). Contact here is frictionless (pressure
  //   only), so the pad's bottom layer is anchored: glued to the floor, as tissue is to the orbit.
  // - The elastic stage hands the pressure solve an impulse the pad's own inertia carries, so the
  //   pad resists with k / (1 + (omega_1 dt)^2): the coupling limit (couplingStepFactor 0.3) keeps
  //   that below 9 %. Without it the heavy body sinks 2.5x too deep and bounces with more kinetic
  //   energy than the fall released.
  const Real d = 0.01, E = 5e5, nu = 0.3, drop = 1 * d, g = 9.81;  // [m], [Pa], [1], [m], [m/s^2]
  const Real gap = (kWallGap - 0.5) * d;                           // [m] lattice start from a wall
  const Real rhoTop = 60000, rhoPad = 1000;                        // [kg/m^3]
  const int padLayers = 5;
  auto world = emptyTank(Vec3(12 * d, 16 * d, 12 * d), d);
  world->gravity = Vec3(0, -g, 0);
  const int pad = world->materials.add(elasticMaterial("pad", rhoPad, E, nu));
  const int top = world->materials.add(elasticMaterial("heavy", rhoTop, E, nu));
  addLattice(*world, Vec3(3 * d, gap, 3 * d), Eigen::Vector3i(6, padLayers, 6), d, pad);
  const Real padTop0 = gap + (padLayers - 0.5) * d;  // [m] the pad's highest particle layer
  addLattice(*world, Vec3(4 * d, padTop0 + 0.5 * d + drop, 4 * d), Eigen::Vector3i(4, 4, 4), d,
             top);
  world->initialize();
  for (std::size_t i = 0; i < world->particles.size(); ++i)
    if (world->particles.material[i] == pad && world->particles.x[i].y() < gap + d)
      setFixed(world->particles, static_cast<Index>(i));
  PipelineOptions options;
  options.solver = "indsph";
  options.elasticity.couplingStepFactor = 0.3;
  Pipeline pipeline = assemblePipeline(*world, options);
  pipeline.attach(*world);
  const BodyState top0 = bodyState(*world, top), pad0 = bodyState(*world, pad);
  const Real restCentre = padTop0 + d + 1.5 * d;  // [m] heavy centre touching the unloaded pad
  const Real fallEnergy = top0.mass * g * drop;   // [J]
  Real maxEnergyRatio = 0, minOverlap = 1e30, maxEarlyEnergy = 0, maxLateEnergy = 0;
  Real sagSum = 0;                      // [m s]
  Real sagTime = 0;                     // [s]
  const Real end = 0.8, window = 0.25;  // [s]
  const auto& p = world->particles;
  while (world->time < end) {
    const Real dt = pipeline.step(*world);
    REQUIRE(allFinite(*world));
    const BodyState t = bodyState(*world, top), b = bodyState(*world, pad);
    const Real released = t.mass * g * (top0.centre.y() - t.centre.y()) +
                          b.mass * g * (pad0.centre.y() - b.centre.y());
    const Real ke = kineticEnergy(*world);
    maxEnergyRatio = std::max(maxEnergyRatio, ke / std::max(released, fallEnergy));
    if (world->time < 0.2) maxEarlyEnergy = std::max(maxEarlyEnergy, ke);
    if (world->time > 0.55) maxLateEnergy = std::max(maxLateEnergy, ke);
    // Interpenetration, column by column: a heavy particle deeper than d/2 inside the pad's
    // surface is one below a pad particle of its own column (|dx|, |dz| < d/2), and the same pair
    // measures a pad particle inside the heavy body's surface.
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.material[i] != top) continue;
      for (std::size_t j = 0; j < p.size(); ++j)
        if (p.material[j] == pad && std::abs(p.x[i].x() - p.x[j].x()) < 0.5 * d &&
            std::abs(p.x[i].z() - p.x[j].z()) < 0.5 * d)
          minOverlap = std::min(minOverlap, p.x[i].y() - p.x[j].y());
    }
    if (world->time > end - window) {
      sagSum += dt * (restCentre - t.centre.y());
      sagTime += dt;
    }
  }
  const Real sag = sagSum / sagTime;  // [m] mean compression of the pad over the last 0.25 s
  // Static 1-D estimate: the heavy body's weight over its footprint, sigma = rho g H, compresses
  // the pad's height L by sigma L / E' with E' = 3 mu (the pressure solve keeps every dynamic
  // particle at its rest number density, so the pad deforms at constant volume: nu_eff = 1/2).
  const Real mu = E / (2 * (1 + nu));                      // [Pa]
  const Real sigma = rhoTop * g * 4 * d;                   // [Pa]
  const Real estimate = sigma * padLayers * d / (3 * mu);  // [m]
  CAPTURE(maxEnergyRatio, minOverlap / d, sag / d, estimate / d, maxEarlyEnergy, maxLateEnergy,
          pipeline.lastTimeStep().dt, world->stepCount);
  // No explosion: kinetic energy never above what gravity released (5 % for the pressure
  // solver's residual compression, as in the light-onto-heavy test).
  CHECK(maxEnergyRatio < 1.05);
  // No interpenetration: every heavy particle stays above the pad particles of its column.
  CHECK(minOverlap > 0);
  // Settles: the bounce dies down. Nothing in the model is a material damping; what dissipates is
  // the pressure solve's inelastic particle contact at each landing (the body leaves the pad near
  // the top of each oscillation, period ~0.09 s). Asserted: the kinetic energy after 0.55 s peaks
  // below half of its peak in the first 0.2 s (measured 0.23; without the coupling limit the
  // bounce grows instead: 1.24, with a kinetic energy 2.2x what the fall released and the heavy
  // body 0.73 d inside the pad).
  CHECK(maxLateEnergy < 0.5 * maxEarlyEnergy);
  // Static compression within 25 % of the 1-D estimate: the coupling limit allows 9 %, the
  // footprint (4 x 4 on 6 x 6: the rim stiffens the pad) and the averaging of a still decaying
  // oscillation over ~2.7 periods (bias up to ~10 % of the estimate) the rest. Measured: -5 %.
  CHECK(sag == Approx(estimate).epsilon(0.25));
}

namespace {

// Couette cell for the fluid-solid viscous drag (explicit viscosity): a heavy elastic plate (2
// layers) under a fluid layer of `fluidLayers`, optionally an anchored elastic lid above it, no
// gravity, no pressure solve (plane shear flow is divergence-free), d = 1 mm, the fluid's
// kinematic viscosity 0.01 m^2/s. The plate starts at `speed` along x, the fluid at rest.
struct CouetteCell {
  std::unique_ptr<World> world;
  int fluid = 0, plate = 0, lid = -1;
  Real bottomLayer = 0, topLayer = 0;  // [m] y of the plate's upper and the lid's lower layer
};

CouetteCell couetteCell(bool withLid, Real speed) {
  const Real d = 1e-3;                                // [m]
  const int length = 24, depth = 8, fluidLayers = 8;  // [particles] along x, z, y
  CouetteCell c;
  c.world = std::make_unique<World>(
      solidWorldParameters(d, Box(Vec3::Constant(-0.01), Vec3::Constant(0.04)), Vec3::Zero()));
  World& w = *c.world;
  Material fluid = sim::testing::water();
  fluid.dynamicViscosity = 10.0;  // [Pa s]: nu = 0.01 m^2/s, diffusion time H^2/nu ~ 8 ms
  c.fluid = w.materials.add(fluid);
  // Heavy plate (100x the fluid's density): it loses ~1 % of its speed to the fluid.
  c.plate = w.materials.add(elasticMaterial("plate", 1e5, 1e6, 0.3));
  addLattice(w, Vec3::Zero(), Eigen::Vector3i(length, 2, depth), d, c.plate, Vec3(speed, 0, 0));
  addLattice(w, Vec3(0, 2 * d, 0), Eigen::Vector3i(length, fluidLayers, depth), d, c.fluid);
  c.bottomLayer = 1.5 * d;
  c.topLayer = (2 + fluidLayers + 0.5) * d;
  if (withLid) {
    c.lid = w.materials.add(elasticMaterial("lid", 1e5, 1e6, 0.3));
    addLattice(w, Vec3(0, (2 + fluidLayers) * d, 0), Eigen::Vector3i(length, 2, depth), d, c.lid);
  }
  w.initialize();
  auto& p = w.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    // No pressure solver sets p.density, which the viscosity reads: the rest density.
    p.density[i] = w.materials[p.material[i]].restDensity;
    if (p.material[i] == c.lid) setFixed(p, static_cast<Index>(i));
  }
  return c;
}

Pipeline couettePipeline(World& world) {
  std::vector<std::unique_ptr<Effect>> effects;
  effects.push_back(std::make_unique<ViscosityMonaghan2005>(false));
  effects.push_back(std::make_unique<ElasticityPeer2018>());
  Pipeline pipeline(std::make_unique<NoPressureSolver>(), std::move(effects), {});
  pipeline.attach(world);
  return pipeline;
}

Vec3 totalMomentum(const World& world) {
  Vec3 m = Vec3::Zero();
  const auto& p = world.particles;
  for (std::size_t i = 0; i < p.size(); ++i) m += p.mass[i] * p.v[i];
  return m;
}

}  // namespace

TEST_CASE("fluid-solid viscous drag exchanges momentum exactly", "[unit][elasticity]") {
  // Plate sliding under a free fluid layer, no lid: the drag is the only force between the two,
  // equal and opposite pair by pair, and the elastic stage keeps each body's momentum, so the
  // total momentum stays what it was to round-off (relative 1e-12: ~100 steps of sums over ~2000
  // terms of 1e-16 relative error each), while the fluid picks up momentum (not vacuous).
  CouetteCell c = couetteCell(false, 0.01);
  Pipeline pipeline = couettePipeline(*c.world);
  const Vec3 start = totalMomentum(*c.world);
  for (int s = 0; s < 100; ++s) pipeline.step(*c.world);
  REQUIRE(allFinite(*c.world));
  Vec3 fluidMomentum = Vec3::Zero();
  const auto& p = c.world->particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.material[i] == c.fluid) fluidMomentum += p.mass[i] * p.v[i];
  CAPTURE(start.transpose(), totalMomentum(*c.world).transpose(), fluidMomentum.transpose());
  CHECK((totalMomentum(*c.world) - start).norm() < 1e-12 * start.norm());
  CHECK(fluidMomentum.x() > 0.01 * start.x());
}

TEST_CASE("an elastic plate sliding under a fluid layer drags it into a Couette profile",
          "[validation][elasticity]") {
  // The plate moves at U = 1 cm/s under 8 fluid layers, an anchored elastic lid on top: the fluid
  // sees both as walls (moving, at rest), so after a few diffusion times H^2 / (pi^2 nu) (0.8 ms;
  // run 8 ms) the profile is linear, u(y) = U_plate (y_lid - y) / (y_lid - y_plate), between the
  // solids' nearest particle layers. Measured per fluid layer over the central columns (>= 4 d
  // from the cell's x ends, >= 2 d from its z faces, which have no neighbours beyond). Tolerance
  // 0.1 U: the no-slip planes of a particle wall sit within ~d/2 of its layer, i.e. within
  // 0.5 / 9 = 6 % of U of the assumed line.
  const Real U = 0.01, d = 1e-3;  // [m/s], [m]
  CouetteCell c = couetteCell(true, U);
  Pipeline pipeline = couettePipeline(*c.world);
  while (c.world->time < 8e-3) pipeline.step(*c.world);
  REQUIRE(allFinite(*c.world));
  const auto& p = c.world->particles;
  std::map<int, std::pair<Real, int>> layers;  // layer index -> (sum of u_x, count)
  Real plateSpeed = 0;
  int plateCount = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.material[i] == c.plate) {
      plateSpeed += p.v[i].x();
      ++plateCount;
    }
    if (p.material[i] != c.fluid) continue;
    if (p.x[i].x() < 4 * d || p.x[i].x() > 20 * d || p.x[i].z() < 2 * d || p.x[i].z() > 6 * d)
      continue;
    auto& l = layers[static_cast<int>(std::floor(p.x[i].y() / d))];
    l.first += p.v[i].x();
    ++l.second;
  }
  plateSpeed /= plateCount;
  REQUIRE(layers.size() == 8);
  Real maxError = 0;  // [m/s]
  for (const auto& [k, l] : layers) {
    const Real y = (k + 0.5) * d;
    const Real expected = plateSpeed * (c.topLayer - y) / (c.topLayer - c.bottomLayer);
    const Real u = l.first / l.second;
    CAPTURE(k, u / U, expected / U);
    maxError = std::max(maxError, std::abs(u - expected));
  }
  CAPTURE(plateSpeed / U, maxError / U, c.world->stepCount);
  CHECK(maxError < 0.1 * U);
  // The plate pays for the fluid's momentum (and the lid's drag): it slowed, by at most a few %.
  CHECK(plateSpeed < U);
  CHECK(plateSpeed > 0.9 * U);
}
