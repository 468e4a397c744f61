// Implicit viscosity (Weiler et al. 2018, sim/effects/viscosity_weiler2018.h;
// docs/methods/viscosity.md, validation).
//
// - start-up plane Couette flow at 1000 cSt between two wall plates, the top one sliding in its own
//   plane: transient and steady profile against the closed form;
// - a 5000 cSt oil column collapsing in a tank under gravity runs at the CFL step, far above the
//   explicit viscous limit, without NaN and with bounded energy;
// - the stage alone: linear momentum to round-off without walls, uniform translation and rigid
//   rotation untouched (closed forms: the Laplacian of both is zero), kinetic energy dissipated;
// - the stage rule: explicit viscosity for water-like fluids, implicit for viscous oils.
#include <catch2/catch.hpp>

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "scene_fixtures.h"
#include "sim/effects/viscosity_weiler2018.h"
#include "sim/fluid/density.h"

using namespace sim;

namespace {

constexpr Real kPi = 3.14159265358979323846;

// Silicone oil of the given kinematic viscosity [m^2/s] at 970 kg/m^3 (reference-data 1.1).
Material siliconeOil(Real kinematicViscosity) {
  Material m;
  m.name = "silicone_oil";
  m.restDensity = 970.0;                                    // [kg/m^3]
  m.dynamicViscosity = kinematicViscosity * m.restDensity;  // [Pa s]
  return m;
}

// ---------------------------------------------------------------------------------------------
// Start-up Couette flow. The engine has no periodic boundaries, so the fluid is a finite slab
// between two plates that reach 4 spacings beyond it in x and z (free side faces, no gravity).
// The top plate's wall particles carry a tangential velocity U (the wall field "velocity"): a
// plate sliding in its own plane has the same particle positions at every instant, so static wall
// particles with a surface velocity are the exact boundary condition, not an approximation. Far
// from the side faces the flow is the one between infinite plates: a shear flow u(y) e_x has
// u . grad u = 0 and no pressure gradient, so the Navier-Stokes equations reduce to the diffusion
// equation u_t = nu u_yy with u(0) = 0, u(H) = U, whose solution from rest is
//   u(y, t) = U y/H - (2U/pi) sum_n (-1)^(n+1)/n sin(n pi y/H) exp(-n^2 pi^2 nu t / H^2).
// (Deen, "Analysis of Transport Phenomena", start-up of Couette flow.) H is the distance between
// the two wall-particle layers: the layers sit on the plate surfaces (box_scene.h convention).
struct CouetteScene {
  std::unique_ptr<World> world;
  Real height = 0;  // [m] H, plate to plate
};

constexpr Real kCouetteSpacing = 1e-3;                  // [m] d
constexpr Real kCouetteViscosity = 1e-3;                // [m^2/s] 1000 cSt
constexpr Real kPlateSpeed = 0.01;                      // [m/s] U; Re = U H / nu = 0.14, laminar
constexpr int kCouetteLayers = 12, kCouetteWidth = 16;  // fluid layers (y) and columns (x, z)

// `lowerViscosity` [m^2/s]: if > 0, the lower half of the layers is a second oil of that viscosity
// (same density), for the two-layer test.
CouetteScene couetteScene(Real maxTimeStep, Real lowerViscosity = 0) {
  const Real d = kCouetteSpacing;
  const Real gap =
      testing::kWallGap * d;  // first fluid layer 1.2 d from a plate (scene_fixtures.h)
  CouetteScene s;
  s.height = 2 * gap + (kCouetteLayers - 1) * d;
  const Real margin = 4 * d, length = kCouetteWidth * d;
  WorldParameters params;
  params.particleSpacing = d;
  params.gravity = Vec3::Zero();
  params.maxTimeStep = maxTimeStep;
  params.domain = Box(Vec3(-margin - 2 * d, -2 * d, -margin - 2 * d),
                      Vec3(length + margin + 2 * d, s.height + 2 * d, length + margin + 2 * d));
  s.world = std::make_unique<World>(params);
  World& w = *s.world;
  w.materials.add(siliconeOil(kCouetteViscosity));
  auto& wallVelocity = w.walls.fields.add<Vec3>({kWallVelocityField, "m/s", true, false});
  const int plateCount = static_cast<int>(std::lround((length + 2 * margin) / d)) + 1;
  for (int a = 0; a < plateCount; ++a)
    for (int c = 0; c < plateCount; ++c) {
      const Real x = -margin + a * d, z = -margin + c * d;
      w.walls.add(Vec3(x, 0, z), Vec3(0, -1, 0), 0);
      w.walls.add(Vec3(x, s.height, z), Vec3(0, 1, 0), 1);
      wallVelocity.back() = Vec3(kPlateSpeed, 0, 0);
    }
  addFluidBlock(w, Vec3(0, gap - 0.5 * d, 0), Vec3(length, s.height - gap + 0.5 * d, length), d, 0);
  if (lowerViscosity > 0) {
    Material lower = siliconeOil(lowerViscosity);
    lower.name = "lower_oil";
    const int index = w.materials.add(lower);
    for (Index i = 0; i < w.particles.size(); ++i)
      if (w.particles.x[i].y() < 0.5 * s.height) w.particles.material[i] = index;
  }
  w.initialize();
  return s;
}

// [m/s] the closed form above, for kinematic viscosity nu [m^2/s]
Real couetteProfile(Real y, Real t, Real H, Real nu) {
  Real u = kPlateSpeed * y / H;
  for (int n = 1; n <= 200; ++n) {
    const Real sign = (n % 2 == 1) ? 1.0 : -1.0;
    u -= 2 * kPlateSpeed / kPi * sign / n * std::sin(n * kPi * y / H) *
         std::exp(-n * n * kPi * kPi * nu * t / (H * H));
  }
  return u;
}

// The shear viscosity the discrete operator has on a cubic lattice of spacing d, as a fraction of
// nu: its x-force on u_x = y^2/2 (for which nu u_yy = nu), i.e.
//   -2(d+2)/2 sum_j V dx^2 dy^2 W'(r) / (r (r^2 + 0.01 h^2))      (V = d^3, rest lattice).
// The sum equals 1 in the continuum limit; at h = 2d it is 0.70: on a cubic lattice the nearest
// neighbours lie on the axes, so the fourth moments of the kernel are anisotropic (the dx^4 sum is
// 1.19 instead of 1, the dx^2 dy^2 sum 0.70). This is a property of the operator (Weiler 2018,
// Monaghan 2005), independent of the solver, and computed here from the kernel alone.
Real latticeShearFactor(const Kernel& kernel, Real d) {
  const Real h = kernel.supportRadius();
  const int reach = static_cast<int>(std::ceil(h / d));
  Real sum = 0;
  for (int a = -reach; a <= reach; ++a)
    for (int b = -reach; b <= reach; ++b)
      for (int c = -reach; c <= reach; ++c) {
        const Vec3 x = d * Vec3(a, b, c);
        const Real r2 = x.squaredNorm();
        if (r2 == 0) continue;
        // gradW = W'(r) x / r, so x . gradW = r W'(r)
        const Real rdW = x.dot(kernel.gradW(x));
        sum -= 5 * d * d * d * x.x() * x.x() * x.y() * x.y() * rdW / (r2 * (r2 + 0.01 * h * h));
      }
  return sum;
}

// Mean u_x of each fluid layer in the central quarter of the slab (more than 4 d = 2 h from the
// free side faces, where the flow is that between infinite plates), against the closed form.
// Mean height and x-velocity of each lattice layer of a Couette scene, over the central half
// of the plates in x and z (away from the side walls).
struct LayerMean {
  Real y = 0, u = 0;  // [m], [m/s]
};
std::vector<LayerMean> couetteLayers(const World& w) {
  const Real d = kCouetteSpacing, length = kCouetteWidth * d;
  std::vector<Real> sumU(kCouetteLayers, 0), sumY(kCouetteLayers, 0);
  std::vector<int> count(kCouetteLayers, 0);
  for (Index i = 0; i < w.particles.size(); ++i) {
    const Vec3& x = w.particles.x[i];
    if (std::abs(x.x() - 0.5 * length) > 0.25 * length ||
        std::abs(x.z() - 0.5 * length) > 0.25 * length)
      continue;
    const int k = static_cast<int>(std::lround((x.y() - testing::kWallGap * d) / d));
    if (k < 0 || k >= kCouetteLayers) continue;
    sumU[static_cast<std::size_t>(k)] += w.particles.v[i].x();
    sumY[static_cast<std::size_t>(k)] += x.y();
    ++count[static_cast<std::size_t>(k)];
  }
  std::vector<LayerMean> layers(count.size());
  for (std::size_t k = 0; k < count.size(); ++k) {
    REQUIRE(count[k] > 0);
    layers[k] = {sumY[k] / count[k], sumU[k] / count[k]};
  }
  return layers;
}

// Returns the largest layer error relative to U.
Real couetteError(const CouetteScene& s, Real nu, const char* label) {
  const World& w = *s.world;
  const std::vector<LayerMean> layers = couetteLayers(w);
  Real worst = 0;
  for (std::size_t k = 0; k < layers.size(); ++k) {
    const Real y = layers[k].y, u = layers[k].u;
    const Real expected = couetteProfile(y, w.time, s.height, nu);
    worst = std::max(worst, std::abs(u - expected) / kPlateSpeed);
    std::printf("  %s t=%.3f s layer %2zu y/H %.3f: u/U %.4f, closed form %.4f\n", label, w.time, k,
                y / s.height, u / kPlateSpeed, expected / kPlateSpeed);
  }
  return worst;
}

const ViscosityWeiler2018& implicitStage(const Pipeline& pipeline) {
  for (const auto& e : pipeline.effects())
    if (e->name() == "implicit_viscosity") return dynamic_cast<const ViscosityWeiler2018&>(*e);
  throw SimError("no implicit_viscosity stage");
}

}  // namespace

