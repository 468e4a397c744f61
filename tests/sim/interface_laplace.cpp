// docs/methods/interface.md validation 1: Young-Laplace pressure jump of an oil droplet in aqueous
// (no gravity, closed box) with the interfacial_tension stage, for two radii and two tensions.
#include <catch2/catch.hpp>

#include <cstdio>
#include <string>
#include <utility>

#include "interface_fixtures.h"
#include "sim/measure/droplet_pressure_jump.h"

using namespace sim;

namespace {

struct LaplaceResult {
  Real measured = 0;  // [Pa] time-averaged inside - outside
  Real expected = 0;  // [Pa] 2 sigma / R
  long steps = 0;
  Real drift = 0;  // [d] distance the droplet's centre moved over the run
};

struct LaplaceOptions {
  sim::StageOverride background = StageOverride::kAuto;
  SurfaceStressForm form = SurfaceStressForm::kAuto;
  Real jitter = 0;  // [d] start lattice moved by up to this per axis
};

constexpr Real kRunTaus = 1.5;  // [1] run length in capillary times

// Runs the droplet for 1.5 capillary times tau = sqrt(rho R^3 / sigma) and averages the jump
// from 0.5 tau on (the first half capillary time lets the lattice sphere relax and the start-up
// acoustic wave decay).
//
// WCSPH: DFSPH's rest state is not yet calm (engine-notes KNOWN PROBLEM). INDSPH: the eye
// scenes' solver, with the background_pressure stage (on by its rule: closed scene, tension) or
// forced off; rest masses (a closed box cannot shed a mass excess under an incompressible solve).
LaplaceResult runLaplace(Real radius, Real sigma, const std::string& solver = "wcsph",
                         const LaplaceOptions& run = {}) {
  testing::DropletSpec s;
  s.radius = radius;
  s.spacing = radius / 6;  // d = R/6: 3 kernel supports per radius (R/6..R/8 validated)
  const Real h = 2 * s.spacing;
  // Fluid reaches 2h beyond the interface's outer edge R + h, plus one d: the outside sample
  // (R + h < r < R + 2h) stays clear of the wall layer.
  s.halfWidth = radius + 2 * h + s.spacing;
  s.sigma = sigma;
  // Viscosity does not enter the static jump; 0.05 Pa s (Ohnesorge ~0.1-0.2) damps the
  // capillary oscillation of the relaxing lattice sphere within the run.
  s.oilViscosity = s.aqueousViscosity = 0.05;
  // WCSPH: background pressure ~ 200 Pa keeps every particle above the p = 0 clamp.
  s.massExcess = solver == "wcsph" ? 0.05 : 0.0;
  s.jitter = run.jitter;
  auto scene = testing::dropletScene(s);
  World& w = *scene.world;
  const Real expected = 2 * sigma / scene.radius;
  PipelineOptions options;
  options.solver = solver;
  // c = 12 sqrt(dp / rho): the jump compresses the droplet by dp / (rho c^2) < 1 %.
  options.wcsph.speedOfSound = 12 * std::sqrt(expected / 1000.0);
  // alpha 0.5 damps the box's acoustic modes excited by the compressed start; artificial
  // viscosity vanishes at rest and cannot shift a static balance.
  options.wcsph.artificialViscosity = 0.5;
  options.forced["background_pressure"] = run.background;
  options.surfaceStress = run.form;
  // The box is full; a jittered start would read as a free surface to the automatic rule.
  options.closedDomain = StageOverride::kOn;
  Pipeline pipeline = assemblePipeline(w, options);
  REQUIRE(pipeline.hasStage("interfacial_tension"));
  REQUIRE(pipeline.hasStage("background_pressure") ==
          (solver == "indsph" && run.background != StageOverride::kOff));
  pipeline.attach(w);
  const auto& pressure = w.particles.fields.get<Real>("pressure");
  const Real tau = std::sqrt(1000.0 * radius * radius * radius / sigma);  // [s]
  Real sum = 0;
  int samples = 0;
  const Vec3 start = centreOfMaterial(w, scene.oil);
  while (w.time < kRunTaus * tau) {
    pipeline.step(w);
    if (w.time < 0.5 * tau) continue;
    const Vec3 centre = centreOfMaterial(w, scene.oil);
    const auto jump = measureDropletPressureJump(
        w, pressure, {centre, scene.radius, h, scene.oil, scene.radius + 2 * h});
    sum += jump.jump;
    ++samples;
  }
  REQUIRE(allFinite(w));
  const Real drift = (centreOfMaterial(w, scene.oil) - start).norm() / s.spacing;
  return {sum / samples, expected, w.stepCount, drift};
}

void checkLaplace(Real radius, Real sigma) {
  const std::string solver = "wcsph";
  const LaplaceResult r = runLaplace(radius, sigma, solver);
  std::printf(
      "Laplace (%s) R = %.1f mm, sigma = %.3f N/m: dp = %.2f Pa, 2 sigma / R = %.2f Pa "
      "(%+.1f %%), %ld steps\n",
      solver.c_str(), radius * 1e3, sigma, r.measured, r.expected,
      100 * (r.measured / r.expected - 1), r.steps);
  // 10 %: the acceptance. The sources of error are the diffuse interface (width 2h =
  // 2R/3 at this resolution: the jump is the stress integral weighted by 1/r over the layer,
  // about 3 % above 2 sigma / R here, see docs/methods/interface.md) and the residual parasitic
  // currents; both are below 5 % in the measured cases, so 10 % fails on a wrong factor (a
  // missing 1/D, a wrong normal or sign), not on noise.
  CHECK(r.measured == Approx(r.expected).epsilon(0.10));
}

}  // namespace

