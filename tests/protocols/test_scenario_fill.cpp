// The default fluid fill (MassRule::kRelaxedFill). With the one-layer wall: particles at rest
// mass hold the cavity minus the wall's d/2 shell and start near rest density after the start-up
// shifting pass. With the layered wall (a rigid cavity's default, accuracy.wall_model "auto"):
// the lattice inside the mesh holds the whole cavity, one lattice with the wall, at rest density
// with no shifting. The implicit solver INDSPH steps the tiny protocol from either start without
// blowing up.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "meshing/mesh_query.h"
#include "protocols/assembly/assemble_scenario.h"
#include "protocols/assembly/relax_fill.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/scenario/scenario.h"
#include "sim/world/pipeline.h"
#include "sim/world/stage_registry.h"

namespace fs = std::filesystem;
using namespace protocols;

namespace {

const fs::path kProtocols = fs::path(TAMPONADE_SOURCE_DIR) / "data" / "protocols";

// Fluid particles' volume fractions C (relax_fill.h): mean and max.
struct FractionStats {
  double mean = 0.0;
  double max = 0.0;
};
FractionStats fractionStats(const Scenario& s) {
  const std::vector<double> c = volumeFractions(*s.world);
  FractionStats f;
  std::size_t n = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const int m = s.world->particles.material[i];
    if (m != s.phases[0].materialIndex && m != s.phases[1].materialIndex) continue;
    f.mean += c[i], ++n, f.max = std::max(f.max, c[i]);
  }
  f.mean /= static_cast<double>(n);
  return f;
}

// Deepest penetration of a fluid particle towards / past the wall, in spacings: for each fluid
// particle the nearest wall particle b, s = (x - x_b) . n_b (n_b outward); returns max s / d
// (negative: every particle is inside, at least -s d from the nearest wall sample's plane).
double deepestPenetration(const Scenario& s) {
  const sim::World& w = *s.world;
  double deepest = -1e9;
  for (std::size_t i = 0; i < w.particles.size(); ++i) {
    double best = 1e300;
    std::size_t nearest = 0;
    for (std::size_t b = 0; b < w.walls.size(); ++b) {
      const double r = (w.particles.x[i] - w.walls.x[b]).squaredNorm();
      if (r < best) best = r, nearest = b;
    }
    deepest =
        std::max(deepest, (w.particles.x[i] - w.walls.x[nearest]).dot(w.walls.normal[nearest]));
  }
  return deepest / w.particleSpacing();
}

Protocol singleLayer(Protocol p) {
  p.accuracy.wallModel.value = WallModelName::kSingleLayer;
  return p;
}

// Deepest fluid particle past the cavity mesh, in spacings (negative: every one inside, at
// least that far from the mesh).
double deepestPastMesh(const Scenario& s) {
  const meshing::MeshQuery query(s.cavity);
  double deepest = -1e9;
  for (std::size_t i = 0; i < s.world->particles.size(); ++i) {
    const sim::Vec3& x = s.world->particles.x[i];
    const double r = std::sqrt(query.squaredDistance(x));
    deepest = std::max(deepest, query.isInside(x) ? -r : r);
  }
  return deepest / s.world->particleSpacing();
}

// Steps a scene with its own pipeline and records the largest volume fraction C seen, then
// whether every position and velocity is finite and the fastest particle.
struct StepStats {
  bool finite = true;
  double maxFraction = 0.0;  // [1]
  double maxSpeed = 0.0;     // [m/s]
};
StepStats stepScene(Scenario& s, int steps) {
  sim::Pipeline pipeline = sim::assemblePipeline(*s.world, s.pipelineOptions);
  pipeline.attach(*s.world);
  StepStats out;
  for (int step = 0; step < steps; ++step) {
    pipeline.step(*s.world);
    out.maxFraction = std::max(out.maxFraction, fractionStats(s).max);
  }
  for (std::size_t i = 0; i < s.world->particles.size(); ++i) {
    out.finite =
        out.finite && s.world->particles.x[i].allFinite() && s.world->particles.v[i].allFinite();
    out.maxSpeed = std::max(out.maxSpeed, s.world->particles.v[i].norm());
  }
  return out;
}

}  // namespace

TEST_CASE("layered wall fill: the lattice inside the mesh holds the cavity at rest density",
          "[unit][scenario]") {
  const Protocol p = parseProtocol((kProtocols / "tiny.toml").string());
  const Scenario s = assembleScenario(p);
  REQUIRE(s.layeredWalls);  // a rigid cavity's default (accuracy.wall_model "auto")
  const double d = s.accuracy.particleSpacing;  // [m]
  const sim::World& w = *s.world;
  for (std::size_t i = 0; i < w.particles.size(); ++i)
    CHECK(w.particles.mass[i] ==
          Approx(w.restDensityOf(static_cast<sim::Index>(i)) * d * d * d).epsilon(1e-14));
  // N d^3 against V: a lattice cut at the mesh holds V on average over lattice offsets; on one
  // offset the staircase changes the count by a fraction of a layer, A d / V = 17 % here, so the
  // bound 3 % is a sixth of a layer (the same bound as the unit test of the wall itself).
  const FluidPhase& aq = s.phases[0];
  const FluidPhase& oil = s.phases[1];
  const double held = static_cast<double>(oil.count + aq.count) * d * d * d;  // [m^3]
  CHECK(s.heldVolumeRatio == Approx(held / s.cavityVolume).epsilon(1e-12));
  CHECK(std::abs(s.heldVolumeRatio - 1.0) < 0.03);
  // One lattice with three wall layers: every fluid particle's kernel support is full of
  // particles of volume d^3, so C = sum_j V_j W_ij is the lattice sum, 1 up to its discretisation
  // (the cubic spline's lattice sum at h = 2d is 1 within 1e-3); a fluid particle next to a
  // stepped wall sees a full lattice too. Bound: mean and max within 1 %.
  const FractionStats c = fractionStats(s);
  WARN("layered: t = 0: C mean " << c.mean << ", max " << c.max << ", held " << s.heldVolumeRatio
                                 << ", deepest past the mesh " << deepestPastMesh(s) << " d");
  CHECK(c.mean == Approx(1.0).margin(0.01));
  CHECK(c.max == Approx(1.0).margin(0.01));
  CHECK(c.mean == Approx(s.startMeanFraction).epsilon(1e-12));
  CHECK(deepestPastMesh(s) <= 0.0);
}