TEST_CASE("implicit viscosity: start-up Couette flow at 1000 cSt matches the closed form",
          "[validation][viscosity]") {
  const auto wallStart = std::chrono::steady_clock::now();
  // dt = 1 ms: 8x the explicit limit 0.125 d^2/nu = 0.125 ms, and short enough that backward
  // Euler follows the transient (its slowest mode, rate pi^2 nu/H^2 = 50/s, has lambda dt = 0.05,
  // a relative amplitude error of lambda dt / 2 per e-folding time).
  auto s = couetteScene(1e-3);
  World& w = *s.world;
  PipelineOptions options;
  options.solver = "dfsph";
  // XSPH smoothing is numerical damping that would act as extra viscosity near the plates (it
  // sees no wall neighbours); the test measures the physical viscosity alone.
  options.forced["velocity_smoothing"] = StageOverride::kOff;
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  REQUIRE(pipeline.hasStage("implicit_viscosity"));
  REQUIRE_FALSE(pipeline.hasStage("viscosity"));
  const Real H = s.height;
  const Real diffusionTime = H * H / kCouetteViscosity;  // [s] 0.18 s
  // Transient: at t = 0.1 H^2/nu the slowest mode has decayed to exp(-pi^2/10) = 0.37. It is
  // compared with the closed form at the operator's lattice shear viscosity (latticeShearFactor):
  // that checks the solver (CG, backward Euler, the moving wall), and the printed error at the
  // physical nu shows how much the discretisation slows the start-up.
  const Real shearFactor = latticeShearFactor(w.kernel, kCouetteSpacing);
  while (w.time < 0.1 * diffusionTime - 1e-9) pipeline.step(w);
  const Real transientPhysical = couetteError(s, kCouetteViscosity, "transient, physical nu");
  const Real transient = couetteError(s, shearFactor * kCouetteViscosity, "transient, lattice nu");
  // Steady: at t = 0.8 H^2/nu the slowest mode is exp(-7.9 * 0.7) = 4e-3 of U. The steady
  // profile does not depend on the viscosity's value, only on the operator being consistent
  // (zero on a linear field) and on the no-slip walls.
  while (w.time < 0.8 * diffusionTime - 1e-9) pipeline.step(w);
  const Real steady = couetteError(s, kCouetteViscosity, "steady");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  const auto& stage = implicitStage(pipeline);
  std::printf(
      "Couette 1000 cSt: %zu particles, %ld steps, lattice shear factor %.3f, max layer "
      "error at t = 0.1 H^2/nu %.2f %% (lattice nu) / %.2f %% (physical nu), steady "
      "%.2f %%, CG %.1f iterations/step, %.1f s\n",
      w.particles.size(), w.stepCount, shearFactor, 100 * transient, 100 * transientPhysical,
      100 * steady, static_cast<double>(stage.totalIterations()) / stage.solves(), seconds);
  CHECK(steady < 0.05);
  CHECK(transient < 0.05);
}