TEST_CASE("Laplace pressure of a 3 mm oil droplet, sigma 40 and 20 mN/m",
          "[validation][interface][laplace]") {
  checkLaplace(0.003, 0.040);
  checkLaplace(0.003, 0.020);
}

TEST_CASE("Laplace pressure of a 2 mm oil droplet, sigma 40 and 20 mN/m",
          "[validation][interface][laplace]") {
  checkLaplace(0.002, 0.040);
  checkLaplace(0.002, 0.020);
}

// The eye scenes' solver, with the corrected surface stress (the automatic choice under INDSPH)
// and the background_pressure stage (on by its rule: closed scene, tension). 10 %: the issue's
// acceptance, as for WCSPH; measured -3.4 % (3 mm, 40 mN/m) and -5.9 % (2 mm, 20 mN/m) over this
// window (0.5-1.5 tau), d = R/6 (docs/methods/interface.md, validation 1). The symmetric form of
// the paper reads 0.844 of 2 sigma / R here: under INDSPH the interface particles disorder and its
// pair sum is then not exact (sim/effects/interfacial_tension_hu_adams2006.h). Its run is the
// control that the corrected form is what meets the tolerance: it must stay below 0.92 (the
// window's step-to-step scatter is 0.80-0.87).
TEST_CASE("Laplace pressure under INDSPH: 3 mm at 40 mN/m and 2 mm at 20 mN/m",
          "[validation][interface][laplace][indsph]") {
  for (const auto& [radius, sigma] : {std::pair{0.003, 0.040}, std::pair{0.002, 0.020}}) {
    const LaplaceResult r = runLaplace(radius, sigma, "indsph");
    std::printf(
        "Laplace (indsph) R = %.1f mm, sigma = %.3f N/m: dp = %.2f Pa, 2 sigma / R = %.2f Pa "
        "(%+.1f %%), %ld steps\n",
        radius * 1e3, sigma, r.measured, r.expected, 100 * (r.measured / r.expected - 1), r.steps);
    CHECK(r.measured == Approx(r.expected).epsilon(0.10));
  }
  const LaplaceResult symmetric =
      runLaplace(0.003, 0.040, "indsph", {.form = SurfaceStressForm::kSymmetric});
  std::printf(
      "Laplace (indsph, symmetric surface stress) R = 3 mm: dp = %.2f Pa of %.2f (%+.1f %%)\n",
      symmetric.measured, symmetric.expected, 100 * (symmetric.measured / symmetric.expected - 1));
  CHECK(symmetric.measured < 0.92 * symmetric.expected);
}

// The corrected form trades the symmetric form's exact pairwise momentum balance for first-order
// consistency (its net force is 7e-3 of sum |f| on a static 0.2 d jittered droplet, 5e-4 once
// relaxed: `sim_laplace_bench solver=indsph jitter=0.2`). The physical requirement is that a
// droplet at rest does not propel itself. Started from a 0.2 d jittered lattice (no symmetry left
// to cancel a net force) its centre moved 0.015 d over the run; the bench puts the symmetric,
// momentum-exact form's at 0.008 d (the parasitic currents' noise) and the corrected one's at
// 0.011 d from the box centre. 0.1 d: an order of magnitude above both. The jump is checked too:
// measured +3.3 % from the jittered start (10 %: the tolerance).
TEST_CASE("A jittered INDSPH droplet at rest does not propel itself under the corrected stress",
          "[validation][interface][laplace][indsph]") {
  const LaplaceResult r = runLaplace(0.003, 0.040, "indsph", {.jitter = 0.2});
  std::printf(
      "Laplace (indsph, 0.2 d jittered start) R = 3 mm: dp = %.2f Pa of %.2f (%+.1f %%), "
      "centre moved %.4f d\n",
      r.measured, r.expected, 100 * (r.measured / r.expected - 1), r.drift);
  CHECK(r.drift < 0.1);
  CHECK(r.measured == Approx(r.expected).epsilon(0.10));
}

// The control: the same droplet with the stage forced off must lose most of its jump, so the
// test above passes because of the stage and not by chance. 0.6: measured 0.28-0.38 of 2 sigma /
// R over the averaging window with the symmetric form, 0.10 with the corrected one (the clumped
// interface's irregular neighbourhoods); any model that held 60 % would be a different finding.
TEST_CASE("Laplace pressure under INDSPH without the background pressure is under-stated",
          "[validation][interface][laplace][indsph]") {
  const LaplaceResult r = runLaplace(0.003, 0.040, "indsph", {.background = StageOverride::kOff});
  std::printf("Laplace (indsph, no background) R = 3 mm, sigma = 0.040 N/m: dp = %.2f Pa of %.2f\n",
              r.measured, r.expected);
  CHECK(r.measured < 0.6 * r.expected);
}
