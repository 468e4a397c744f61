// Hydrostatic tank at rest (issue 2, validation 1): the pressure profile matches rho g (H - y),
// the density error stays below the solver tolerance, and the kinetic energy decays.
#include <catch2/catch.hpp>

#include <cstdio>

#include "scene_fixtures.h"

using namespace sim;

namespace {

struct HydrostaticResult {
  Real meanRelativeError;   // mean |p - rho g (H - y)| / (rho g H) over particles below the surface layer
  Real maxRelativeError;
  Real kineticEarly, kineticLate;
  Real averageCompression;
};

HydrostaticResult runTank(const PipelineOptions& options, Real settleTime) {
  const Real d = 0.005, width = 0.08, height = 0.16;
  auto tank = testing::hydrostaticTank(width, height, d);
  World& w = *tank.world;
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  HydrostaticResult r{};
  while (w.time < 0.5 * settleTime) pipeline.step(w);
  r.kineticEarly = kineticEnergy(w);
  while (w.time < settleTime) pipeline.step(w);
  r.kineticLate = kineticEnergy(w);
  r.averageCompression = pipeline.solver().stats().averageCompression;

  const auto& pressure = w.particles.fields.get<Real>("pressure");
  const Real rho = 1000.0, g = 9.81;
  // Free-surface height: the settled column's top particle layer plus half a spacing.
  Real top = 0;
  for (const Vec3& x : w.particles.x) top = std::max(top, x.y());
  const Real H = top + 0.5 * d;
  Real sum = 0, maxErr = 0;
  int count = 0;
  for (Index i = 0; i < w.particles.size(); ++i) {
    const Real depth = H - w.particles.x[i].y();
    if (depth < w.supportRadius()) continue;  // the free-surface layer lacks neighbours
    const Real err = std::abs(pressure[i] - rho * g * depth) / (rho * g * H);
    sum += err;
    maxErr = std::max(maxErr, err);
    ++count;
  }
  r.meanRelativeError = sum / count;
  r.maxRelativeError = maxErr;
  std::printf("%s: mean err %.4f max err %.4f KE %.3g -> %.3g, compression %.2e, steps %ld\n",
              options.solver.c_str(), r.meanRelativeError, r.maxRelativeError, r.kineticEarly,
              r.kineticLate, r.averageCompression, w.stepCount);
  return r;
}

}  // namespace

TEST_CASE("DFSPH hydrostatic tank matches rho g (H - y)", "[validation][hydrostatic]") {
  PipelineOptions options;
  options.solver = "dfsph";
  const auto r = runTank(options, 1.0);
  CHECK(r.meanRelativeError < 0.02);
  CHECK(r.maxRelativeError < 0.05);
  CHECK(r.averageCompression <= options.dfsph.densityTolerance);
  CHECK(r.kineticLate < r.kineticEarly);
}

TEST_CASE("WCSPH hydrostatic tank matches rho g (H - y)", "[validation][hydrostatic]") {
  PipelineOptions options;
  options.solver = "wcsph";
  options.wcsph.speedOfSound = 10 * std::sqrt(2 * 9.81 * 0.16);
  const auto r = runTank(options, 1.0);
  CHECK(r.meanRelativeError < 0.02);
  CHECK(r.maxRelativeError < 0.05);
  CHECK(r.kineticLate < r.kineticEarly);
}