// ---------------------------------------------------------------------------------------------
namespace {

Real potentialEnergy(const World& w) {  // [J] relative to y = 0
  Real e = 0;
  for (Index i = 0; i < w.particles.size(); ++i)
    e -= w.particles.mass[i] * w.gravity.dot(w.particles.x[i]);
  return e;
}

}  // namespace

// A 5000 cSt oil column (2 x 3 x 2 cm, d = 2 mm, 1500 particles) settling in a closed-bottom tank
// under gravity with DFSPH for 0.3 s. The explicit viscous limit is 0.125 d^2/nu = 0.1 ms; the
// CFL step of the scene (body-force bound cfl sqrt(d/g) = 0.15 sqrt(d/g) = 2.14 ms, the flow
// being slow) is 21x larger. Every step must be that CFL step: not limited by a viscosity stage
// and not shortened by the displacement guard (the implicit solve must not create velocities the
// guard rejects).
TEST_CASE("implicit viscosity: a 5000 cSt oil column is stable at the CFL step",
          "[stability][viscosity]") {
  const auto wallStart = std::chrono::steady_clock::now();
  const Real d = 0.002, nu = 5e-3;  // [m], [m^2/s]
  const Real gap = (testing::kWallGap - 0.5) * d;
  TankSpec tank;
  tank.innerMax = Vec3(0.02 + 2 * gap, 0.05, 0.02 + 2 * gap);
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = tankDomain(tank, d);
  World w(params);
  w.materials.add(siliconeOil(nu));
  addTankWalls(w, tank, d);
  addFluidBlock(w, Vec3::Constant(gap), Vec3(gap + 0.02, gap + 0.03, gap + 0.02), d, 0);
  w.initialize();
  PipelineOptions options;
  options.solver = "dfsph";
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  REQUIRE(pipeline.hasStage("implicit_viscosity"));
  REQUIRE_FALSE(pipeline.hasStage("viscosity"));
  const Real explicitLimit = 0.125 * d * d / nu;  // [s]
  const Real e0 = kineticEnergy(w) + potentialEnergy(w);
  const Real pe0 = potentialEnergy(w);
  Real minDt = 1, maxKinetic = 0, worstEnergy = -1;
  int notCfl = 0, byViscosity = 0;
  while (w.time < 0.3) {
    const Real dt = pipeline.step(w);
    const std::string& by = pipeline.lastTimeStep().limitedBy;
    if (by != "cfl" && by != "max") ++notCfl;
    if (by.find("viscosity") != std::string::npos) ++byViscosity;
    minDt = std::min(minDt, dt);
    REQUIRE(allFinite(w));
    const Real kinetic = kineticEnergy(w);
    maxKinetic = std::max(maxKinetic, kinetic);
    // Energy: viscosity only dissipates; what the pressure solve may add is bounded by its
    // compression error. Relative to the potential energy available for release (pe0 - pe at
    // rest is a fraction of pe0), E(t) - E(0) must stay below 1 % of pe0.
    worstEnergy = std::max(worstEnergy, (kinetic + potentialEnergy(w) - e0) / pe0);
  }
  const auto& visc = implicitStage(pipeline);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  const Real meanDt = w.time / static_cast<Real>(w.stepCount);
  std::printf(
      "5000 cSt column: %zu particles, %ld steps, dt mean %.2e s min %.2e s (explicit "
      "limit %.2e s: %.0fx, %.0fx), %d steps shortened by the displacement guard (%ld "
      "rejections), max KE %.3e J, max energy gain %.2e of PE0, CG %.1f iterations/step, "
      "%.1f s\n",
      w.particles.size(), w.stepCount, meanDt, minDt, explicitLimit, meanDt / explicitLimit,
      minDt / explicitLimit, notCfl, pipeline.rejectedSteps(), maxKinetic, worstEnergy,
      static_cast<double>(visc.totalIterations()) / visc.solves(), seconds);
  CHECK(byViscosity == 0);
  CHECK(notCfl == 0);
  // The scene's CFL step is 21.4x the explicit limit (comment above); every step at the CFL step
  // means the smallest one is too. Fails if any step came near the explicit limit.
  CHECK(minDt > 20 * explicitLimit);
  CHECK(worstEnergy < 0.01);
}

