// The settling run shared by the contact-angle scenes with straight contact lines (the meniscus,
// interface_meniscus.h, and the sessile ridge, interface_ridge.h): INDSPH, free-slip walls (a
// no-slip wall pins a contact line, Huh & Scriven 1971), the box declared closed, stepped to
// tEnd. The angle is the mean over the last fifth of the run, when the start's transient has
// decayed. The round sessile droplet (interface_sessile.h) assembles its own pipeline (a choice of
// solver, relaxation steps) and then runs the same stepping loop, stepAndMeasureAngle.
#pragma once

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "interface_fixtures.h"

namespace sim::testing {

// The closed box `spec` (origin at innerMin = 0, lid on) with walls of three lattice layers,
// without gravity, holding no particles yet: oil (970 kg/m^3) and aqueous (1000 kg/m^3) of
// dynamic viscosity `viscosity` [Pa s], sigma 0.04 N/m between them. The scene tags the walls
// that carry its contact angle and fills the box. Shared by the meniscus, the ridge and the bench's
// static wedge.
struct OilAqueousBox {
  std::unique_ptr<World> world;
  int oil = -1, aqueous = -1;
};

inline OilAqueousBox oilAqueousLayeredBox(const TankSpec& spec, Real d, Real viscosity) {
  const WallLayers layers{3};
  WorldParameters params;
  params.particleSpacing = d;
  params.gravity = Vec3::Zero();
  params.domain = tankDomain(spec, d);
  // The domain reaches one spacing beyond the outermost layer.
  params.domain.extend(spec.innerMin - Vec3::Constant((layers.count + 1) * d));
  params.domain.extend(spec.innerMax + Vec3::Constant((layers.count + 1) * d));
  OilAqueousBox box;
  box.world = std::make_unique<World>(params);
  World& w = *box.world;
  box.oil = w.materials.add(liquid("oil", 970, viscosity));
  box.aqueous = w.materials.add(liquid("aqueous", 1000, viscosity));
  w.materials.setInterfacialTension(box.oil, box.aqueous, 0.04);
  addTankWalls(w, spec, d, 0, layers);
  return box;
}

struct AngleRunResult {
  Real angle = 0;       // [deg] through the oil, mean over the last fifth of the run
  Real finalAngle = 0;  // [deg] at the end
  long steps = 0;
  std::size_t particles = 0;
  double seconds = 0;  // [s] wall time of the stepping
  bool finite = true;
};

// Steps `pipeline` (attached) for `duration` from the world's current time. `measure(world)`
// returns the angle in degrees, averaged over the last fifth of the run; `describe(world)` is one
// progress line, printed ten times during the run when `print` is set. `seconds` is the wall time
// of these steps.
template <class Measure, class Describe>
AngleRunResult stepAndMeasureAngle(World& w, Pipeline& pipeline, Real duration, bool print,
                                   Measure measure, Describe describe) {
  AngleRunResult r;
  const auto t0 = std::chrono::steady_clock::now();
  const Real tStart = w.time;
  Real sum = 0, next = 0;
  int samples = 0;
  while (w.time - tStart < duration) {
    pipeline.step(w);
    if (w.time - tStart > 0.8 * duration) {
      sum += measure(w);
      ++samples;
    }
    if (print && w.time - tStart >= next) {
      std::printf("  t = %.4f s  %s  steps %ld\n", w.time, describe(w).c_str(), w.stepCount);
      std::fflush(stdout);
      next += duration / 10;
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

// The straight-line scenes' run: INDSPH, free slip, the box declared closed, from t = 0 to tEnd.
template <class Measure, class Describe>
AngleRunResult settleContactAngle(World& w, Real tEnd, bool print, Measure measure,
                                  Describe describe) {
  PipelineOptions options;
  options.solver = "indsph";
  options.wallFriction = false;
  options.closedDomain = StageOverride::kOn;
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  return stepAndMeasureAngle(w, pipeline, tEnd, print, measure, describe);
}

}  // namespace sim::testing
