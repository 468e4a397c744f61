// The settling run shared by the contact-angle scenes with straight contact lines (the meniscus,
// interface_meniscus.h, and the sessile ridge, interface_ridge.h): INDSPH, free-slip walls (a
// no-slip wall pins a contact line, Huh & Scriven 1971), the box declared closed, stepped to
// tEnd. The angle is the mean over the last fifth of the run, when the start's transient has
// decayed. The round sessile droplet (interface_sessile.h) keeps its own loop, which has a
// choice of solver and relaxation steps, but reports the same result.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

#include "interface_fixtures.h"

namespace sim::testing {

// World parameters of the closed box `spec` whose walls are `layers` lattice layers thick, without
// gravity: the domain reaches one spacing beyond the outermost layer.
inline WorldParameters layeredBoxParameters(const TankSpec& spec, Real d,
                                            const WallLayers& layers) {
  WorldParameters params;
  params.particleSpacing = d;
  params.gravity = Vec3::Zero();
  params.domain = tankDomain(spec, d);
  params.domain.extend(spec.innerMin - Vec3::Constant((layers.count + 1) * d));
  params.domain.extend(spec.innerMax + Vec3::Constant((layers.count + 1) * d));
  return params;
}

struct AngleRunResult {
  Real angle = 0;       // [deg] through the oil, mean over the last fifth of the run
  Real finalAngle = 0;  // [deg] at the end
  long steps = 0;
  std::size_t particles = 0;
  double seconds = 0;  // [s] wall time of the stepping
  bool finite = true;
};

// `measure(world)` returns the angle in degrees; `describe(world)` one progress line, printed ten
// times during the run when `print` is set.
template <class Measure, class Describe>
AngleRunResult settleContactAngle(World& w, Real tEnd, bool print, Measure measure,
                                  Describe describe) {
  PipelineOptions options;
  options.solver = "indsph";
  options.wallFriction = false;
  options.closedDomain = Force::kOn;
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  AngleRunResult r;
  const auto t0 = std::chrono::steady_clock::now();
  Real sum = 0, next = 0;
  int samples = 0;
  while (w.time < tEnd) {
    pipeline.step(w);
    if (w.time > 0.8 * tEnd) {
      sum += measure(w);
      ++samples;
    }
    if (print && w.time >= next) {
      std::printf("  t = %.4f s  %s  steps %ld\n", w.time, describe(w).c_str(), w.stepCount);
      std::fflush(stdout);
      next += tEnd / 10;
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.finite = allFinite(w);
  r.finalAngle = measure(w);
  r.angle = samples > 0 ? sum / samples : r.finalAngle;
  r.steps = w.stepCount;
  r.particles = w.particles.size();
  return r;
}

}  // namespace sim::testing
