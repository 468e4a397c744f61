// Interfacial tension and wall wetting: invariants of the interfacial-tension and wall-adhesion
// stages, the material-table API and the measurement helpers. Static configurations only (no time
// stepping).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "interface_fixtures.h"
#include "interface_ridge.h"
#include "interface_sessile.h"
#include "sim/effects/interfacial_tension_hu_adams2006.h"
#include "sim/effects/wall_adhesion_young.h"
#include "sim/fluid/density.h"
#include "sim/measure/scan_golden_minimum.h"
#include "sim/measure/sessile_contact_angle.h"

using namespace sim;
using Catch::Matchers::Contains;

namespace {

// Accelerations of one effect alone on the scene as built (densities by summation).
void applyAlone(World& w, Effect& effect) {
  computeDensities(w, w.particles.density);
  effect.attach(w);
  for (auto& a : w.particles.a) a.setZero();
  effect.apply(w, StepContext{1e-4});
}

testing::DropletScene freeDroplet(Real perR) {
  testing::DropletSpec s;
  s.radius = 0.003;
  s.spacing = s.radius / perR;
  s.halfWidth = s.radius + 3 * 2 * s.spacing;  // interface (R +- h) more than h from the walls
  s.sigma = 0.04;
  s.massExcess = 0;
  return testing::dropletScene(s);
}

constexpr Real kHemisphereRadius = 0.003;  // [m]

// tissueLayers > 0: the floor is that many layers of elastic tissue on the layered wall, its top
// layer the wetted surface (DropletSpec::tissueFloorLayers).
testing::DropletSpec hemisphereSpec(int wallLayers = 0, int tissueLayers = 0) {
  testing::DropletSpec s;
  s.wallLayers = wallLayers;
  s.tissueFloorLayers = tissueLayers;
  s.radius = kHemisphereRadius;
  s.spacing = s.radius / 6;
  s.halfWidth = 2 * s.radius;
  s.boxHeight = 1.6 * s.radius;
  s.sigma = 0.04;
  s.massExcess = 0;
  s.sessileStartCos = 0;  // centre on the floor: a hemisphere, 90 deg
  return s;
}
testing::DropletScene hemisphere(int wallLayers = 0, int tissueLayers = 0) {
  return testing::dropletScene(hemisphereSpec(wallLayers, tissueLayers));
}

// Sum of m a . e_r over particles within `reach` of the vertical axis through the centre,
// e_r the horizontal radial direction [N].
Real radialForce(const World& w, const Vec3& centre, Real reach) {
  Real f = 0;
  for (Index i = 0; i < w.particles.size(); ++i) {
    Vec3 r = w.particles.x[i] - centre;
    r.y() = 0;
    if (r.norm() == 0 || r.norm() > reach) continue;
    f += w.particles.mass[i] * w.particles.a[i].dot(r.normalized());
  }
  return f;
}

}  // namespace

TEST_CASE("MaterialTable keeps sigma per pair and contact angles, and rejects bad values",
          "[unit][interface]") {
  MaterialTable t;
  const int oil = t.add(testing::liquid("oil", 970, 1.0));
  const int aq = t.add(testing::liquid("aqueous", 1000, 1e-3));
  CHECK(t.interfacialTension(oil, aq) == 0.0);
  t.setInterfacialTension(aq, oil, 0.04);
  CHECK(t.interfacialTension(oil, aq) == 0.04);  // symmetric
  t.setInterfacialTension(oil, aq, 0.035);       // replaces, does not add
  CHECK(t.interfacialTensions().size() == 1);
  CHECK(t.interfacialTension(aq, oil) == 0.035);
  CHECK_THROWS_WITH(t.setInterfacialTension(oil, aq, -0.01), Contains(">= 0 N/m"));
  CHECK_THROWS_WITH(t.setInterfacialTension(oil, oil, 0.01), Contains("two different"));
  t.setContactAngle(aq, 3, 18.0);
  REQUIRE(t.contactAngles().size() == 1);
  CHECK(t.contactAngles()[0].fluidMaterial == aq);
  CHECK_THROWS_WITH(t.setContactAngle(oil, 3, 180.0), Contains("measured through material 'oil'"));
  CHECK_THROWS_AS(t.setContactAngle(7, 3, 30.0), SimError);
}

