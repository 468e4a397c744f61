// docs/methods/interface.md validation 5: equilibrium tamponade shapes in a spherical cavity. An
// oil volume in an aqueous-filled sphere (one layer of wall particles on a Fibonacci point set)
// settles to the Young-Laplace shape; the two closed-form limits are checked through the oil
// coverage of the wall (fraction of wall area whose nearest fluid particle is oil):
//   (a) no gravity (Bond number 0): a spherical lens meeting the wall at theta;
//   (b) no tension (Bond number infinite): a flat interface normal to gravity at the height that
//       holds the oil volume.
// Closed forms and the scene: interface_fixtures.h (lensCoverage, flatCoverage, cavityScene).
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>

#include "interface_fixtures.h"

using namespace sim;

namespace {

constexpr Real kCavityRadius = 0.003;         // [m] Rs: a small sphere keeps the test cheap
constexpr Real kSpacing = kCavityRadius / 8;  // [m] d = Rs / 8: 1631 fluid, 804 wall particles
constexpr Real kStartFraction = 0.3;          // [1] nominal oil volume fraction of the start cut

// Resolution tolerance on the coverage. The nearest-fluid classification places the contact
// line on the wall to within one wall-particle spacing d, and the interface itself is resolved
// to about d (one particle layer). An error of d in the contact line's arc position along the
// wall changes the covered zone's area fraction (1 - cos alpha) / 2 by sin(alpha) d / (2 Rs)
// <= d / (2 Rs) = 0.0625 at Rs = 8 d.
constexpr Real kCoverageTolerance = kSpacing / (2 * kCavityRadius);

struct CavityResult {
  testing::CavityState mean;  // coverage and angle averaged over the sampling window
  Vec3 axis = Vec3::Zero();   // covered cap's axis at the end
  Real start = 0;             // [1] coverage at the start
  Real expected = 0;          // [1] closed form for the scene's oil volume fraction
  long steps = 0;
  double seconds = 0;
};

struct CavityCase {
  bool lens = true;        // (a) lens without gravity, else (b) flat without tension
  Real theta = 90;         // [deg] through the oil, case (a)
  Real tiltDeg = 0;        // [deg] the start cut's normal tilted from +y (the closed-form axis)
  Real tEnd = 0.08;        // [s]
  Real sampleFrom = 0.05;  // [s]
  const char* solver = "wcsph";
  // [1] mass above rest density: WCSPH's Tait clamp at p = 0 then never acts; an incompressible
  // solver needs 0 in a closed cavity (the excess could never leave it)
  Real massExcess = 0.02;
  Real startFraction = kStartFraction;  // [1] oil volume fraction of the start cut
  int wallLayers =
      0;  // CavitySpec::latticeWallLayers: 0 one Akinci layer, 3 the eye's layered wall
};

CavityResult runCavity(const CavityCase& c) {
  const auto t0 = std::chrono::steady_clock::now();
  testing::CavitySpec s;
  s.cavityRadius = kCavityRadius;
  s.spacing = kSpacing;
  // The start: a flat cut holding the nominal volume fraction, its normal tilted by tiltDeg.
  s.oilOffset = kCavityRadius * (1 - 2 * testing::flatCoverage(c.startFraction));
  s.latticeWallLayers = c.wallLayers;
  const Real tilt = c.tiltDeg * std::numbers::pi / 180;
  s.oilAxis = Vec3(std::sin(tilt), std::cos(tilt), 0);
  s.massExcess = c.massExcess;
  PipelineOptions options;
  options.solver = c.solver;     // not DFSPH: its rest state is not calm (docs/methods/solvers.md)
  options.wallFriction = false;  // free slip: a no-slip wall pins a contact line (Huh-Scriven)
  options.wcsph.artificialViscosity = 0.1;
  if (c.lens) {
    s.sigma = 0.04;  // [N/m] silicone oil / aqueous (reference-data.md)
    // Capillary time sqrt(rho Rs^3 / sigma) = 26 ms; 0.03 Pa s damps the lens' l = 2
    // oscillation within the run (measured: at 0.005 Pa s it still swung +-0.05 in coverage
    // after 0.1 s and once detached from the wall).
    s.viscosity = 0.03;
    options.wcsph.speedOfSound = 2;  // 12 sqrt(2 sigma / (rho Rs)): density error < 1 %
  } else {
    s.gravity = Vec3(0, -9.81, 0);
    // A light "oil" (700 kg/m^3) so that the re-levelling time sqrt(Rs rho / (g drho)) ~ 30 ms
    // fits the run; the flat closed form does not depend on the densities.
    s.oilDensity = 700;
    s.viscosity = 0.05;
    options.wcsph.speedOfSound = 3;  // 10 sqrt(g 2 Rs) ~ 2.4 m/s: density error < 1 %
  }
  auto scene = testing::cavityScene(s);
  World& w = *scene.world;
  if (c.lens) w.materials.setContactAngle(scene.oil, 0, c.theta);
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  CavityResult out;
  out.expected = c.lens ? testing::lensCoverage(scene.oilVolumeFraction, c.theta).coverage
                        : testing::flatCoverage(scene.oilVolumeFraction);
  out.start = testing::measureCavity(scene, kCavityRadius).coverage;
  int samples = 0;
  while (w.time < c.tEnd) {
    pipeline.step(w);
    if (w.time > c.sampleFrom && w.stepCount % 20 == 0) {
      const testing::CavityState m = testing::measureCavity(scene, kCavityRadius);
      out.mean.coverage += m.coverage;
      out.mean.shepardCoverage += m.shepardCoverage;
      out.mean.dry += m.dry;
      out.mean.angle += m.angle;
      out.axis = m.axis;
      ++samples;
    }
  }
  REQUIRE(allFinite(w));
  REQUIRE(samples > 0);
  out.mean.coverage /= samples;
  out.mean.shepardCoverage /= samples;
  out.mean.dry /= samples;
  out.mean.angle /= samples;
  out.steps = w.stepCount;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

TEST_CASE("Cavity closed forms: lens and flat coverage agree in their shared limits",
          "[unit][interface][cavity]") {
  // A flat cut at height y0 meets the sphere at acos(y0 / Rs) through the oil above it, so the
  // lens of that angle and the same volume is the flat cut (r -> infinity; bisection stops at
  // r = 1e4 Rs, a relative error ~1e-4).
  for (const Real v : {0.1, 0.3, 0.45}) {
    const Real flat = testing::flatCoverage(v);
    const Real theta = std::acos(1 - 2 * flat) * 180 / std::numbers::pi;
    CHECK(testing::lensCoverage(v, theta).coverage == Approx(flat).margin(1e-3));
  }
  // A small 90 deg lens is a hemisphere of radius r on a nearly flat wall: v = r^3 / 2 and
  // coverage = pi r^2 / (4 pi) = r^2 / 4 (first order in r, here r = 0.0126).
  const Real v = 1e-6, r = std::cbrt(2 * v);
  CHECK(testing::lensCoverage(v, 90).coverage == Approx(r * r / 4).epsilon(0.02));
  // Half the cavity filled: the flat interface through the centre covers half the wall.
  CHECK(testing::flatCoverage(0.5) == Approx(0.5).margin(1e-12));
}

namespace {

// The 120 deg lens (through the oil; the receding side, where validation 3 meets +-5 deg) from
// the flat cut, coverage sampled from 0.05 s on.
void checkLens120(const char* solver, Real massExcess, Real tEnd) {
  CavityCase c;
  c.lens = true;
  c.theta = 120;
  c.tEnd = tEnd;
  c.sampleFrom = 0.05;
  c.solver = solver;
  c.massExcess = massExcess;
  const CavityResult r = runCavity(c);
  std::printf(
      "cavity lens 120 deg, %s: coverage %.4f (Shepard %.4f, dry %.4f), closed form "
      "%.4f, start %.4f; interface angle %.1f deg; %ld steps, %.1f s\n",
      solver, r.mean.coverage, r.mean.shepardCoverage, r.mean.dry, r.expected, r.start,
      r.mean.angle, r.steps, r.seconds);
  // The start (the flat cut's coverage, 0.35) lies two tolerances from the lens' 0.225: a run
  // whose contact line did not recede fails.
  REQUIRE(std::abs(r.start - r.expected) > 1.5 * kCoverageTolerance);
  CHECK(r.mean.coverage == Approx(r.expected).margin(kCoverageTolerance));
}

}  // namespace

TEST_CASE("Cavity without gravity: the oil settles to the 120 deg lens (Bond number 0)",
          "[validation][interface][cavity]") {
  checkLens120("wcsph", 0.02, 0.08);
}

// The same lens under INDSPH, the scenario runner's default solver, whose background_pressure
// stage puts the wall stress on the liquid with more volume, here the aqueous
// (sim/effects/wall_adhesion_young.h), at rest
// mass (an incompressible solver cannot remove an excess from the closed cavity). Measured
// (`sim_interface_bench cavity 120 0.3 8 0 970 0.03 0.04 0 indsph`): 0.228-0.234 at d = Rs/8
// (closed form 0.2249). Before background_pressure left contact-line particles unshifted: 0.208,
// and 0.168 with the stress on the oil, the choice without the stage.
TEST_CASE("Cavity without gravity under INDSPH: the oil settles to the 120 deg lens",
          "[validation][interface][cavity]") {
  checkLens120("indsph", 0.0, 0.1);
}

TEST_CASE(
    "Cavity without tension: the oil layer holds the flat interface at the volume's height "
    "(Bond number infinite)",
    "[validation][interface][cavity]") {
  // The oil starts as the level layer of the closed form and must hold it: the check is that the
  // single-layer wall, the two-phase density and the coverage read-out keep the contact line
  // where hydrostatics puts it. (A dynamic approach does not fit a CI run: a layer tilted by
  // 30 deg re-levels by turning the whole free-slip content as a rigid body, an undamped
  // pendulum whose period exceeds 0.2 s; with no-slip walls the contact line is pinned; a
  // central column rises 0.24 mm in 65 ms. `sim_interface_bench cavity flat` runs them,
  // docs/methods/interface.md has the numbers.)
  CavityCase c;
  c.lens = false;
  c.tiltDeg = 0;
  // The contact line has settled by 0.02 s (bench: 0.3134 from 0.016 s on, in WCSPH and INDSPH
  // alike); INDSPH takes 20x fewer steps here.
  c.tEnd = 0.04;
  c.sampleFrom = 0.02;
  c.solver = "indsph";
  const CavityResult r = runCavity(c);
  const Real tiltEnd =
      std::acos(std::clamp(r.axis.y(), Real(-1), Real(1))) * 180 / std::numbers::pi;
  std::printf(
      "cavity flat: coverage %.4f (Shepard %.4f, dry %.4f), closed form %.4f, start "
      "%.4f; cap axis %.1f deg from vertical; %ld steps, %.1f s\n",
      r.mean.coverage, r.mean.shepardCoverage, r.mean.dry, r.expected, r.start, tiltEnd, r.steps,
      r.seconds);
  CHECK(r.mean.coverage == Approx(r.expected).margin(kCoverageTolerance));
  // Contact-line errors of +-d on opposite sides of the cap (polar radius alpha, cos alpha =
  // 1 - 2 x 0.35) tilt its axis by at most d / (Rs sin alpha) = 7.6 deg.
  const Real alpha = std::acos(1 - 2 * r.expected);
  CHECK(tiltEnd < kSpacing / (kCavityRadius * std::sin(alpha)) * 180 / std::numbers::pi);
}

// The same level on the eye's layered wall (three lattice layers behind the sphere, the fluid
// filling every lattice point inside it). On one Akinci layer the fluid leaves a dry cap of 6.6 %
// of the wall under the lid and the protocol's coverage (Shepard oil fraction >= 0.5) reads 0.248
// against 0.349 (`sim_interface_bench cavity flat 0.06 8 0 700 0.05 0 0 indsph`); on the layered
// wall (TAMP_CAV_LAYERS=3) 0.372 against 0.375, nothing dry, and the bulk interface at 0.248 of
// the fluid's radius above its centre against hydrostatics' 0.250 (0.262 against 0.301 on one
// layer). So here the protocol's own coverage is held to the contact-line tolerance too.
TEST_CASE(
    "Cavity without tension on the eye's layered wall: the protocol's coverage is the "
    "flat interface's, nothing dry",
    "[validation][interface][cavity]") {
  CavityCase c;
  c.lens = false;
  c.tEnd = 0.04;
  c.sampleFrom = 0.02;
  c.solver = "indsph";
  c.massExcess = 0.0;
  c.wallLayers = 3;
  const CavityResult r = runCavity(c);
  std::printf(
      "cavity flat on the layered wall: coverage %.4f (Shepard %.4f, dry %.4f), closed "
      "form %.4f, start %.4f; %ld steps, %.1f s\n",
      r.mean.coverage, r.mean.shepardCoverage, r.mean.dry, r.expected, r.start, r.steps, r.seconds);
  CHECK(r.mean.coverage == Approx(r.expected).margin(kCoverageTolerance));
  CHECK(r.mean.shepardCoverage == Approx(r.expected).margin(kCoverageTolerance));
  CHECK(r.mean.dry == 0.0);
}

// The eye's case on its layered wall (protocols/assembly/layered_cavity_walls.h: three layers
// cut from the fluid's lattice behind the sphere, the wall a staircase about it): the library
// oils wet the retina at 18 deg through the aqueous, 162 deg through the oil, and fill most of the
// eye, so the oil is the larger phase pressed against the wall and the aqueous a wetting lens.
// Here 70 % oil at 162 deg through it, no gravity, INDSPH. The closed form's contact line is not
// what the coverage read-out sees at this angle (the aqueous wedge is thinner than a particle for
// 1.5 d beyond the line, so "nearest fluid is oil" there: coverage 0.49 against 0.32), so the
// check is the interface's angle from the fitted sphere, against the issue's +-10 deg outside
// 30-150 deg. Measured (`TAMP_CAV_V=0.7 TAMP_CAV_LAYERS=3 sim_interface_bench cavity 162 0.8 8 0
// 970 0.03 0.04 0 indsph`): 156.9 at 0.2 s, 155.9-156.9 to 0.76 s (settled). On one Akinci layer
// (TAMP_CAV_LAYERS=0) the same lens finds no sphere to fit (180 deg) while the oil drifts 0.8 mm
// along the wall: the eye's old wall did not hold the angle (docs/methods/interface.md).
TEST_CASE("Cavity with the eye's layered wall holds the library oils' 162 deg contact angle",
          "[validation][interface][cavity]") {
  CavityCase c;
  c.lens = true;
  c.theta = 162;
  c.startFraction = 0.7;
  c.tEnd = 0.3;
  c.sampleFrom = 0.2;
  c.solver = "indsph";
  c.massExcess = 0.0;
  c.wallLayers = 3;
  const CavityResult r = runCavity(c);
  std::printf(
      "cavity lens 162 deg on the layered wall: interface angle %.1f deg; coverage %.4f "
      "(Shepard %.4f, dry %.4f), closed form %.4f, start %.4f; %ld steps, %.1f s\n",
      r.mean.angle, r.mean.coverage, r.mean.shepardCoverage, r.mean.dry, r.expected, r.start,
      r.steps, r.seconds);
  CHECK(r.mean.angle == Approx(162.0).margin(10.0));
  CHECK(r.mean.dry == 0.0);  // the fluid fills the cavity up to the wall everywhere
}
