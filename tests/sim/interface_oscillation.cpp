// docs/methods/interface.md validation 2: the l = 2 oscillation of an oil droplet in aqueous
// against Lamb's frequency for a drop in another liquid (Lamb 1932, Hydrodynamics, section 275).
// The costly variants (other resolutions, amplitudes, INDSPH) are `sim_interface_bench
// oscillation`; docs/methods/interface.md section 2 has the table.
#include <catch2/catch.hpp>

#include <cstdio>

#include "interface_oscillation.h"

using namespace sim;

namespace {
// d = R/6, the resolution of the other interface validations (Laplace jump -5.7 % there).
constexpr Real kOscillationPerR = 6;
}  // namespace

// R = 3 mm, sigma = 40 mN/m, 970 in 1000 kg/m^3, mu = 1e-3 Pa s (physical), WCSPH with its
// artificial viscosity alpha 0.05, box half-width 2 R. The lattice sphere is relaxed first (100
// steps with the velocities reset), then kicked with the linear mode's velocity field
// (p2ModeVelocity, eps = 0.15), so no lattice reshuffle and no mean-shape drift enter Q(t).
TEST_CASE("l = 2 droplet oscillation: period within 10 % of Lamb's (relaxed start, velocity kick)",
          "[validation][interface][oscillation]") {
  testing::OscillationSpec o;
  o.solver = "wcsph";
  o.perR = kOscillationPerR;
  o.amplitude = 0.15;
  o.relaxSteps = 100;
  o.periods = 1.1;  // the crossings at 0, ~T/2 and ~T
  const testing::OscillationRun run = testing::runOscillation(o);
  const Real period = 2 * std::numbers::pi / run.omega;
  const testing::OscillationAnalysis an =
      testing::analyseOscillation(run.t, run.q, run.omega, true);
  const testing::DampedCosineFit& fit = an.fit;
  const auto& crossings = an.crossings;
  const Real fitted = an.fittedPeriod, crossing = an.crossingPeriod;
  std::printf(
      "l = 2 oscillation, d = R/%.0f: Lamb %.2f ms, fit %.2f ms (%+.1f %%, damping %.1f 1/s), "
      "zero crossings (%zu) %.2f ms (%+.1f %%); %ld + %ld steps\n",
      o.perR, period * 1e3, fitted * 1e3, 100 * (fitted / period - 1), fit.damping,
      crossings.size(), crossing * 1e3, 100 * (crossing / period - 1), run.relaxSteps, run.steps);
  // Tolerance 10 %: the criterion. The known systematic shifts are each well inside it:
  // the closed box (a drop in a rigid sphere of radius b: the outer inertia grows by
  // (1 + (3/2)(R/b)^5) / (1 - (R/b)^5), +1.6 % on the period for b = 2 R, less for the cube),
  // the amplitude (Zrnic & Brenn 2021, J. Fluid Mech. 923 A9: -5 % on the frequency at aspect
  // ratio 1.5, i.e. eps ~ 0.29; eps^2 scaling gives ~ -1.4 % at 0.15), the damping (a damped
  // oscillator's sqrt(1 - (beta/omega)^2), ~ -5 % at the measured beta ~ 26 1/s) and the
  // resolution (the Laplace jump reads 5-6 % low at d = R/6, validation 1, i.e. sigma_eff ~ 0.94
  // sigma: +3 % on the period).
  CHECK(std::abs(fitted / period - 1) < 0.10);
  // Zero crossings: the kick (t = 0), the crossing near T/2 and the one near T.
  REQUIRE(crossings.size() >= 3);
  CHECK(std::abs(crossing / period - 1) < 0.10);
  // The oscillation decays (any dissipation is positive) and the fit found it (amplitude well
  // above the residual: the signal is not the particle noise).
  CHECK(fit.damping > 0);
  CHECK(fit.amplitude > 5 * fit.rms);
}
