// The background_pressure stage (sim/effects/background_pressure.h) - its rule, its
// time-step limit and the invariants of its force on a static lattice. The physics check (the
// Laplace jump it restores under INDSPH) is in interface_laplace.cpp.
#include <catch2/catch.hpp>

#include <cmath>

#include "interface_fixtures.h"
#include "sim/effects/background_pressure.h"
#include "sim/fluid/indsph_wang2023.h"
#include "sim/world/pair_loop.h"

using namespace sim;
using Catch::Matchers::Contains;

namespace {

testing::DropletScene closedDroplet() {
  testing::DropletSpec s;
  s.radius = 0.003;
  s.spacing = s.radius / 6;
  s.halfWidth = s.radius + 3 * 2 * s.spacing;
  s.sigma = 0.04;
  s.massExcess = 0;
  return testing::dropletScene(s);
}

const StageDecision& decision(const Pipeline& p, const std::string& name) {
  for (const auto& d : p.decisions())
    if (d.name == name) return d;
  FAIL("no decision for " << name);
  return p.decisions().front();
}

}  // namespace

TEST_CASE("background_pressure runs in closed INDSPH scenes with interfacial tension only",
          "[unit][interface]") {
  auto scene = closedDroplet();
  World& w = *scene.world;
  REQUIRE(countFreeSurfaceParticles(w) == 0);
  PipelineOptions o;
  o.solver = "indsph";
  {
    const Pipeline p = assemblePipeline(w, o);
    CHECK(p.hasStage("background_pressure"));
    // p_bg = 2 sigma / d = 2 * 0.04 / 0.5e-3 = 160 Pa, named in the plan's reason.
    CHECK_THAT(decision(p, "background_pressure").reason, Contains("p_bg = 160 Pa"));
  }
  o.solver = "wcsph";
  o.wcsph.speedOfSound = 1.0;
  CHECK_FALSE(assemblePipeline(w, o).hasStage("background_pressure"));
  o.solver = "indsph";
  o.backgroundPressure = 0;
  CHECK_FALSE(assemblePipeline(w, o).hasStage("background_pressure"));
  o.backgroundPressure = -1;
  o.forced["background_pressure"] = StageOverride::kOff;
  CHECK_FALSE(assemblePipeline(w, o).hasStage("background_pressure"));
  o.forced.clear();
  // With an elastic material the rule keeps it off (docs/methods/interface.md, validation 1b).
  Material tissue;
  tissue.name = "tissue";
  tissue.kind = MaterialKind::kElastic;
  tissue.restDensity = 1000;
  tissue.youngsModulus = 1e5;
  tissue.poissonRatio = 0.3;
  w.particles.material[0] = w.materials.add(tissue);
  const Pipeline elastic = assemblePipeline(w, o);
  CHECK_FALSE(elastic.hasStage("background_pressure"));
  CHECK_THAT(decision(elastic, "background_pressure").reason, Contains("elastic material"));
}

TEST_CASE("background_pressure stays off where a free surface exists", "[unit][interface]") {
  // Open tank: aqueous below, oil above, the oil's top layer is a free surface.
  TankSpec tank;
  const Real d = 0.5e-3;
  tank.innerMax = Vec3(10 * d, 20 * d, 10 * d);
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = tankDomain(tank, d);
  World w(params);
  const int oil = w.materials.add(testing::liquid("oil", 970, 0.05));
  const int aqueous = w.materials.add(testing::liquid("aqueous", 1000, 0.05));
  w.materials.setInterfacialTension(oil, aqueous, 0.04);
  addTankWalls(w, tank, d);
  const Real gap = (testing::kWallGap - 0.5) * d;
  addFluidBlock(w, Vec3::Constant(gap), Vec3(gap + 9 * d, gap + 5 * d, gap + 9 * d), d, aqueous);
  addFluidBlock(w, Vec3(gap, gap + 5 * d, gap), Vec3(gap + 9 * d, gap + 10 * d, gap + 9 * d), d,
                oil);
  w.initialize();
  // The top layer has 0.85 of the rest number density (a half-space of the lattice), below the
  // rule's 0.9; its 6 x 6 particles without a side-wall neighbour are counted.
  CHECK(countFreeSurfaceParticles(w) >= 36);
  PipelineOptions o;
  o.solver = "indsph";
  const Pipeline p = assemblePipeline(w, o);
  CHECK(p.hasStage("interfacial_tension"));
  CHECK_FALSE(p.hasStage("background_pressure"));
  CHECK_THAT(decision(p, "background_pressure").reason, Contains("free surface"));
  // A scene that knows better overrides the detection, both ways.
  o.closedDomain = StageOverride::kOn;
  CHECK(assemblePipeline(w, o).hasStage("background_pressure"));
  auto closed = closedDroplet();
  o.closedDomain = StageOverride::kOff;
  CHECK_FALSE(assemblePipeline(*closed.world, o).hasStage("background_pressure"));
}

