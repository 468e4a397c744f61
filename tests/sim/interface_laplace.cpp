// Issue 6, validation 1: Young-Laplace pressure jump of an oil droplet in aqueous (no gravity,
// closed box) with the interfacial_tension stage, for two radii and two tensions.
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
};

constexpr Real kRunTaus = 1.5;  // [1] run length in capillary times

// Runs the droplet for 1.5 capillary times tau = sqrt(rho R^3 / sigma) and averages the jump
// from 0.5 tau on (the first half capillary time lets the lattice sphere relax and the start-up acoustic
// wave decay).
//
// WCSPH: DFSPH's rest state is not yet calm (engine-notes KNOWN PROBLEM). INDSPH: the eye
// scenes' solver, with the background_pressure stage (on by its rule: closed scene, tension) or
// forced off; rest masses (a closed box cannot shed a mass excess under an incompressible solve).
LaplaceResult runLaplace(Real radius, Real sigma, const std::string& solver = "wcsph",
                         Force background = Force::kAuto) {
  testing::DropletSpec s;
  s.radius = radius;
  s.spacing = radius / 6;  // d = R/6: 3 kernel supports per radius (issue 6 suggests R/6..R/8)
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
  options.forced["background_pressure"] = background;
  Pipeline pipeline = assemblePipeline(w, options);
  REQUIRE(pipeline.hasStage("interfacial_tension"));
  REQUIRE(pipeline.hasStage("background_pressure") ==
          (solver == "indsph" && background != Force::kOff));
  pipeline.attach(w);
  const auto& pressure = w.particles.fields.get<Real>("pressure");
  const Real tau = std::sqrt(1000.0 * radius * radius * radius / sigma);  // [s]
  Real sum = 0;
  int samples = 0;
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
  return {sum / samples, expected, w.stepCount};
}

void checkLaplace(Real radius, Real sigma) {
  const std::string solver = "wcsph";
  const LaplaceResult r = runLaplace(radius, sigma, solver);
  std::printf("Laplace (%s) R = %.1f mm, sigma = %.3f N/m: dp = %.2f Pa, 2 sigma / R = %.2f Pa "
              "(%+.1f %%), %ld steps\n",
              solver.c_str(), radius * 1e3, sigma, r.measured, r.expected,
              100 * (r.measured / r.expected - 1), r.steps);
  // 10 %: the acceptance. The sources of error are the diffuse interface (width 2h =
  // 2R/3 at this resolution: the jump is the stress integral weighted by 1/r over the layer,
  // about 3 % above 2 sigma / R here, see docs/interface.md) and the residual parasitic
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

// The eye scenes' solver. Without the background pressure the surface stress clumps the
// interface (sum V |gradC| falls to half the sphere's area) and the jump reads 0.3 of 2 sigma / R;
// with the stage's transport correction 0.84 over this window (0.5-1.5 tau) at d = R/6, for both
// droplets, and 0.89 at R/8 (docs/interface.md, validation 1b). The issue's +-10 % is met by the
// WCSPH cases above, NOT by INDSPH at this resolution (-16 %); this test guards the fix: 0.75 is
// far above what the scene gives without the stage (0.31, the control below) and below the
// measured 0.84 by more than the step-to-step scatter in the window (0.80-0.87); 1.1 as for WCSPH.
TEST_CASE("Laplace pressure under INDSPH: 3 mm at 40 mN/m and 2 mm at 20 mN/m",
          "[validation][interface][laplace][indsph]") {
  for (const auto& [radius, sigma] : {std::pair{0.003, 0.040}, std::pair{0.002, 0.020}}) {
    const LaplaceResult r = runLaplace(radius, sigma, "indsph");
    std::printf("Laplace (indsph) R = %.1f mm, sigma = %.3f N/m: dp = %.2f Pa, 2 sigma / R = %.2f Pa "
                "(%+.1f %%), %ld steps\n",
                radius * 1e3, sigma, r.measured, r.expected, 100 * (r.measured / r.expected - 1),
                r.steps);
    CHECK(r.measured > 0.75 * r.expected);
    CHECK(r.measured < 1.10 * r.expected);
  }
}

// The control: the same droplet with the stage forced off must lose most of its jump, so the
// test above passes because of the stage and not by chance. 0.6: measured 0.28-0.38 of 2 sigma /
// R over the averaging window; any model that held 60 % would be a different finding.
TEST_CASE("Laplace pressure under INDSPH without the background pressure is under-stated",
          "[validation][interface][laplace][indsph]") {
  const LaplaceResult r = runLaplace(0.003, 0.040, "indsph", Force::kOff);
  std::printf("Laplace (indsph, no background) R = 3 mm, sigma = 0.040 N/m: dp = %.2f Pa of %.2f\n",
              r.measured, r.expected);
  CHECK(r.measured < 0.6 * r.expected);
}
