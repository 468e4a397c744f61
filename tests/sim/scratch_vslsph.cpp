#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include "scene_fixtures.h"
using namespace sim;
TEST_CASE("scratch vslsph", "[scratch]") {
  const Real d = 0.005, height = 0.06;
  auto tank = testing::hydrostaticTank(0.03, height, d);
  World& w = *tank.world;
  PipelineOptions options;
  options.solver = getenv("SOLVER") ? getenv("SOLVER") : "vslsph";
  options.wcsph.speedOfSound = 10 * std::sqrt(2 * 9.81 * height);
  if (getenv("HMIN")) options.vslsph.minSupportFactor = atof(getenv("HMIN"));
  if (getenv("HMAX")) options.vslsph.maxSupportFactor = atof(getenv("HMAX"));
  if (getenv("AV")) options.vslsph.artificialViscosity = atof(getenv("AV"));
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  for (int s = 0; s < 100000 && w.time < (getenv("TEND") ? atof(getenv("TEND")) : 0.3); ++s) {
    pipeline.step(w);
    const auto& st = pipeline.solver().stats();
    if (s % 500 == 0) {
      Real hmin = 1, hmax = 0, pmax = 0;
      if (w.particles.fields.has("support_radius")) {
        for (Real h : w.particles.fields.get<Real>("support_radius")) { hmin = std::min(hmin, h); hmax = std::max(hmax, h); }
      }
      for (Real p : w.particles.fields.get<Real>("pressure")) pmax = std::max(pmax, p);
      std::printf("step %d t %.4f dt %.2e KE %.3g comp %.3e max %.3e h [%.4f %.4f] pmax %.1f pairs %zu\n", s, w.time, w.lastTimeStep, kineticEnergy(w), st.averageCompression, st.maxCompression, hmin, hmax, pmax, w.fluidNeighbors().totalPairs());
    }
  }
}