TEST_CASE("Capillary time-step limit is Brackbill's sqrt(rho_avg d^3 / (2 pi sigma))",
          "[unit][interface]") {
  auto scene = freeDroplet(6);
  World& w = *scene.world;
  InterfacialTensionHuAdams2006 tension;
  tension.attach(w);
  const Real d = w.particleSpacing();
  const Real expected =
      std::sqrt(0.5 * (970.0 + 1000.0) * d * d * d / (2 * std::numbers::pi * 0.04));
  CHECK(tension.maxTimeStep(w) == Approx(expected).epsilon(1e-12));
}

namespace {

struct StressSums {
  Real expected = 0;  // [Pa] 2 sigma / R of the lattice droplet's radius
  Real jump = 0;      // [Pa] sum_i -m_i a_i.e_r / (4 pi r_i^2): the jump the force field asks for
  Real net = 0;       // [N] |sum m a|
  Real scale = 0;     // [N] sum |m a|
};

// The tension alone on a free droplet: pressure jump the force field asks for, dp = -int f_r dr =
// sum_i -m_i a_i.e_r / (4 pi r_i^2) (force per volume summed over spherical shells), and the net
// force against the sum of magnitudes.
StressSums tensionSums(Real perR, SurfaceStressForm form) {
  auto scene = freeDroplet(perR);
  World& w = *scene.world;
  InterfacialTensionHuAdams2006 tension(form);
  applyAlone(w, tension);
  StressSums sums;
  sums.expected = 2 * 0.04 / scene.radius;
  Vec3 momentum = Vec3::Zero();
  for (Index i = 0; i < w.particles.size(); ++i) {
    const Vec3 r = w.particles.x[i] - scene.centre;
    const Vec3 f = w.particles.mass[i] * w.particles.a[i];
    sums.jump -= f.dot(r.normalized()) / (4 * std::numbers::pi * r.squaredNorm());
    momentum += f;
    sums.scale += f.norm();
  }
  sums.net = momentum.norm();
  return sums;
}

}  // namespace

TEST_CASE(
    "Interfacial stress on a lattice droplet integrates to 2 sigma / R, and the symmetric form "
    "conserves momentum exactly",
    "[unit][interface]") {
  for (const Real perR : {6.0, 8.0}) {
    const StressSums symmetric = tensionSums(perR, SurfaceStressForm::kSymmetric);
    const StressSums corrected = tensionSums(perR, SurfaceStressForm::kCorrected);
    const Real expected = symmetric.expected;
    INFO("d = R/" << perR << ": jump symmetric " << symmetric.jump << " Pa, corrected "
                  << corrected.jump << " Pa, 2 sigma / R " << expected);
    // Symmetric: measured 0.03 % (R/6) and 0.45 % (R/8) off; 2 % allows the lattice's departure
    // from a sphere, while a wrong factor in the stress (1/D, sign, |gradC|) is off by 30 % or
    // more.
    CHECK(symmetric.jump == Approx(expected).epsilon(0.02));
    // Corrected: measured -5.1 % (R/6) and -6.1 % (R/8). On the lattice the kernel's gradient
    // moment sum_j V_j gradW_ij (x_j - x_i)^T is ~1.02 I, not I; the symmetric form keeps that
    // factor (and lands on 2 sigma / R by it), the correction removes it and shows the diffuse
    // layer's own discretisation error. 10 %: the Laplace tolerance; a wrong factor is
    // still off by 30 % or more. (On relaxed, disordered droplets, where the eye runs, the
    // corrected form is the accurate one: validation 1 of docs/methods/interface.md.)
    CHECK(corrected.jump == Approx(expected).epsilon(0.10));
    // Every pair term of the symmetric form is antisymmetric and no stressed particle is near a
    // wall: sum m a = 0 to round-off (relative to the sum of |m a|).
    CHECK(symmetric.net < 1e-12 * symmetric.scale);
  }
}

