// Conservation and input checks of the engine (validations 3 and 4).
//
// Linear momentum: with no walls and no gravity, every force the pressure solvers, the viscosity
// and the velocity smoothing apply is a sum of pair terms that are equal and opposite
// (m_i a_ij = -m_j a_ji: antisymmetric kernel gradient, symmetric pair coefficient), so the total
// momentum can only change by floating-point round-off. Each pair term is evaluated twice (once
// from each side) with products in a different order, so the two halves differ by a few ulps of
// the term; summed over ~30 neighbours x 1000 particles x 20 steps the drift is ~1e-15..1e-14 of
// sum m|v|. The bound 1e-12 of sum m|v| is round-off with two orders of margin, and a single
// non-antisymmetric term (e.g. a missing m_j, or a one-sided wall term) shows up at 1e-3 or more.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "scene_fixtures.h"
#include "sim/fluid/density.h"
#include "sim/scenes/dam_break.h"
#include "solid_fixtures.h"

using namespace sim;
using Catch::Matchers::Contains;

namespace {

// A 10 x 10 x 10 lattice blob of water (d = 1 cm) with random velocities up to 5 cm/s in a large
// empty domain, no walls, no gravity. `dynamicViscosity` [Pa s]: water's 1e-3 Pa s barely acts
// over 20 steps, so the viscosity test uses a syrup-like 0.5 Pa s that changes the velocities
// as much as the pressure does.
std::unique_ptr<World> randomBlob(Real dynamicViscosity = 1e-3) {
  const Real d = 0.01;  // [m]
  WorldParameters params;
  params.particleSpacing = d;
  params.gravity = Vec3::Zero();
  params.domain = Box(Vec3::Constant(-0.5), Vec3::Constant(0.6));
  auto world = std::make_unique<World>(params);
  Material fluid = testing::water();
  fluid.dynamicViscosity = dynamicViscosity;
  world->materials.add(fluid);
  addFluidBlock(*world, Vec3::Zero(), Vec3::Constant(10 * d), d, 0);
  std::mt19937 rng(42);
  std::uniform_real_distribution<Real> u(-0.05, 0.05);
  for (Vec3& v : world->particles.v) v = Vec3(u(rng), u(rng), u(rng));
  world->initialize();
  return world;
}

Real sumMassSpeed(const World& w) {  // [kg m/s] sum m|v|
  Real s = 0;
  for (std::size_t i = 0; i < w.particles.size(); ++i)
    s += w.particles.mass[i] * w.particles.v[i].norm();
  return s;
}

// Runs 20 steps with the given stages and returns max |P(t) - P(0)| / sum m|v|.
Real momentumDrift(const std::string& solver, bool viscosity, bool smoothing) {
  auto world = randomBlob(viscosity ? 0.5 : 1e-3);
  PipelineOptions options;
  options.solver = solver;
  options.wcsph.speedOfSound = 2.0;  // [m/s] 40x the largest initial speed
  options.forced["viscosity"] = viscosity ? StageOverride::kOn : StageOverride::kOff;
  options.forced["velocity_smoothing"] = smoothing ? StageOverride::kOn : StageOverride::kOff;
  if (smoothing) options.velocitySmoothing = 0.5;  // strong, so a defect would be large
  Pipeline pipeline = assemblePipeline(*world, options);
  pipeline.attach(*world);
  REQUIRE(pipeline.hasStage("viscosity") == viscosity);
  REQUIRE(pipeline.hasStage("velocity_smoothing") == smoothing);
  REQUIRE_FALSE(pipeline.hasStage("gravity"));
  const Vec3 p0 = linearMomentum(*world);
  const std::vector<Vec3> v0ById = world->particles.v;  // ids are creation indices before sorting
  Real drift = 0;
  for (int s = 0; s < 20; ++s) {
    pipeline.step(*world);
    drift = std::max(drift, (linearMomentum(*world) - p0).norm() / sumMassSpeed(*world));
  }
  // The stages must actually have acted, or a zero drift proves nothing: the summed change of
  // individual momenta, sum m|v - v0|, must be a visible fraction of sum m|v0|.
  const auto& p = world->particles;
  Real changed = 0, total = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& v0 = v0ById[static_cast<std::size_t>(p.id[i])];
    changed += p.mass[i] * (p.v[i] - v0).norm();
    total += p.mass[i] * v0.norm();
  }
  std::printf("momentum %s%s%s: drift %.2e of sum m|v|, stages changed %.2e of sum m|v0|\n",
              solver.c_str(), viscosity ? "+viscosity" : "", smoothing ? "+smoothing" : "", drift,
              changed / total);
  CHECK(changed / total > 1e-3);
  return drift;
}