TEST_CASE("background_pressure's time-step limit is 0.2 h / sqrt(p_bg / rho)",
          "[unit][interface]") {
  auto scene = closedDroplet();
  const BackgroundPressure stage(160.0, 985.0);
  CHECK(stage.maxTimeStep(*scene.world) ==
        Approx(kBackgroundCourant * scene.world->supportRadius() / std::sqrt(160.0 / 985.0))
            .epsilon(1e-12));
  CHECK_THROWS_AS(BackgroundPressure(0.0, 985.0), SimError);
  CHECK_THROWS_AS(BackgroundPressure(-1.0, 985.0), SimError);
}

constexpr Real kDt = 1e-4;  // [s]

// The stage's accelerations alone, with densities as INDSPH sets them (m delta, so V = 1 / delta:
// d^3 on the lattice for both phases, which mass-density summation would not give next to the
// interface).
void applyStage(World& w, BackgroundPressure& stage) {
  std::vector<Real> delta;
  computeNumberDensities(w, delta);
  for (Index i = 0; i < w.particles.size(); ++i)
    w.particles.density[i] = w.particles.mass[i] * delta[i];
  stage.attach(w);
  stage.apply(w, StepContext{kDt});
  // The stage writes the transport correction dv = dt a_bg; the tests read a_bg = dv / dt.
  const auto& dv = w.particles.fields.get<Vec3>(field::kTransportShift);
  for (Index i = 0; i < w.particles.size(); ++i) w.particles.a[i] = dv[i] / kDt;
}

TEST_CASE("background_pressure exerts no force inside a regular lattice", "[unit][interface]") {
  auto scene = closedDroplet();
  World& w = *scene.world;
  BackgroundPressure stage(160.0, 985.0);
  applyStage(w, stage);
  // Scale: a particle missing half its support feels about p_bg / (rho d).
  const Real scale = 160.0 / (1000.0 * w.particleSpacing());
  Real interiorMax = 0, wallMax = 0;
  const NeighborList& nw = w.wallNeighbors();
  for (Index i = 0; i < w.particles.size(); ++i) {
    const Real a = w.particles.a[i].norm();
    // The droplet and its interface (r < R + h): every neighbour's own support is free of walls,
    // so every V_j there is the lattice's d^3.
    if ((w.particles.x[i] - scene.centre).norm() < scene.radius + w.supportRadius())
      interiorMax = std::max(interiorMax, a);
    if (nw.begin(i) != nw.end(i)) wallMax = std::max(wallMax, a);
  }
  // A complete, point-symmetric neighbourhood: the bracket sum_j (V_i^2 + V_j^2) gradW_ij
  // vanishes to round-off, across the oil/aqueous interface too (both phases have V = d^3).
  CHECK(interiorMax < 1e-9 * scale);
  // Next to the walls it does not (the Akinci layer completes the support only approximately),
  // so the check above is not vacuous.
  CHECK(wallMax > 1e-3 * scale);
}