TEST_CASE("layered wall fill: INDSPH steps the tiny protocol, finite and inside the mesh",
          "[stability][scenario]") {
  const Protocol p = parseProtocol((kProtocols / "tiny.toml").string());
  Scenario s = assembleScenario(p);
  REQUIRE(s.layeredWalls);
  const StepStats r = stepScene(s, 30);
  const double maxC = r.maxFraction, maxSpeed = r.maxSpeed;
  const bool finite = r.finite;
  WARN("layered, after 30 steps, t = " << s.world->time << " s: max C " << maxC << ", max speed "
                                       << maxSpeed << ", deepest past the mesh "
                                       << deepestPastMesh(s) << " d");
  CHECK(finite);
  // The fluid's first layer sits d/2 in front of the wall's (the lattice): a particle may move
  // within that half spacing but not through the wall layer at d/2 behind the mesh.
  CHECK(deepestPastMesh(s) < 0.5);
  // Compression stays bounded: the solve stops at a mean 0.5 % (draft), a particle's local C may
  // exceed it; bound 5 % (what the stability tests allow for a bounded compression).
  CHECK(maxC < 1.05);
}

TEST_CASE("default fill: rest-mass particles hold the cavity minus the wall shell at rest density",
          "[unit][scenario]") {
  const Protocol p = singleLayer(parseProtocol((kProtocols / "tiny.toml").string()));
  const Scenario s = assembleScenario(p);
  const double d = s.accuracy.particleSpacing;  // [m]
  const sim::World& w = *s.world;
  const FluidPhase& aq = s.phases[0];
  const FluidPhase& oil = s.phases[1];
  // Every particle carries rho d^3: no compression built into the masses.
  for (std::size_t i = 0; i < w.particles.size(); ++i)
    CHECK(w.particles.mass[i] ==
          Approx(w.restDensityOf(static_cast<sim::Index>(i)) * d * d * d).epsilon(1e-14));
  // Volumes held: N d^3 against V - A d/2, the fluid's share of the cavity with Akinci walls
  // (the wall particles' volumes stand for the d/2 shell). A lattice cut at gap g holds
  // V - A g on average over lattice offsets (sample_volume.h); on one offset the staircase along
  // the wall changes the count by up to ~A d / (2 d^3) x d^3 x (fraction of a layer), measured
  // for this eye: see WARN; bound 5 % (a third of the A d/2 shell, 17 % of V at d = 1.2 mm).
  const double held = static_cast<double>(oil.count + aq.count) * d * d * d;  // [m^3]
  WARN("held / (V - A d/2) = " << s.heldVolumeRatio << ", held / V = " << held / s.cavityVolume
                               << ", N = " << oil.count + aq.count);
  CHECK(s.heldVolumeRatio ==
        Approx(held / (s.cavityVolume - 0.5 * d * s.cavityArea)).epsilon(1e-12));
  CHECK(std::abs(s.heldVolumeRatio - 1.0) < 0.05);
  // Phases: the oil holds the fill fraction of the particles to one particle.
  const double share = static_cast<double>(oil.count) / static_cast<double>(oil.count + aq.count);
  CHECK(std::abs(share - 0.9) <= 0.5 / static_cast<double>(oil.count + aq.count) + 1e-15);
  // Start density after the shifting pass.
  const FractionStats c = fractionStats(s);
  WARN("t = 0: C mean " << c.mean << ", max " << c.max << " (scenario: " << s.startMeanFraction
                        << ", " << s.startMaxFraction << "), penetration "
                        << deepestPenetration(s));
  CHECK(c.mean == Approx(s.startMeanFraction).epsilon(1e-12));
  CHECK(s.fillCompression == Approx(s.startMeanFraction).epsilon(1e-12));
  CHECK(deepestPenetration(s) < 0.0);
}

TEST_CASE("default fill: INDSPH steps the tiny protocol, finite and inside the wall",
          "[stability][scenario]") {
  const Protocol p = singleLayer(parseProtocol((kProtocols / "tiny.toml").string()));
  Scenario s = assembleScenario(p);
  s.pipelineOptions.solver = "indsph";
  const StepStats r = stepScene(s, 30);
  const double maxC = r.maxFraction, maxSpeed = r.maxSpeed;
  const bool finite = r.finite;
  WARN("after 30 steps, t = " << s.world->time << " s: max C " << maxC << ", max speed " << maxSpeed
                              << ", penetration " << deepestPenetration(s));
  CHECK(finite);
  CHECK(deepestPenetration(s) < 0.0);
}