// ---------------------------------------------------------------------------------------------
// The stage alone on a blob without walls: one implicit solve at a step 40x the explicit limit.
namespace {

struct Blob {
  std::unique_ptr<World> world;
  ViscosityWeiler2018 stage;
};

// A 10 x 10 x 10 lattice of 1000 cSt oil (d = 2 mm), jittered by 0.1 d so the lattice symmetry
// hides nothing, with densities from the summation. `velocity(x)` sets the initial field.
template <class F>
std::unique_ptr<Blob> blob(F&& velocity, int viscousMaterials = 1) {
  const Real d = 0.002;
  WorldParameters params;
  params.particleSpacing = d;
  params.gravity = Vec3::Zero();
  params.domain = Box(Vec3::Constant(-0.01), Vec3::Constant(0.03));
  auto b = std::make_unique<Blob>();
  b->world = std::make_unique<World>(params);
  World& w = *b->world;
  w.materials.add(siliconeOil(1e-3));
  Material aqueous;
  aqueous.name = "aqueous";
  aqueous.restDensity = 1005;       // [kg/m^3]
  aqueous.dynamicViscosity = 7e-4;  // [Pa s]
  if (viscousMaterials > 1) w.materials.add(aqueous);
  addFluidBlock(w, Vec3::Zero(), Vec3::Constant(10 * d), d, 0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> jitter(-0.1 * d, 0.1 * d);
  for (Index i = 0; i < w.particles.size(); ++i) {
    Vec3& x = w.particles.x[i];
    x += Vec3(jitter(rng), jitter(rng), jitter(rng));
    w.particles.v[i] = velocity(x);
    if (viscousMaterials > 1 && x.y() > 5 * d) {  // upper half aqueous
      w.particles.material[i] = 1;
      w.particles.mass[i] *= aqueous.restDensity / 970.0;
    }
  }
  w.initialize();
  computeDensities(w, w.particles.density);
  b->stage.attach(w);
  return b;
}

constexpr Real kBlobStep = 0.004;  // [s] = 40 x 0.125 d^2/nu

Real sumMassSpeed(const World& w) {  // [kg m/s]
  Real s = 0;
  for (Index i = 0; i < w.particles.size(); ++i) s += w.particles.mass[i] * w.particles.v[i].norm();
  return s;
}

Vec3 angularMomentum(const World& w) {  // [kg m^2/s] about the origin
  Vec3 l = Vec3::Zero();
  for (Index i = 0; i < w.particles.size(); ++i)
    l += w.particles.mass[i] * w.particles.x[i].cross(w.particles.v[i]);
  return l;
}

}  // namespace

// Round-off bound: each pair force is evaluated from both sides with the same bits (symmetric
// coefficient, antisymmetric gradient), so the pair sums cancel up to the rounding of the
// per-particle sums: ~1e-16 relative per term, ~30 terms per particle, 1000 particles, so
// ~1e-14 of sum m|v|. 1e-12 leaves two orders of margin; one non-antisymmetric term (a missing
// m_j, the CG solution used without the momentum-exact update) shows up at 1e-6 or more.
TEST_CASE("implicit viscosity conserves linear momentum to round-off without walls",
          "[unit][viscosity][conservation]") {
  for (int phases : {1, 2}) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> u(-0.05, 0.05);
    auto b = blob([&](const Vec3&) { return Vec3(u(rng), u(rng), u(rng)); }, phases);
    World& w = *b->world;
    const Vec3 p0 = linearMomentum(w);
    const Real scale = sumMassSpeed(w);
    const Real e0 = kineticEnergy(w);
    b->stage.apply(w, StepContext{kBlobStep});
    const Real drift = (linearMomentum(w) - p0).norm() / scale;
    const Real e1 = kineticEnergy(w);
    std::printf(
        "momentum, %d phase(s): drift %.2e of sum m|v|, KE %.3e -> %.3e J, CG %d "
        "iterations, residual %.1e\n",
        phases, drift, e0, e1, b->stage.lastIterations(), b->stage.lastResidual());
    INFO(phases << " phase(s)");
    CHECK(drift < 1e-12);
    // Backward Euler with a symmetric positive semi-definite viscous operator only dissipates.
    // With one phase (dt nu k^2 >> 1 for the particle-scale random field) most energy is gone;
    // with two, the upper half is aqueous, 1400x less viscous, and keeps most of its energy.
    CHECK(e1 < e0);
    if (phases == 1) CHECK(e1 < 0.5 * e0);
    CHECK(b->stage.lastResidual() <= 1e-6);
  }
}