namespace {

testing::DropletScene jitteredDroplet(Real oilDensity) {
  testing::DropletSpec s;
  s.radius = 0.003;
  s.spacing = s.radius / 6;
  s.halfWidth = 2 * s.radius;
  s.sigma = 0.04;
  s.massExcess = 0;
  s.oilDensity = oilDensity;
  s.jitter = 0.2;  // disordered: every V_i differs, so a non-symmetric pair weight would show
  return testing::dropletScene(s);
}

constexpr Real kReferenceDensity = 985.0;  // [kg/m^3] rho_ref of the stage in these tests

}  // namespace

TEST_CASE("background_pressure's fluid pair terms are equal and opposite", "[unit][interface]") {
  auto scene = jitteredDroplet(970);
  World& w = *scene.world;
  BackgroundPressure stage(160.0, kReferenceDensity);
  applyStage(w, stage);
  // The shift is dv_i = -(dt p_bg / (rho_ref V_i)) bracket_i, so rho_ref V_i dv_i / dt is the
  // bracket times -p_bg: its fluid pairs must cancel.
  Vec3 momentum = Vec3::Zero(), wallPart = Vec3::Zero();
  Real magnitude = 0;
  const PairLoop walls = wallPairs(w);
  for (Index i = 0; i < w.particles.size(); ++i) {
    const Real vi = w.particles.mass[i] / w.particles.density[i];
    const Vec3 f = kReferenceDensity * vi * w.particles.a[i];
    momentum += f;
    magnitude += f.norm();
    // The wall term as the stage writes it: -p_bg 2 V_i^2 / V0_i sum_b V_b gradW_ib.
    Vec3 g = Vec3::Zero();
    walls.forEach(i, [&](Index b, const Vec3& gradW) { g += w.walls.volume[b] * gradW; });
    wallPart -= 160.0 * 2 * vi * vi / w.restVolumeOf(i) * g;
  }
  REQUIRE(magnitude > 0);
  // Weight V_i^2 + V_j^2 on an antisymmetric gradient: the fluid pairs cancel to round-off and
  // all of the sum is the walls' share.
  CHECK((momentum - wallPart).norm() < 1e-12 * magnitude);
}

TEST_CASE("background_pressure shifts a particle the same whatever its phase's density",
          "[unit][interface]") {
  // The shift is a regularisation of the particle arrangement, not a force: Young's relation and
  // the Laplace jump contain no density, so neither may the shift. Dividing by m_i, as the
  // one-phase original does, shifted a 1760 kg/m^3 droplet 1.8x less than the water around it,
  // and a 150 deg sessile droplet settled at 164 deg instead of 147 (background_pressure.h).
  // Same arrangement, droplet at 970 and at 1760 kg/m^3: the shift fields must agree to
  // round-off (the densities enter V = m / (m delta) = 1 / delta only through rounding).
  auto light = jitteredDroplet(970);
  auto heavy = jitteredDroplet(1760);
  REQUIRE(light.world->particles.size() == heavy.world->particles.size());
  BackgroundPressure lightStage(160.0, kReferenceDensity), heavyStage(160.0, kReferenceDensity);
  applyStage(*light.world, lightStage);
  applyStage(*heavy.world, heavyStage);
  const auto& pl = light.world->particles;
  const auto& ph = heavy.world->particles;
  Real largest = 0, difference = 0, heavyDroplet = 0;  // [m/s^2]
  for (Index i = 0; i < pl.size(); ++i) {
    largest = std::max(largest, pl.a[i].norm());
    difference = std::max(difference, (pl.a[i] - ph.a[i]).norm());
    if (ph.mass[i] > 1.5 * pl.mass[i]) heavyDroplet = std::max(heavyDroplet, ph.a[i].norm());
  }
  // Not vacuous: the jittered droplet's particles are shifted, and it has heavy particles.
  REQUIRE(heavyDroplet > 1e-3 * largest);
  CHECK(difference < 1e-9 * largest);
}