TEST_CASE("Wall adhesion exerts Young's line force sigma cos(theta) at the contact line",
          "[unit][interface]") {
  // Hemisphere of oil on the floor: the wall stress -sigma cos(theta) (I - m m) delta_w under
  // the oil ends at the contact line (radius a ~ R) and pulls it outward with 2 pi a sigma
  // cos(theta) in total.
  const int layers = GENERATE(0, 3);  // one Akinci layer (eye scenes); lattice layers (tests)
  // The stress on the non-wetting phase (without background_pressure) or on the phase with more
  // volume, here the aqueous (with it): Young's line force either way.
  const WallLayerPhase phase = GENERATE(WallLayerPhase::kNonWetting, WallLayerPhase::kLarger);
  for (const Real theta : {60.0, 90.0, 120.0, 30.0}) {
    auto scene = hemisphere(layers);
    World& w = *scene.world;
    w.materials.setContactAngle(scene.oil, testing::kFloorTag, theta);
    WallAdhesionYoung adhesion(phase);
    applyAlone(w, adhesion);
    CHECK_FALSE(adhesion.layerOnA());  // the oil (A) is the smaller phase
    const Real h = w.supportRadius();
    const Real force = radialForce(w, scene.centre, scene.radius + 3 * h);
    // The contact line's radius is the hemisphere's, kHemisphereRadius (the fixture's
    // scene.radius is the radius of a sphere of the droplet's volume, 2^(-1/3) of it).
    const Real expected =
        2 * std::numbers::pi * kHemisphereRadius * 0.04 * std::cos(theta * std::numbers::pi / 180);
    INFO("theta " << theta << " deg, layer "
                  << (phase == WallLayerPhase::kLarger ? "on the larger phase"
                                                       : "on the non-wetting phase")
                  << ": radial force " << force << " N, expected " << expected);
    if (theta == 90.0) {
      CHECK(std::abs(force) < 1e-12);
    } else {
      // Measured at d = R/6: with three lattice layers (fluid from d/2) +2.7 % when
      // the layer is on the aqueous and -14.5 % / -10.6 % when it is on the oil (theta 120,
      // layered / Akinci); with one Akinci layer, the hemisphere on the fluid's floor, +12.7 %:
      // the layer's discrete divergence at the lattice contact line, whose radius the lattice
      // resolves to d / 2 (8 % of a). Against the equivalent sphere
      // radius, 0.79 a, these read +29 / +7 / +20 % (docs/methods/interface.md). 30 % catches a
      // wrong sign or a lost factor 2 in gamma.
      CHECK(force == Approx(expected).epsilon(0.30));
    }
  }
}