// The operator acts on v_ij . x_ij only, so it vanishes for uniform translation and for rigid
// rotation v = omega x x (then v_ij . x_ij = (omega x x_ij) . x_ij = 0): both fields must come
// out of the solve unchanged, and angular momentum with them. Translation: relative 1e-12
// (round-off). Rotation: the stage forms v_ij . x_ij as v_ij . gradW_ij (gradW is parallel to
// x_ij), and the pair cache holds gradW in single precision (sim/neighbors/pair_precision.h), so
// its direction is x_ij's to 2^-24 = 6e-8 per component: bound 1e-7 (measured 1.2e-8; 1.5e-15
// with a double-precision cache). Angular momentum stays at round-off: the pair terms cancel.
TEST_CASE("implicit viscosity leaves translation and rigid rotation unchanged",
          "[unit][viscosity]") {
  const Vec3 velocity(0.03, -0.02, 0.01), omega(1.0, 2.0, -0.5);  // [m/s], [1/s]
  auto translating = blob([&](const Vec3&) { return velocity; });
  translating->stage.apply(*translating->world, StepContext{kBlobStep});
  Real worst = 0;
  for (const Vec3& v : translating->world->particles.v)
    worst = std::max(worst, (v - velocity).norm() / velocity.norm());
  CHECK(worst < 1e-12);

  auto rotating = blob([&](const Vec3& x) { return Vec3(omega.cross(x)); });
  World& w = *rotating->world;
  const Vec3 l0 = angularMomentum(w);
  rotating->stage.apply(w, StepContext{kBlobStep});
  Real worstRotation = 0;
  for (Index i = 0; i < w.particles.size(); ++i)
    worstRotation =
        std::max(worstRotation,
                 (w.particles.v[i] - omega.cross(w.particles.x[i])).norm() / (omega.norm() * 0.02));
  std::printf(
      "rigid motion: translation changed by %.1e, rotation by %.1e, angular momentum by "
      "%.1e (relative)\n",
      worst, worstRotation, (angularMomentum(w) - l0).norm() / l0.norm());
  CHECK(worstRotation < 1e-7);
  CHECK((angularMomentum(w) - l0).norm() < 1e-12 * l0.norm());
}

