// The implicit viscosity stage allocates nothing once attached (the engine rule "allocate in
// attach()"; docs/developer-guide.md code rule 9). A separate executable, because counting
// allocations replaces the global operator new for the whole program.
#include <catch2/catch.hpp>

#include "allocation_counter.h"
#include "scene_fixtures.h"
#include "sim/effects/viscosity_weiler2018.h"
#include "sim/fluid/density.h"
#include "sim/fluid/vslsph_li2023.h"

using namespace sim;

TEST_CASE("implicit viscosity allocates nothing after attach()", "[unit][viscosity]") {
  const Real d = 0.002;  // [m]
  WorldParameters params;
  params.particleSpacing = d;
  params.gravity = Vec3::Zero();
  params.domain = Box(Vec3::Constant(-0.01), Vec3::Constant(0.03));
  World w(params);
  Material oil;
  oil.name = "oil";
  oil.restDensity = 970;        // [kg/m^3]
  oil.dynamicViscosity = 0.97;  // [Pa s] 1000 cSt
  w.materials.add(oil);
  // a plate under the blob, so that the wall term runs too
  for (int a = -2; a < 10; ++a)
    for (int c = -2; c < 10; ++c) w.walls.add(Vec3(a * d, -0.7 * d, c * d), Vec3(0, -1, 0));
  addFluidBlock(w, Vec3(0, 0.5 * d, 0), Vec3(8 * d, 8.5 * d, 8 * d), d, 0);
  for (Index i = 0; i < w.particles.size(); ++i)
    w.particles.v[i] = Vec3(0.01 * std::sin(400.0 * w.particles.x[i].y()), 0, 0);
  w.initialize();
  computeDensities(w, w.particles.density);
  ViscosityWeiler2018 stage;
  stage.attach(w);
  counting = true;
  for (int s = 0; s < 3; ++s) stage.apply(w, StepContext{0.004});
  counting = false;
  INFO("CG iterations of the last solve: " << stage.lastIterations());
  CHECK(stage.lastIterations() > 0);  // it did solve something
  CHECK(allocations.load() == 0);
}

// The VSLSPH solver's part of a step (neighbour update with per-particle supports, densities,
// supports, forces) allocates nothing once the lists have grown to the scene's size. The solver is
// driven directly; the whole Pipeline::step around it is test_pipeline_allocation.cpp's.
TEST_CASE("VSLSPH steps allocate nothing after warm-up", "[unit][solvers]") {
  auto tank = testing::hydrostaticTank(0.03, 0.03, 0.005);
  World& w = *tank.world;
  VslsphParameters params;
  params.speedOfSound = 10 * std::sqrt(2 * 9.81 * 0.03);  // [m/s]
  VslsphLi2023 solver(params);
  solver.attach(w);
  const Real dt = solver.maxTimeStep(w);  // [s]
  auto step = [&] {
    w.updateNeighbors();
    solver.beginStep(w, StepContext{dt});
    for (Index i = 0; i < w.particles.size(); ++i) w.particles.v[i] += dt * w.gravity;
    solver.correctVelocities(w, StepContext{dt});
    for (Index i = 0; i < w.particles.size(); ++i) w.particles.x[i] += dt * w.particles.v[i];
  };
  for (int s = 0; s < 40; ++s) step();  // warm-up: the lists reach their size, one Z-order sort
  counting = true;
  for (int s = 0; s < 20; ++s) step();  // includes a Z-order sort (every 16 updates)
  counting = false;
  CHECK(solver.stats().maxCompression > 0);  // the column has met the floor: pressures acted
  CHECK(allocations.load() == 0);
}