// Over an elastic sclera the retina is tissue, not wall particles (protocols/scenario/
// tissue_particles.cpp). The tissue's top layer, tagged as the floor's wetted surface, sits where
// the wall's surface layer sat, on the same lattice; the fluid sees the same geometry. Both stages
// must then act on the fluid as over the wall: the same Young line force (wall_adhesion) and the
// same mirrored surface stress (interfacial_tension). Before, neither acted over tissue: the line
// force was 0, and a 120 deg droplet settled at 83-85 deg (`sim_interface_bench sessile 120 0.3 0
// indsph 3 6 0.005 0.2 tissue=2`; docs/methods/interface.md, validation 3).
TEST_CASE("Over a wetted tissue floor the interface stages act as over the wall it replaces",
          "[unit][interface]") {
  const Real d = kHemisphereRadius / 6;  // [m] the hemisphere fixture's spacing
  const Real h = 2 * d;                  // [m] its support radius
  for (const Real theta : {60.0, 120.0}) {
    auto wall = hemisphere(3);
    auto tissue = hemisphere(3, 2);
    // The droplet sits 2 d higher on the tissue; compare about each one's own centre.
    const Real lift = tissue.floorHeight - wall.floorHeight;
    REQUIRE(lift == Approx(2 * d));
    REQUIRE((tissue.centre - wall.centre).y() == Approx(lift));
    for (auto* scene : {&wall, &tissue})
      scene->world->materials.setContactAngle(scene->oil, testing::kFloorTag, theta);
    WallAdhesionYoung onWall(WallLayerPhase::kNonWetting), onTissue(WallLayerPhase::kNonWetting);
    applyAlone(*wall.world, onWall);
    applyAlone(*tissue.world, onTissue);
    // Within 1.5 h of the contact line, clear of the floor's edges at 2 R (see below).
    const Real wallForce = radialForce(*wall.world, wall.centre, kHemisphereRadius + 1.5 * h);
    const Real tissueForce = radialForce(*tissue.world, tissue.centre, kHemisphereRadius + 1.5 * h);
    INFO("theta " << theta << ": wall_adhesion's radial force " << tissueForce << " N over tissue, "
                  << wallForce << " N over the wall");
    // Same lattice, so the same areas; the tissue's normals come from its volume fraction's
    // gradient instead of the wall's stored normals, which on the flat floor agree except within
    // h of the box's side walls (hence the reach). What differs is the fluid's summed density
    // next to the floor: the tissue (1000 kg/m^3) adds its mass where the wall adds the fluid's
    // own rest density times its volume, so the oil (970) reads up to 3 % denser there and its
    // volumes, which weigh the wall delta function, change by a fraction of that. Measured
    // (d = R/6): -0.003 % at 60 deg (the stress on the aqueous, 1000 kg/m^3 like the tissue),
    // -0.38 % at 120 deg (on the oil); +0.07 / -0.45 % with the tissue in
    // the stage's pair sum (it is left out, as the walls are). 1 % holds that; a lost area, normal
    // or fluid sum on the tissue is off by 10 % or more (before this stage read tissue, the force
    // over it was 0).
    const Real young = 2 * std::numbers::pi * kHemisphereRadius * 0.04 *
                       std::abs(std::cos(theta * std::numbers::pi / 180));  // [N]
    CHECK(std::abs(wallForce) > 0.5 * young);  // the test above checks the wall's size (0.85 here)
    CHECK(tissueForce == Approx(wallForce).epsilon(0.01));
  }
  // The tension alone (no contact angle): its mirrored stress at the floor.
  auto wall = hemisphere(3);
  auto tissue = hemisphere(3, 2);
  InterfacialTensionHuAdams2006 onWall(SurfaceStressForm::kCorrected),
      onTissue(SurfaceStressForm::kCorrected);
  applyAlone(*wall.world, onWall);
  applyAlone(*tissue.world, onTissue);
  // Particle by particle: the fluid lattices are the same, the tissue's 2 d higher.
  const auto key = [d](const Vec3& x, Real floor) {
    return std::array<long, 3>{std::lround(x.x() / d - 0.5), std::lround((x.y() - floor) / d - 0.5),
                               std::lround(x.z() / d - 0.5)};
  };
  std::map<std::array<long, 3>, Vec3> tissueAcceleration;
  const auto& pt = tissue.world->particles;
  for (Index i = 0; i < pt.size(); ++i)
    if (pt.material[i] != tissue.tissue)
      tissueAcceleration[key(pt.x[i], tissue.floorHeight)] = pt.a[i];
  Real worstNearFloor = 0, worstAbove = 0, largest = 0;  // [m/s^2]
  const auto& pw = wall.world->particles;
  for (Index i = 0; i < pw.size(); ++i) {
    const auto found = tissueAcceleration.find(key(pw.x[i], wall.floorHeight));
    REQUIRE(found != tissueAcceleration.end());
    const Real difference = (found->second - pw.a[i]).norm();
    // A particle's force reads its neighbours' stresses: the floor reaches 2 h up.
    Real& worst = pw.x[i].y() - wall.floorHeight < 2 * h ? worstNearFloor : worstAbove;
    worst = std::max(worst, difference);
    largest = std::max(largest, pw.a[i].norm());
  }
  INFO("interfacial_tension: largest acceleration " << largest
                                                    << " m/s^2; largest difference "
                                                       "tissue - wall within 2 h of the floor "
                                                    << worstNearFloor << ", above " << worstAbove);
  CHECK(largest > 0);
  // Beyond 2 h the floor is out of reach: the scenes are the same there.
  CHECK(worstAbove <= 1e-9 * largest);
  // Next to the floor the fluid's volumes differ a little (the density note above): measured
  // 0.41 % of the largest acceleration; 1 %. Without the mirrored stress on tissue neighbours it
  // was 33 %; with the colour gradient's correction completed by the tissue, 22 %.
  CHECK(worstNearFloor <= 0.01 * largest);
}

TEST_CASE("A contact angle through aqueous is 180 deg minus the angle through oil",
          "[unit][interface]") {
  auto throughOil = hemisphere();
  auto throughAqueous = hemisphere();
  throughOil.world->materials.setContactAngle(throughOil.oil, testing::kFloorTag, 60.0);
  throughAqueous.world->materials.setContactAngle(throughAqueous.aqueous, testing::kFloorTag,
                                                  120.0);
  WallAdhesionYoung a, b;
  applyAlone(*throughOil.world, a);
  applyAlone(*throughAqueous.world, b);
  Real maxDiff = 0, maxA = 0;
  for (Index i = 0; i < throughOil.world->particles.size(); ++i) {
    maxDiff = std::max(
        maxDiff, (throughOil.world->particles.a[i] - throughAqueous.world->particles.a[i]).norm());
    maxA = std::max(maxA, throughOil.world->particles.a[i].norm());
  }
  CHECK(maxA > 0);
  CHECK(maxDiff <= 1e-12 * maxA);  // cos(180 - t) = -cos(t): identical up to round-off
}