constexpr Real kRoundOff = 1e-12;  // [1] see the file comment

}  // namespace

TEST_CASE("pressure forces conserve linear momentum to round-off", "[unit][conservation]") {
  // VSLSPH: its kernel-averaged gradient is antisymmetric and its lists symmetric (eq. 17).
  for (const std::string solver : {"wcsph", "dfsph", "vslsph"}) {
    const Real drift = momentumDrift(solver, false, false);
    INFO(solver << ": relative momentum drift " << drift);
    CHECK(drift < kRoundOff);
  }
}

TEST_CASE("viscosity conserves linear momentum to round-off", "[unit][conservation]") {
  const Real drift = momentumDrift("wcsph", true, false);
  INFO("relative momentum drift " << drift);
  CHECK(drift < kRoundOff);
}

TEST_CASE("velocity smoothing conserves linear momentum to round-off", "[unit][conservation]") {
  const Real drift = momentumDrift("dfsph", false, true);
  INFO("relative momentum drift " << drift);
  CHECK(drift < kRoundOff);
}

// The momentum test must be able to fail: the same blob with gravity on gains momentum at once.
TEST_CASE("momentum drift measure detects an external force", "[unit][conservation]") {
  auto world = randomBlob();
  world->gravity = Vec3(0, -9.81, 0);
  PipelineOptions options;
  options.solver = "wcsph";
  options.wcsph.speedOfSound = 2.0;
  Pipeline pipeline = assemblePipeline(*world, options);
  pipeline.attach(*world);
  REQUIRE(pipeline.hasStage("gravity"));
  const Vec3 p0 = linearMomentum(*world);
  pipeline.step(*world);
  CHECK((linearMomentum(*world) - p0).norm() / sumMassSpeed(*world) > 1e-6);
}

// ---- bad parameters (validation 4): SimError with a message naming the problem ----

TEST_CASE("non-positive spacing is rejected", "[unit][bad_input]") {
  WorldParameters p;
  p.domain = Box(Vec3::Zero(), Vec3::Ones());
  for (Real d : {0.0, -0.01, std::numeric_limits<Real>::quiet_NaN()}) {
    p.particleSpacing = d;
    CHECK_THROWS_AS(p.validate(), SimError);
    CHECK_THROWS_WITH(p.validate(), Contains("particle spacing must be a positive length"));
    CHECK_THROWS_AS(World(p), SimError);
  }
}

TEST_CASE("non-positive rest density is rejected", "[unit][bad_input]") {
  MaterialTable table;
  for (Real rho : {0.0, -1000.0}) {
    Material m = testing::water();
    m.restDensity = rho;
    CHECK_THROWS_AS(table.add(m), SimError);
    CHECK_THROWS_WITH(table.add(m), Contains("water") && Contains("rest density must be > 0"));
  }
}

TEST_CASE("bad time step bounds are rejected", "[unit][bad_input]") {
  WorldParameters p;
  p.particleSpacing = 0.01;
  p.domain = Box(Vec3::Zero(), Vec3::Ones());
  p.minTimeStep = 0;
  CHECK_THROWS_WITH(p.validate(), Contains("minimum time step must be > 0"));
  p.minTimeStep = -1e-5;
  CHECK_THROWS_AS(p.validate(), SimError);
  p.minTimeStep = 1e-4;
  p.maxTimeStep = 1e-5;
  CHECK_THROWS_WITH(p.validate(), Contains("maximum time step must be >= the minimum"));
  p.maxTimeStep = 1e-3;
  CHECK_NOTHROW(p.validate());
}