// Same inputs and thread count give the same bits (docs/developer-guide.md principle 7), and with
// the fixed-block reductions also across thread counts.
TEST_CASE("implicit viscosity is bit-identical across thread counts", "[unit][viscosity]") {
  std::vector<std::vector<Vec3>> results;
  for (int threads : {1, 2}) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<Real> u(-0.05, 0.05);
    auto b = blob([&](const Vec3&) { return Vec3(u(rng), u(rng), u(rng)); }, 2);
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    b->stage.apply(*b->world, StepContext{kBlobStep});
    b->stage.apply(*b->world, StepContext{kBlobStep});  // second solve uses the warm start
    omp_set_num_threads(before);
    results.push_back(b->world->particles.v);
  }
  bool identical = true;
  for (std::size_t i = 0; i < results[0].size(); ++i)
    identical = identical && results[0][i] == results[1][i];
  CHECK(identical);
}

// ---------------------------------------------------------------------------------------------
// The stage rule (stage_registry.cpp): implicit when 0.125 d^2/nu is below the CFL step.
TEST_CASE("viscosity stage rule: explicit for water, implicit for silicone oil",
          "[unit][viscosity][pipeline]") {
  auto make = [](Real kinematicViscosity, Real d) {
    WorldParameters params;
    params.particleSpacing = d;
    params.domain = Box(Vec3::Constant(-0.1), Vec3::Constant(0.1));
    auto w = std::make_unique<World>(params);
    w->materials.add(siliconeOil(kinematicViscosity));
    addFluidBlock(*w, Vec3::Zero(), Vec3::Constant(5 * d), d, 0);
    w->initialize();
    return w;
  };
  auto reasonOf = [](const Pipeline& p, const std::string& name) {
    for (const auto& d : p.decisions())
      if (d.name == name) return d.reason;
    return std::string();
  };
  SECTION("water-like 1 cSt at d = 2 mm: explicit limit 0.5 s >> CFL step 5 ms") {
    auto w = make(1e-6, 0.002);
    const Pipeline p = assemblePipeline(*w, PipelineOptions{});
    CHECK(p.hasStage("viscosity"));
    CHECK_FALSE(p.hasStage("implicit_viscosity"));
    CHECK_THAT(reasonOf(p, "implicit_viscosity"), Catch::Contains("costs no extra steps"));
  }
  SECTION("1000 cSt at d = 1 mm: explicit limit 0.08 ms << CFL step 0.15 sqrt(d/g) = 1.51 ms") {
    auto w = make(1e-3, 0.001);
    const Pipeline p = assemblePipeline(*w, PipelineOptions{});
    CHECK(p.hasStage("implicit_viscosity"));
    CHECK_FALSE(p.hasStage("viscosity"));
    CHECK_THAT(reasonOf(p, "implicit_viscosity"),
               Catch::Contains("18.9x more steps"));  // 1.51 ms / 0.08 ms
  }
  SECTION("an acoustic solver step below the explicit limit keeps viscosity explicit") {
    auto w = make(1e-3, 0.001);
    PipelineOptions o;
    o.solver = "wcsph";
    o.wcsph.speedOfSound = 10;  // [m/s] dt = 0.4 d / c = 0.04 ms < 0.08 ms
    const Pipeline p = assemblePipeline(*w, o);
    CHECK(p.hasStage("viscosity"));
    CHECK_FALSE(p.hasStage("implicit_viscosity"));
  }
  SECTION("forcing one viscosity stage on switches the other's automatic choice off") {
    auto w = make(1e-3, 0.001);
    PipelineOptions o;
    o.forced["viscosity"] = StageOverride::kOn;
    const Pipeline p = assemblePipeline(*w, o);
    CHECK(p.hasStage("viscosity"));
    CHECK_FALSE(p.hasStage("implicit_viscosity"));
    CHECK_THAT(reasonOf(p, "implicit_viscosity"), Catch::Contains("forced on instead"));
  }
  SECTION("an inviscid fluid gets neither") {
    auto w = make(0, 0.001);
    const Pipeline p = assemblePipeline(*w, PipelineOptions{});
    CHECK_FALSE(p.hasStage("viscosity"));
    CHECK_FALSE(p.hasStage("implicit_viscosity"));
  }
}