TEST_CASE("Interface stages are assembled only when the scene calls for them",
          "[unit][interface]") {
  auto scene = hemisphere();
  World& w = *scene.world;
  PipelineOptions options;
  options.solver = "wcsph";
  options.wcsph.speedOfSound = 2;
  {
    const Pipeline p = assemblePipeline(w, options);
    CHECK(p.hasStage("interfacial_tension"));
    CHECK_FALSE(p.hasStage("wall_adhesion"));  // no contact angle yet
  }
  w.materials.setContactAngle(scene.aqueous, testing::kFloorTag, 18.0);
  {
    const Pipeline p = assemblePipeline(w, options);
    CHECK(p.hasStage("wall_adhesion"));
    CHECK_THAT(p.describe(), Contains("a contact angle is given"));
  }
  w.materials.setInterfacialTension(scene.oil, scene.aqueous, 0.0);  // removes the pair
  {
    const Pipeline p = assemblePipeline(w, options);
    CHECK_FALSE(p.hasStage("interfacial_tension"));
    CHECK_FALSE(p.hasStage("wall_adhesion"));
  }
  options.forced["interfacial_tension"] = StageOverride::kOn;
  Pipeline forced = assemblePipeline(w, options);
  CHECK_THROWS_WITH(forced.attach(w), Contains("no pair of materials has a tension"));
}

TEST_CASE("The wall stress's phase follows the background pressure stage", "[unit][interface]") {
  // The choice measured on the cavity lens (wall_adhesion_young.h): the larger phase with the
  // particle shift of background_pressure, the non-wetting phase without it.
  auto scene = hemisphere();
  World& w = *scene.world;
  w.materials.setContactAngle(scene.oil, testing::kFloorTag, 120.0);
  PipelineOptions options;
  options.solver = "indsph";
  options.closedDomain = StageOverride::kOn;
  CHECK(assemblePipeline(w, options).hasStage("background_pressure"));
  CHECK_THAT(assemblePipeline(w, options).describe(), Contains("liquid with more volume"));
  options.forced["background_pressure"] = StageOverride::kOff;
  CHECK_THAT(assemblePipeline(w, options).describe(), Contains("non-wetting liquid"));
  options.forced.clear();
  options.solver = "wcsph";
  options.wcsph.speedOfSound = 2;
  CHECK_FALSE(assemblePipeline(w, options).hasStage("background_pressure"));
  CHECK_THAT(assemblePipeline(w, options).describe(), Contains("non-wetting liquid"));
  options.forced["background_pressure"] = StageOverride::kOn;
  CHECK_THAT(assemblePipeline(w, options).describe(), Contains("liquid with more volume"));
}

TEST_CASE("Contact angle on a wall tag that does not exist is an error naming the tag",
          "[unit][interface]") {
  auto scene = hemisphere();
  scene.world->materials.setContactAngle(scene.oil, 42, 60.0);
  WallAdhesionYoung adhesion;
  CHECK_THROWS_WITH(adhesion.attach(*scene.world), Contains("wall tag 42"));
}

namespace {
// [m] Height above the wall of the centroid of the spherical cap of `volume` [m^3] and angle
// `thetaDeg` through the droplet: a cap of height H from a sphere of radius R has its centroid
// H (4R - H) / (4 (3R - H)) above its base.
Real capCentroidHeight(Real volume, Real thetaDeg) {
  const Real u = std::cos(thetaDeg * std::numbers::pi / 180);
  const Real radius = std::cbrt(3 * volume / (std::numbers::pi * (2 + u) * (1 - u) * (1 - u)));
  const Real height = radius * (1 - u);
  return height * (4 * radius - height) / (4 * (3 * radius - height));
}
}  // namespace