TEST_CASE("particles outside the domain are rejected at initialize", "[unit][bad_input]") {
  WorldParameters p;
  p.particleSpacing = 0.01;
  p.domain = Box(Vec3::Zero(), Vec3::Constant(0.1));
  SECTION("a dynamic particle") {
    World w(p);
    w.materials.add(testing::water());
    w.particles.add(Vec3::Constant(0.05), Vec3::Zero(), 1e-3, 0);
    w.particles.add(Vec3(0.05, 0.2, 0.05), Vec3::Zero(), 1e-3, 0);
    CHECK_THROWS_AS(w.initialize(), SimError);
    try {
      w.initialize();
    } catch (const SimError& e) {
      CHECK_THAT(e.what(), Contains("water particle (id 1)") &&
                               Contains("outside the simulation domain") &&
                               Contains("at the start"));
    }
  }
  SECTION(
      "a dynamic particle that leaves during the run names its material, time and likely cause") {
    p.gravity = Vec3::Zero();
    World w(p);
    w.materials.add(testing::water());
    w.materials.add(testing::elasticMaterial("fat", 900.0, 1e3, 0.45));  // E [Pa], nu
    w.particles.add(Vec3::Constant(0.05), Vec3::Zero(), 1e-3, 0);
    w.particles.add(Vec3(0.05, 0.05, 0.02), Vec3::Zero(), 0.9e-3, 1);
    w.initialize();
    for (const int material : {0, 1}) {
      // Index of that material's particle (initialize may have re-sorted them).
      const std::size_t i = w.particles.material[0] == material ? 0 : 1;
      const Vec3 inside = w.particles.x[i];
      w.particles.x[i] = Vec3(0.05, -0.01, 0.05);  // moved out
      w.stepCount = 7;
      w.time = 0.25;
      try {
        w.updateNeighbors();
        FAIL("no error for a particle outside the domain");
      } catch (const SimError& e) {
        INFO(e.what());
        CHECK_THAT(e.what(),
                   Contains(material == 0 ? "water particle (id 0)" : "fat particle (id 1)") &&
                       Contains("left the simulation domain at t = 0.25 s (step 7)") &&
                       Contains(material == 0 ? "through a wall" : "too soft for its load"));
      }
      w.particles.x[i] = inside;
    }
  }
  SECTION("a wall particle") {
    World w(p);
    w.materials.add(testing::water());
    w.particles.add(Vec3::Constant(0.05), Vec3::Zero(), 1e-3, 0);
    w.walls.add(Vec3(-0.1, 0.05, 0.05));
    CHECK_THROWS_WITH(w.initialize(), Contains("wall particle 0") && Contains("outside"));
  }
}

TEST_CASE("dam break scene rejects bad input", "[unit][bad_input]") {
  DamBreakSpec spec;
  spec.spacing = 0;
  CHECK_THROWS_WITH(buildDamBreak(spec), Contains("spacing must be in (0, a/4]"));
  spec = DamBreakSpec{};
  spec.columnWidth = -0.05;
  CHECK_THROWS_WITH(buildDamBreak(spec), Contains("column width a must be > 0"));
  spec = DamBreakSpec{};
  spec.solver = "sph-magic";
  CHECK_THROWS_AS(buildDamBreak(spec), SimError);
  CHECK_THROWS_WITH(buildDamBreak(spec), Contains("unknown solver 'sph-magic'"));
  spec = DamBreakSpec{};
  spec.initialDensityRatio = 0;
  CHECK_THROWS_WITH(buildDamBreak(spec), Contains("initial density ratio must be > 0"));
}

// The column starts at the asked fraction of the rest density (what `bench engine
// --initial-density` sets). Closed form: on a cubic lattice of spacing d the cubic spline of
// support 2d sums to 0.99997 / d^3 (the 123 lattice points within 2d), so an interior particle of
// mass R rho0 d^3 reads R rho0 to 3e-5; the bound 1e-4 leaves room for that and round-off, and a
// mass that ignored R would miss by 0.2.
TEST_CASE("dam break column starts at its initial density ratio", "[unit][scene]") {
  for (const Real ratio : {1.0, 0.8}) {
    DamBreakSpec spec;
    spec.spacing = spec.columnWidth / 8;
    spec.depth = spec.columnWidth;
    spec.initialDensityRatio = ratio;
    DamBreakScene scene = buildDamBreak(spec);
    World& w = *scene.world;
    std::vector<Real> density;
    computeDensities(w, density);
    // The particle nearest the column's centroid: more than 2d from every wall and the surface.
    Vec3 centre = Vec3::Zero();
    for (const Vec3& x : w.particles.x) centre += x;
    centre /= static_cast<Real>(w.particles.size());
    Index nearest = 0;
    for (Index i = 0; i < static_cast<Index>(w.particles.size()); ++i)
      if ((w.particles.x[i] - centre).norm() < (w.particles.x[nearest] - centre).norm())
        nearest = i;
    const Real rho0 = w.materials[0].restDensity;
    CHECK(density[nearest] / rho0 == Approx(ratio).margin(1e-4));
  }
}
