// Hydrostatic tank at rest (validation 1), for WCSPH and DFSPH.
//
// A 4 x 4 x 8 cm water column (d = 5 mm, 1,024 particles) settles for 0.6 s; over the next 0.4 s
// the pressure of every particle and its position are averaged in time, then compared layer by
// layer with rho g (H - y). Time averaging is part of the measurement, not a smoothing trick:
// the column's own acoustic and sloshing modes (period ~ 4H/c and ~ 2 pi sqrt(W/g) ~ 0.1 s) make
// any single snapshot deviate by several per cent from the mean state, for any solver (a snapshot
// at t = 0.6 s was +8 % off for WCSPH). The hydrostatic claim is about the mean state.
#include <catch2/catch.hpp>

#include <cstdio>
#include <map>

#include "scene_fixtures.h"

using namespace sim;

namespace {

constexpr Real kSpacing = 0.005, kWidth = 0.04, kHeight = 0.08;  // [m]
constexpr Real kSettle = 0.6, kWindow = 0.4;                     // [s]
constexpr Real kRho = 1000.0, kG = 9.81;

struct ProfileResult {
  int layers = 0;
  Real meanError = 0, maxError = 0;  // [1] |p_layer - rho g depth| / (rho g H)
  Real kineticAfterImpact = 0;       // [J] at t = 0.25 s, after the column has met the floor
  Real kineticWindow = 0;            // [J] mean over the averaging window
  Real maxCompression = 0;           // [1] largest mean compression a step reported in the window
  long steps = 0, rejected = 0;
  bool finite = true, contained = true;
};

ProfileResult runProfile(const PipelineOptions& options) {
  auto tank = testing::hydrostaticTank(kWidth, kHeight, kSpacing);
  World& w = *tank.world;
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  ProfileResult r;
  while (w.time < 0.25) pipeline.step(w);
  r.kineticAfterImpact = kineticEnergy(w);
  while (w.time < kSettle) pipeline.step(w);

  // Time averages keyed by particle id (the pipeline re-sorts particles every 16 steps).
  const Index n = static_cast<Index>(w.particles.size());
  std::vector<Real> pressureTime(n, 0.0);
  std::vector<Vec3> positionTime(n, Vec3::Zero());
  Real elapsed = 0, kineticTime = 0;
  const long stepsBefore = w.stepCount;
  while (w.time < kSettle + kWindow) {
    const Real dt = pipeline.step(w);
    const auto& pressure = w.particles.fields.get<Real>("pressure");
    for (Index i = 0; i < n; ++i) {
      pressureTime[w.particles.id[i]] += dt * pressure[i];
      positionTime[w.particles.id[i]] += dt * w.particles.x[i];
    }
    elapsed += dt;
    kineticTime += dt * kineticEnergy(w);
    r.maxCompression = std::max(r.maxCompression, pipeline.solver().stats().averageCompression);
  }
  r.steps = w.stepCount - stepsBefore;
  r.rejected = pipeline.rejectedSteps();
  r.kineticWindow = kineticTime / elapsed;
  r.finite = allFinite(w);
  const Vec3 lo = tank.spec.innerMin, hi = tank.spec.innerMax;
  for (const Vec3& x : w.particles.x)
    r.contained = r.contained && (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();

  Real top = 0;
  for (Index id = 0; id < n; ++id) top = std::max(top, positionTime[id].y() / elapsed);
  const Real H = top + 0.5 * kSpacing;  // free surface: half a spacing above the top layer
  const Real h = w.supportRadius();
  // Interior particles only: more than h below the free surface (kernel deficiency there) and
  // more than h from every wall (the single-layer Akinci wall term biases density within h).
  std::map<int, std::tuple<Real, Real, int>> layers;  // pressure sum, depth sum, count
  for (Index id = 0; id < n; ++id) {
    const Vec3 x = positionTime[id] / elapsed;
    if (H - x.y() < h || x.y() < h || x.x() < h || x.z() < h || hi.x() - x.x() < h ||
        hi.z() - x.z() < h)
      continue;
    auto& [p, depth, count] = layers[static_cast<int>(x.y() / kSpacing)];
    p += pressureTime[id] / elapsed;
    depth += H - x.y();
    ++count;
  }
  Real sum = 0;
  for (const auto& [k, layer] : layers) {
    const auto& [p, depth, count] = layer;
    if (count < 4) continue;
    const Real error = std::abs(p / count - kRho * kG * depth / count) / (kRho * kG * H);
    sum += error;
    r.maxError = std::max(r.maxError, error);
    ++r.layers;
  }
  r.meanError = r.layers > 0 ? sum / r.layers : 1.0;
  std::printf(
      "%s hydrostatic: %d layers, mean error %.4f, max %.4f; KE %.3g J after impact, %.3g J "
      "in window; %ld steps in window, %ld rejected in all\n",
      std::string(pipeline.solver().name()).c_str(), r.layers, r.meanError, r.maxError,
      r.kineticAfterImpact, r.kineticWindow, r.steps, r.rejected);
  return r;
}

// Tolerances, in units of rho g H (H ~ 7.5 cm, the column widens to fill the tank):
// - the free surface H is known to about a quarter spacing (the top layer is not flat):
//   (d/4)/H = 1.7 %;
// - compressibility changes the mass per height: WCSPH at c = 10 v_max compresses by
//   rho g H/(rho c^2) = 0.5 %, DFSPH by its tolerance 0.1 %;
// so the mean over layers must be within 3 %. A single layer also carries the sampling error of
// its ~30 particles' mean depth and pressure in a disordered packing: 5 %.
void checkProfile(const ProfileResult& r) {
  CHECK(r.finite);
  CHECK(r.contained);
  REQUIRE(r.layers >= 8);
  CHECK(r.meanError < 0.03);
  CHECK(r.maxError < 0.05);
  // Kinetic energy decays: the motion left from the column meeting the floor has died down by at
  // least a factor of 3 (measured: ~6x for DFSPH, ~20x for WCSPH) rather than being sustained by
  // the solver.
  CHECK(r.kineticWindow < r.kineticAfterImpact / 3);
  // A calm fluid needs no step redone: the time step from the CFL and body-force bounds must be
  // consistent with the displacement guard (at most 1 % of steps rejected).
  CHECK(r.rejected <= r.steps / 100);
}

}  // namespace

PipelineOptions optionsFor(const char* solver) {
  PipelineOptions options;
  options.solver = solver;
  options.wcsph.speedOfSound = 10 * std::sqrt(2 * kG * kHeight);  // 10x the largest flow speed
  return options;
}

TEST_CASE("WCSPH hydrostatic tank matches rho g (H - y)", "[validation][hydrostatic]") {
  checkProfile(runProfile(optionsFor("wcsph")));
}

TEST_CASE("DFSPH hydrostatic tank matches rho g (H - y) within its density tolerance",
          "[validation][hydrostatic]") {
  const PipelineOptions options = optionsFor("dfsph");
  const ProfileResult r = runProfile(options);
  checkProfile(r);
  // Every step's mean compression stays below the solver's tolerance (Bender & Koschier 2017).
  CHECK(r.maxCompression <= options.dfsph.densityTolerance);
}

// Every other solver on the same tank, against the same reference and bounds.
TEST_CASE("INDSPH hydrostatic tank matches rho g (H - y)", "[validation][hydrostatic]") {
  checkProfile(runProfile(optionsFor("indsph")));
}

TEST_CASE("number-density baseline hydrostatic tank matches rho g (H - y)",
          "[validation][hydrostatic]") {
  checkProfile(runProfile(optionsFor("number_density")));
}

// IISPH at its default tolerance 1e-4 (mean compression; the INDSPH eta). At 1e-3 its worst
// interior layer read +6 %: relaxed Jacobi stops with a long-wavelength
// pressure error over the column that a mean compression of 1e-3 still allows (3e-4: 3.8 %,
// 1e-4: 3.2 %, mean 1.7 %), so the tolerance, not the wall term, was the cause.
TEST_CASE("IISPH hydrostatic tank matches rho g (H - y)", "[validation][hydrostatic]") {
  checkProfile(runProfile(optionsFor("iisph")));
}

// VSLSPH (per-particle smoothing length, Li et al. 2023) on the same tank, reference and bounds:
// its state equation is WCSPH's linearised at the same speed of sound, so the same compressibility
// allowance holds; the variable support changes the density estimate, not the force balance.
TEST_CASE("VSLSPH hydrostatic tank matches rho g (H - y)", "[validation][hydrostatic]") {
  checkProfile(runProfile(optionsFor("vslsph")));
}