TEST_CASE("The centroid angle inverts a cap's centroid height", "[unit][interface]") {
  // The hemisphere's centroid is 3/8 of its radius above the base (a textbook value), and the
  // angle of every cap comes back from its centroid height.
  const Real r0 = 0.003, volume = 2.0 / 3.0 * std::numbers::pi * r0 * r0 * r0;
  CHECK(capCentroidHeight(volume, 90) == Approx(3.0 / 8.0 * r0).epsilon(1e-12));
  CHECK(capAngleOfCentroid(volume, 3.0 / 8.0 * r0) == Approx(90).margin(1e-6));
  for (const Real theta : {10.0, 30.0, 60.0, 120.0, 150.0, 170.0})
    CHECK(capAngleOfCentroid(volume, capCentroidHeight(volume, theta)) ==
          Approx(theta).margin(1e-6));
  CHECK(capAngleOfCentroid(volume, 0.0) == 0.0);   // a film
  CHECK(capAngleOfCentroid(volume, r0) == 180.0);  // above the touching sphere's centre
  CHECK_THROWS_AS(capAngleOfCentroid(0.0, 1e-3), SimError);
}

TEST_CASE("The footprint angle inverts a cap's section radius at a height", "[unit][interface]") {
  // Caps of R0 = 3 mm's hemisphere volume, the section at d / 2 with d = R0 / 12 (the first
  // fluid layer): the section radius of the cap of angle theta gives theta back.
  const Real r0 = 0.003, volume = 2.0 / 3.0 * std::numbers::pi * r0 * r0 * r0, y = r0 / 24;
  for (const Real theta : {10.0, 18.0, 30.0, 60.0, 95.0, 120.0, 150.0, 165.0, 175.0}) {
    const Real u = std::cos(theta * std::numbers::pi / 180);
    const Real radius = std::cbrt(3 * volume / (std::numbers::pi * (2 + u) * (1 - u) * (1 - u)));
    const Real dz = y + radius * u;
    const Real section = std::sqrt(radius * radius - dz * dz);
    CHECK(capAngleOfFootprint(volume, section, y) == Approx(theta).margin(1e-6));
  }
  // Wider than every cap's section: the widest one's angle, below the smallest inverted above.
  const Real widest = capAngleOfFootprint(volume, 10 * r0, y);
  CHECK(widest < 10.0);
  CHECK(widest > 0.0);
  CHECK(capAngleOfFootprint(volume, 0.0, y) == 180.0);  // narrower than the touching sphere
  CHECK_THROWS_AS(capAngleOfFootprint(0.0, 1e-3, y), SimError);
}

TEST_CASE("The fits' minimiser finds the global minimum among local ones", "[unit][interface]") {
  // A parabola with a ripple of period 5: local minima every 5 units, the global one near 37.3
  // (the ripple's cos has its trough at 37.5, the parabola pulls it towards 37.3). A pure golden
  // search over [1, 179] would stop in whichever ripple its first bracket holds.
  const auto cost = [](Real x) {
    return 0.01 * (x - 37.3) * (x - 37.3) - std::cos(2 * std::numbers::pi * (x - 37.5) / 5);
  };
  const Real found = scanGoldenMinimum(cost, ScanGoldenSearch{1, 179, 1, 0, 180, 60});
  // Its exact place: where the derivative vanishes, by bisection near 37.4.
  Real lo = 36.5, hi = 38.5;
  const auto slope = [](Real x) {
    return 0.02 * (x - 37.3) +
           2 * std::numbers::pi / 5 * std::sin(2 * std::numbers::pi * (x - 37.5) / 5);
  };
  for (int k = 0; k < 100; ++k) (slope(0.5 * (lo + hi)) > 0 ? hi : lo) = 0.5 * (lo + hi);
  CHECK(found == Approx(0.5 * (lo + hi)).margin(1e-6));
  // A minimum beyond the allowed range ends at its bound (the outline fit's 179 deg).
  const Real bounded = scanGoldenMinimum([](Real x) { return (x - 200) * (x - 200); },
                                         ScanGoldenSearch{90, 178, 2, 90, 179, 20});
  CHECK(bounded == Approx(179).margin(1e-3));
}

TEST_CASE("Sphere fit recovers a sphere and the cap angle from points on it", "[unit][interface]") {
  // Points on a cap of a sphere of radius 2 centred 1 below the plane y = 0: the cap meets the
  // plane at acos(-(-1)/2)... theta = acos(-z_c / R) with z_c = -1: 60 deg.
  std::vector<Vec3> points;
  const Vec3 c(0.3, -1.0, -0.2);
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 40; ++j) {
      const Real polar = 0.9 * std::acos(0.5) * (i + 0.5) / 20;  // stays above y = 0
      const Real az = 2 * std::numbers::pi * j / 40;
      points.push_back(c + 2 * Vec3(std::sin(polar) * std::cos(az), std::cos(polar),
                                    std::sin(polar) * std::sin(az)));
    }
  const SphereFit fit = fitSphere(points);
  CHECK((fit.centre - c).norm() < 1e-9);  // exact data: only round-off
  CHECK(fit.radius == Approx(2.0).epsilon(1e-9));
  CHECK(fit.rmsResidual < 1e-9);
  CHECK_THROWS_AS(fitSphere({Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()}), SimError);
}