// Two layers: the lower half 10x more viscous than the upper (10000 cSt under 1000 cSt, same
// density). In steady state the shear stress tau is the same in both layers, so the profile is
// piecewise linear and the interface (at H/2) moves at
//   u_I = U (H1/mu1) / (H1/mu1 + H2/mu2) = U (1/10) / (1/10 + 1) = U/11 = 0.0909 U.
// The interface pairs use the harmonic mean of mu (header of viscosity_weiler2018.h). Bound 5 % of
// U as for the one-layer profile. Measured: 2.3 % with the harmonic mean, 3.3 % with the
// arithmetic mean (a scratch build), so at a ratio of 10 this bound does not separate the two;
// the choice rests on stress continuity, and the ratio oil/aqueous is ~1000.
TEST_CASE("implicit viscosity: two-layer Couette flow matches the piecewise-linear profile",
          "[validation][viscosity]") {
  const Real ratio = 10;
  auto s = couetteScene(2e-3, ratio * kCouetteViscosity);
  World& w = *s.world;
  PipelineOptions options;
  options.solver = "dfsph";
  options.forced["velocity_smoothing"] = StageOverride::kOff;
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  REQUIRE(pipeline.hasStage("implicit_viscosity"));
  // Slowest mode: the lower layer diffuses 10x faster, so the upper layer's mode decays last; its
  // rate lies between 4 pi^2 nu/H^2 (interface velocity held) and pi^2 nu/H^2 (interface free of
  // stress, a quarter wave): at t = 0.8 H^2/nu it is at most exp(-7.9) = 4e-4 of U.
  const Real H = s.height;
  while (w.time < 0.8 * H * H / kCouetteViscosity - 1e-9) pipeline.step(w);
  const Real uInterface = kPlateSpeed / (1 + ratio);  // [m/s]
  const std::vector<LayerMean> layers = couetteLayers(w);
  Real worst = 0;
  for (std::size_t k = 0; k < layers.size(); ++k) {
    const Real y = layers[k].y, u = layers[k].u;
    const Real expected = y < 0.5 * H
                              ? uInterface * y / (0.5 * H)
                              : uInterface + (kPlateSpeed - uInterface) * (y - 0.5 * H) / (0.5 * H);
    worst = std::max(worst, std::abs(u - expected) / kPlateSpeed);
    std::printf("  two layers t=%.3f s layer %2zu y/H %.3f: u/U %.4f, closed form %.4f\n", w.time,
                k, y / H, u / kPlateSpeed, expected / kPlateSpeed);
  }
  std::printf(
      "two-layer Couette (10000 cSt under 1000 cSt): %ld steps, max layer error %.2f %% of U\n",
      w.stepCount, 100 * worst);
  CHECK(worst < 0.05);
}