TEST_CASE("Geometric sphere fit and the volume cap recover exact caps", "[unit][interface]") {
  // Points on the cap of a sphere of radius 2 whose centre is z_c = -cos(theta) R above the
  // plane y = 0 (theta = 40 deg through the cap); the cap volume pi R^3 (2 + u)(1 - u)^2 / 3,
  // u = cos(theta). Exact data: both fits must return the sphere to round-off.
  const Real theta = 40 * std::numbers::pi / 180, radius = 2, u = std::cos(theta);
  const Vec3 c(0.3, -u * radius, -0.2);
  std::vector<Vec3> points;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 40; ++j) {
      const Real polar = theta * (i + 0.5) / 20;
      const Real az = 2 * std::numbers::pi * j / 40;
      points.push_back(c + radius * Vec3(std::sin(polar) * std::cos(az), std::cos(polar),
                                         std::sin(polar) * std::sin(az)));
    }
  SphereFit start;
  start.centre = c + Vec3(0.1, -0.3, 0.05);
  start.radius = 1.5;
  const SphereFit fit = fitSphereGeometric(points, start);
  CHECK((fit.centre - c).norm() < 1e-8);
  CHECK(fit.radius == Approx(radius).epsilon(1e-8));
  const Real volume = std::numbers::pi * radius * radius * radius * (2 + u) * (1 - u) * (1 - u) / 3;
  const WallPlane plane{Vec3::Zero(), Vec3::UnitY()};
  CHECK(capAngleOfVolume(points, plane, Vec3(c.x(), 0.5, c.z()), volume) ==
        Approx(40.0).margin(1e-6));
}

TEST_CASE("The sessile cap fit reads static lattice caps of 30 to 165 deg at their angle",
          "[unit][interface]") {
  // The measurement of validation 3 on the droplet as built, no step: the lattice sites inside a
  // cap of exactly theta (the hemisphere's volume, R0 = 6 d, the 0.2 d jittered lattice and the
  // three wall layers of the [contact_angle] runs) are oil. The angle follows from the cap's
  // centre height z_c = -R cos(theta): an error dz in it is dz / (R sin theta) in theta, and the
  // lattice cap defines its surface only to within the cell, about 0.1 d in the mean over the
  // points, i.e. 1 deg at 90 deg. Tolerance 2 deg for 30-150 deg (measured 30.5, 44.3, 58.7,
  // 89.2, 120.2, 150.8); at 165 deg the same 0.1 d is 4.6 deg (sin 165 = 0.26, the contact disc
  // is 1.2 d in radius), so 5 deg there (measured 168.1). The free algebraic sphere through the
  // same points reads 33.6 for 30 deg (a short arc, docs/methods/interface.md validation 3): the
  // reason the fit is volume-constrained.
  for (const Real theta : {30.0, 45.0, 60.0, 90.0, 120.0, 150.0, 165.0}) {
    testing::SessileCase c;
    c.theta = theta;
    c.startCos = -std::cos(theta * std::numbers::pi / 180);
    c.wallLayers = 3;
    c.jitter = 0.2;
    c.solver = "indsph";  // rest mass as in the runs: the volume sum m / rho0 is the lattice's
    auto scene = testing::sessileScene(c);
    const World& w = *scene.world;
    const WallPlane floor{Vec3::Zero(), Vec3::UnitY()};
    const CapFit fit = fitSessileCap(w, scene.oil, floor, w.particleSpacing());
    INFO("static cap " << theta << " deg reads " << fit.contactAngle << " deg (free sphere "
                       << fit.sphereAngle << ")");
    CHECK(fit.contactAngle == Approx(theta).margin(theta > 150 ? 5.0 : 2.0));
    // The centroid angle (no interface points): the same 0.1 d surface uncertainty moves the
    // centroid by less than 0.1 d, so the tolerance is 0.1 d over d(centroid height)/d(theta) at
    // this angle: 4.8 deg at 30, 3.3 at 90, 3.4 at 150, 5 at 165. Measured 32.8, 47.0, 61.3, 90.3,
    // 120.2, 148.6, 164.7. A wrong cap height or centroid formula reads tens of
    // degrees off.
    const Real perDegree = std::abs(capCentroidHeight(fit.volume, theta + 0.5) -
                                    capCentroidHeight(fit.volume, theta - 0.5));  // [m / deg]
    INFO("centroid angle " << fit.centroidAngle << " deg, tolerance "
                           << 0.1 * w.particleSpacing() / perDegree << " deg");
    CHECK(fit.centroidAngle == Approx(theta).margin(0.1 * w.particleSpacing() / perDegree));
  }
}

TEST_CASE("The ridge fit reads static lattice segments of 30 to 165 deg at their angle",
          "[unit][interface]") {
  // The ridge's measurement (interface_ridge.h) on the ridge as built, no step: the 0.2 d
  // jittered lattice sites inside a circular segment of exactly theta (the cross-section of a
  // half-disc of R0) are oil. As for the round cap, the lattice defines the surface to about
  // 0.1 d in the mean, dz / (R sin theta) in theta: 0.5 deg at 30-150 deg with R0 = 12 d (R = 8.6
  // to 50 d), and at 165 deg 1.2 deg with R0 = 24 d (R = 17 d); R0 = 12 d there reads 169.5,
  // its contact strip 4.4 d wide. Measured 30.24, 89.66, 149.89 and 164.75 deg. Tolerance 1 deg:
  // the band is 5 deg, so the measurement may use at most a fifth of it. A wrong segment
  // radius or centre height reads several degrees off.
  for (const auto& [theta, r0PerD] : {std::pair{30.0, 12.0}, std::pair{90.0, 12.0},
                                      std::pair{150.0, 12.0}, std::pair{165.0, 24.0}}) {
    testing::RidgeCase c;
    c.theta = c.startTheta = theta;
    c.r0PerD = r0PerD;
    const testing::RidgeScene scene = testing::ridgeScene(c);
    const testing::RidgeFit fit = testing::fitRidge(*scene.world, scene.oil, scene.depth);
    INFO("static ridge " << theta << " deg (R0 = " << r0PerD << " d) reads " << fit.angle
                         << " deg, rms " << fit.rms * 1e3 << " mm, " << fit.points << " points");
    CHECK(fit.angle == Approx(theta).margin(1.0));
  }
}

// Without the pair cache (WorldParameters::cachePairKernels = false) every stage evaluates the
// kernel where it read the cache; the cached values are the kernel's own bit for bit, so a run
// must not depend on the choice: positions and velocities equal (==, not a tolerance) after
// steps that use the interface stages (tension, wall adhesion at the retina's 18 deg, background
// pressure) under INDSPH with gravity.
TEST_CASE("Interface stages give the same state bit for bit without the pair cache",
          "[unit][interface]") {
  std::array<testing::DropletScene, 2> scenes;
  for (int k = 0; k < 2; ++k) {
    testing::DropletSpec s = hemisphereSpec();
    s.gravity = Vec3(0, -9.81, 0);
    s.cachePairKernels = k == 0;
    scenes[k] = testing::dropletScene(s);
    scenes[k].world->materials.setContactAngle(scenes[k].aqueous, testing::kFloorTag, 18.0);
  }
  PipelineOptions options;
  options.solver = "indsph";
  options.closedDomain = StageOverride::kOn;
  Pipeline cached = assemblePipeline(*scenes[0].world, options);
  Pipeline uncached = assemblePipeline(*scenes[1].world, options);
  REQUIRE(cached.hasStage("wall_adhesion"));
  REQUIRE(cached.hasStage("background_pressure"));
  cached.attach(*scenes[0].world);
  uncached.attach(*scenes[1].world);
  REQUIRE(scenes[1].world->fluidGradients().empty());
  REQUIRE(scenes[1].world->fluidKernelValues().empty());
  for (int step = 0; step < 20; ++step) {
    cached.step(*scenes[0].world);
    uncached.step(*scenes[1].world);
  }
  const auto& a = scenes[0].world->particles;
  const auto& b = scenes[1].world->particles;
  REQUIRE(a.size() == b.size());
  for (Index i = 0; i < a.size(); ++i) {
    REQUIRE(a.x[i] == b.x[i]);
    REQUIRE(a.v[i] == b.v[i]);
  }
}