// The splitting with the pressure solve (viscosity_weiler2018.cpp, apply): the viscous solve starts
// from the step-start velocity, so it acts on motion only. A fluid at rest between two no-slip
// plates, with gravity's increment g dt already integrated into v* (as the pipeline does before
// the implicit effects), keeps v = g dt on every particle: the pressure solve, not wall friction,
// is what must take that increment back. Solving from v* instead slowed the particles next to the
// plates (the wall term acts on v_i - v_b = g dt) and let the walls carry weight: on an eye at
// INDSPH's 1.9 ms step that was visible as velocity noise and aqueous creeping up the wall.
// Exact: the solve from v^n = 0 has the solution 0 and zero forces, so round-off only.
TEST_CASE("implicit viscosity does not act on the step's own body-force increment",
          "[unit][viscosity]") {
  CouetteScene s = couetteScene(1e-3);
  World& w = *s.world;
  for (auto& v : w.walls.fields.get<Vec3>(kWallVelocityField)) v.setZero();  // plates at rest
  computeDensities(w, w.particles.density);
  ViscosityWeiler2018 stage;
  stage.attach(w);
  const Real dt = 2e-3;           // [s] 16 x the explicit viscous limit 0.125 d^2 / nu
  const Vec3 g(0.0, -9.81, 0.0);  // [m/s^2]
  for (Index i = 0; i < w.particles.size(); ++i) {
    w.particles.a[i] = g;
    w.particles.v[i] = dt * g;  // v* = v^n + dt a with v^n = 0
  }
  stage.apply(w, StepContext{dt});
  Real worst = 0;  // [1] largest |v - g dt| / |g dt|
  for (Index i = 0; i < w.particles.size(); ++i)
    worst = std::max(worst, (w.particles.v[i] - dt * g).norm() / (dt * g).norm());
  INFO("largest relative change of g dt: " << worst);
  CHECK(worst < 1e-12);
  // A real motion next to the plates is still slowed: the same fluid sliding at 1 cm/s along x.
  for (Index i = 0; i < w.particles.size(); ++i) {
    w.particles.a[i].setZero();
    w.particles.v[i] = Vec3(0.01, 0.0, 0.0);
  }
  stage.apply(w, StepContext{dt});
  Real slowest = 1;
  for (Index i = 0; i < w.particles.size(); ++i)
    slowest = std::min(slowest, w.particles.v[i].x() / 0.01);
  CHECK(slowest <
        0.9);  // the first layer loses > 10 % of its speed to the no-slip plates in one step
}
