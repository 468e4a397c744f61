// Multiphase pressure solvers: the number-density discretisation of Wang et al. 2023,
// INDSPH stability over density ratios, buoyancy direction, and the interface-gap diagnostic.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "scene_fixtures.h"
#include "sim/fluid/density.h"
#include "sim/fluid/indsph_wang2023.h"
#include "sim/measure/interface_gap.h"

using namespace sim;

namespace {

Material fluid(const char* name, Real rho) {
  Material m;
  m.name = name;
  m.restDensity = rho;        // [kg/m^3]
  m.dynamicViscosity = 1e-3;  // [Pa s]
  return m;
}

struct TwoPhaseTank {
  TankSpec spec;
  std::unique_ptr<World> world;
};

// A tank of inner size `inner` with material 0 (heavy) and 1 (light) added by `fill`.
// closed: with a lid, so that a light phase displaced by the heavy one stays in the box (the eye
// is closed too); "inside the tank" then means no particle went through a wall.
template <class Fill>
TwoPhaseTank makeTank(const Vec3& inner, Real d, Real heavy, Real light, Fill fill,
                      bool closed = false) {
  TwoPhaseTank t;
  t.spec.innerMin = Vec3::Zero();
  t.spec.innerMax = inner;
  t.spec.closedTop = closed;
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = tankDomain(t.spec, d);
  t.world = std::make_unique<World>(params);
  t.world->materials.add(fluid("heavy", heavy));
  t.world->materials.add(fluid("light", light));
  addTankWalls(*t.world, t.spec, d);
  fill(*t.world);
  t.world->initialize();
  return t;
}

bool insideTank(const World& w, const TankSpec& spec) {
  for (const Vec3& x : w.particles.x)
    if ((x.array() < spec.innerMin.array()).any() || (x.array() > spec.innerMax.array()).any())
      return false;
  return true;
}

Real meanHeight(const World& w, int material) {
  Real sum = 0;
  int count = 0;
  for (Index i = 0; i < w.particles.size(); ++i)
    if (w.particles.material[i] == material) {
      sum += w.particles.x[i].y();
      ++count;
    }
  return sum / count;
}

constexpr Real kBlobSpacing = 0.005;  // [m]

// A 2 cm cube of material 1 (density blobDensity) in the middle of a 4 x 6 x 4 cm column of
// water (material 0), on a lattice of spacing kBlobSpacing.
TwoPhaseTank blobInWater(Real blobDensity) {
  const Real d = kBlobSpacing, gap = (testing::kWallGap - 0.5) * d;
  const Vec3 inner(0.04 + 2 * gap, 0.07, 0.04 + 2 * gap);
  const Vec3 blobMin(gap + 0.01, gap + 0.02, gap + 0.01), blobMax = blobMin + Vec3::Constant(0.02);
  return makeTank(inner, d, 1000.0, blobDensity, [&](World& w) {
    addFluidBlock(w, Vec3::Constant(gap), Vec3(gap + 0.04, gap + 0.02, gap + 0.04), d, 0);
    addFluidBlock(w, Vec3(gap, gap + 0.04, gap), Vec3(gap + 0.04, gap + 0.06, gap + 0.04), d, 0);
    addFluidBlock(w, Vec3(gap, gap + 0.02, gap), Vec3(blobMin.x(), gap + 0.04, gap + 0.04), d, 0);
    addFluidBlock(w, Vec3(blobMax.x(), gap + 0.02, gap), Vec3(gap + 0.04, gap + 0.04, gap + 0.04),
                  d, 0);
    addFluidBlock(w, Vec3(blobMin.x(), gap + 0.02, gap), Vec3(blobMax.x(), gap + 0.04, blobMin.z()),
                  d, 0);
    addFluidBlock(w, Vec3(blobMin.x(), gap + 0.02, blobMax.z()),
                  Vec3(blobMax.x(), gap + 0.04, gap + 0.04), d, 0);
    addFluidBlock(w, blobMin, blobMax, d, 1);
  });
}

}  // namespace

TEST_CASE("Number density is blind to a 1:10 mass jump that mass-weighted density sees",
          "[unit][solvers][indsph]") {
  // Wang et al. 2023, section 3.3 / Fig. 1: an undisturbed lattice, heavy below and light above.
  // Number density (eq. 6) depends only on positions, so every interior particle of the lattice
  // has the same value whatever the phases; the mass-weighted density (eq. 4) of a light particle
  // next to the interface counts its heavy neighbours ten times over.
  const Real d = 0.01;
  const Real gap = (testing::kWallGap - 0.5) * d;
  const Real side = 12 * d;
  auto t = makeTank(Vec3::Constant(side + 2 * gap), d, 1000.0, 100.0, [&](World& w) {
    addFluidBlock(w, Vec3::Constant(gap), Vec3(gap + side, gap + side / 2, gap + side), d, 0);
    addFluidBlock(w, Vec3(gap, gap + side / 2, gap), Vec3::Constant(gap + side), d, 1);
  });
  World& w = *t.world;
  std::vector<Real> delta, rho;
  computeNumberDensities(w, delta);
  computeDensities(w, rho);
  const Real h = w.supportRadius();
  const Real interfaceY = gap + side / 2;
  Real deltaBulk = -1, worstNumberJump = 0, worstLightDensity = 0;
  for (Index i = 0; i < w.particles.size(); ++i) {
    const Vec3& x = w.particles.x[i];
    // Interior: more than h from every wall, so only the phases differ between particles.
    if ((x.array() - gap < h).any() || (gap + side - x.array() < h).any()) continue;
    if (deltaBulk < 0) deltaBulk = delta[i];
    worstNumberJump = std::max(worstNumberJump, std::abs(delta[i] / deltaBulk - 1));
    if (w.particles.material[i] == 1 && x.y() - interfaceY < d)
      worstLightDensity = std::max(worstLightDensity, rho[i] / w.restDensityOf(i) - 1);
  }
  // Same geometry, same sum: equal to rounding (1e-12 is ~1e4 ulps of a ~40-term sum).
  CHECK(worstNumberJump < 1e-12);
  // The light layer touching the interface gets a large part of its kernel sum from heavy
  // particles (about a third for the cubic spline at h = 2d), times 10: far above 50 %.
  CHECK(worstLightDensity > 0.5);
}

TEST_CASE("INDSPH two-phase dam break stays bounded at density ratios 1:2, 1:10, 1:75",
          "[stability][solvers][indsph]") {
  const Real ratio = GENERATE(2.0, 10.0, 75.0);
  const Real d = 0.005, gap = (testing::kWallGap - 0.5) * d;
  const Vec3 inner(0.06 + 2 * gap, 0.06, 0.02 + 2 * gap);
  // Heavy column on the left, light column of the same height on the right, released at once.
  auto t = makeTank(
      inner, d, 1000.0, 1000.0 / ratio,
      [&](World& w) {
        addFluidBlock(w, Vec3::Constant(gap), Vec3(gap + 0.03, gap + 0.03, gap + 0.02), d, 0);
        addFluidBlock(w, Vec3(gap + 0.03, gap, gap), Vec3(gap + 0.06, gap + 0.03, gap + 0.02), d,
                      1);
      },
      /*closed=*/true);
  World& w = *t.world;
  PipelineOptions options;
  options.solver = "indsph";
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  // Energy bound: the kinetic energy can never exceed the potential energy the heavy phase can
  // release by falling the full column height (a conservation-law bound, loose on purpose).
  Real heavyMass = 0;
  for (Index i = 0; i < w.particles.size(); ++i)
    if (w.particles.material[i] == 0) heavyMass += w.particles.mass[i];
  const Real energyBound = heavyMass * 9.81 * 0.03;
  Real worstMaxCompression = 0, maxKinetic = 0;
  bool finite = true, inside = true;
  // One simulated second: the heavy column collapses, runs under the light one, hits the far wall
  // and sloshes back (with omega = 1 the 1:75 case threw a particle through the floor at 0.31 s).
  while (w.time < 1.0 && finite && inside) {
    pipeline.step(w);
    finite = allFinite(w);
    inside = insideTank(w, t.spec);
    maxKinetic = std::max(maxKinetic, kineticEnergy(w));
    worstMaxCompression = std::max(worstMaxCompression, pipeline.solver().stats().maxCompression);
  }
  const auto gapInfo = interfaceGap(w, 1, 0);
  std::printf(
      "INDSPH 1:%g dam break: t %.3f s, KE max %.3g J (bound %.3g), max compression %.2e, "
      "mean compression %.2e, interface gap %.2f d\n",
      ratio, w.time, maxKinetic, energyBound, worstMaxCompression,
      pipeline.solver().stats().averageCompression, gapInfo.meanNearestDistance);
  CHECK(finite);
  CHECK(inside);
  CHECK(maxKinetic < energyBound);
  // eta = 1e-4 bounds the MEAN compression; single particles at an impact may exceed it. 5 % is
  // the level at which a particle pair overlaps by about 1.6 % of d and the linearised
  // prediction stops being valid; a blow-up shows as compression far beyond it.
  CHECK(worstMaxCompression < 0.05);
  CHECK(pipeline.solver().stats().averageCompression <= options.indsph.tolerance);
}

// VSLSPH (explicit, per-particle smoothing length) on the same two-phase dam break, at the ratios
// where `tamponade bench solvers --quick` finds it stable (1:2 ... 1:10; at 1:30 and 1:75 a light
// particle leaves the tank after about 0.22 s: docs/methods/solvers.md). Bounds: the same energy
// bound; the mean compression of an explicit solver at c = 10 v_max stays near 1 % (Becker &
// Teschner 2007), so 1 % (measured over 1 s: worst step 0.85 % at 1:2 and 0.84 % at 1:10, both at
// the column's impact on the far wall); no particle through a wall. Peak KE 5 % and 16 % of the
// bound.
TEST_CASE("VSLSPH two-phase dam break stays bounded at density ratios 1:2 and 1:10",
          "[stability][solvers][vslsph]") {
  const Real ratio = GENERATE(2.0, 10.0);
  const Real d = 0.005, gap = (testing::kWallGap - 0.5) * d;
  const Vec3 inner(0.06 + 2 * gap, 0.06, 0.02 + 2 * gap);
  auto t = makeTank(
      inner, d, 1000.0, 1000.0 / ratio,
      [&](World& w) {
        addFluidBlock(w, Vec3::Constant(gap), Vec3(gap + 0.03, gap + 0.03, gap + 0.02), d, 0);
        addFluidBlock(w, Vec3(gap + 0.03, gap, gap), Vec3(gap + 0.06, gap + 0.03, gap + 0.02), d,
                      1);
      },
      /*closed=*/true);
  World& w = *t.world;
  PipelineOptions options;
  options.solver = "vslsph";
  options.wcsph.speedOfSound = 10 * std::sqrt(2 * 9.81 * 0.03);  // [m/s] 10x the free-fall speed
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  Real heavyMass = 0;
  for (Index i = 0; i < w.particles.size(); ++i)
    if (w.particles.material[i] == 0) heavyMass += w.particles.mass[i];
  const Real energyBound = heavyMass * 9.81 * 0.03;
  Real maxKinetic = 0, worstMeanCompression = 0;
  bool finite = true, inside = true;
  while (w.time < 1.0 && finite && inside) {
    pipeline.step(w);
    finite = allFinite(w);
    inside = insideTank(w, t.spec);
    maxKinetic = std::max(maxKinetic, kineticEnergy(w));
    worstMeanCompression =
        std::max(worstMeanCompression, pipeline.solver().stats().averageCompression);
  }
  std::printf(
      "VSLSPH 1:%g dam break: t %.3f s, KE max %.3g J (bound %.3g), worst mean "
      "compression %.2e\n",
      ratio, w.time, maxKinetic, energyBound, worstMeanCompression);
  CHECK(finite);
  CHECK(inside);
  CHECK(maxKinetic < energyBound);
  CHECK(worstMeanCompression < 0.01);
}

TEST_CASE("INDSPH buoyancy: a light blob rises and a heavy blob sinks",
          "[validation][solvers][indsph]") {
  const Real blobDensity = GENERATE(500.0, 2000.0);
  const Real d = kBlobSpacing;
  auto t = blobInWater(blobDensity);
  World& w = *t.world;
  PipelineOptions options;
  options.solver = "indsph";
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  const Real start = meanHeight(w, 1);
  while (w.time < 0.15) pipeline.step(w);
  const Real shift = meanHeight(w, 1) - start;
  std::printf("INDSPH blob %g in 1000: mean height change %.4f m after %.3f s\n", blobDensity,
              shift, w.time);
  REQUIRE(allFinite(w));
  // Buoyant acceleration |1 - 1000/rho| g (Archimedes) moves the blob by ~0.5 a t^2 = 5-11 cm
  // without drag; drag and the surrounding flow reduce that, but the sign must be right and the
  // blob must move by more than half a particle spacing (lattice noise is well below d/2).
  if (blobDensity < 1000)
    CHECK(shift > 0.5 * d);
  else
    CHECK(shift < -0.5 * d);
}

// docs/methods/interface.md validation 6: near-neutral buoyancy, the regime of silicone oil in
// aqueous (3 % density difference). Both phases are water-like in viscosity here, to isolate
// buoyancy from viscous drag.
//
// The reference matters. The column starts 1.2 d above the floor and settles in its first 0.1 s;
// with the walls holding the fluid beside them, the settling is a circulation: the middle of the
// tank sinks 0.6-0.8 d while the water near the side walls rises back. Against the mean height of
// all the water (the first version of this test), a neutral blob in the middle therefore
// "drifted" -0.21 d in 0.3 s. Measured (d = 5 mm, 0.3 s): displacements of the blob
// and of the water that started directly above and below it (its column):
//   blob 1000: -0.67 d, its column -0.60 d: blob - column within 0.13 d over the whole run;
//   blob 970: -0.60 d; blob 1060: -1.00 d; against the neutral blob +0.07 d and -0.33 d.
namespace {

struct BlobRun {
  Real blob = 0;         // [m] mean height change of the blob's particles
  Real column = 0;       // [m] mean height change of the water that started above/below it
  Real maxRelative = 0;  // [m] max |blob - column| over the run (sampled every 10 steps)
};

BlobRun runBlob(Real blobDensity, Real duration) {
  auto t = blobInWater(blobDensity);
  World& w = *t.world;
  PipelineOptions options;
  options.solver = "indsph";
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  // Start heights by particle id (ids survive the Z-order re-sorting); the column is the water
  // whose start x and z lie within the blob's 2 cm footprint.
  const Real centre = 0.5 * t.spec.innerMax.x();
  std::vector<Real> y0(w.particles.size());
  std::vector<char> column(w.particles.size(), 0);
  for (Index i = 0; i < w.particles.size(); ++i) {
    const Vec3& x = w.particles.x[i];
    y0[w.particles.id[i]] = x.y();
    column[w.particles.id[i]] = std::abs(x.x() - centre) < 0.01 && std::abs(x.z() - centre) < 0.01;
  }
  BlobRun out;
  auto measure = [&]() {
    Real blob = 0, col = 0;
    int nb = 0, nc = 0;
    for (Index i = 0; i < w.particles.size(); ++i) {
      const auto id = w.particles.id[i];
      const Real dy = w.particles.x[i].y() - y0[id];
      if (w.particles.material[i] == 1) {
        blob += dy;
        ++nb;
      } else if (column[id]) {
        col += dy;
        ++nc;
      }
    }
    out.blob = blob / nb;
    out.column = col / nc;
    out.maxRelative = std::max(out.maxRelative, std::abs(out.blob - out.column));
  };
  while (w.time < duration) {
    pipeline.step(w);
    if (w.stepCount % 10 == 0) measure();
  }
  measure();
  REQUIRE(allFinite(w));
  return out;
}

}  // namespace

TEST_CASE("INDSPH neutral buoyancy: a blob of the water's density moves with its water column",
          "[validation][solvers][indsph][buoyancy]") {
  const Real d = kBlobSpacing;
  const BlobRun r = runBlob(1000.0, 0.3);
  std::printf(
      "INDSPH neutral blob: %.3f d, its column %.3f d, max |blob - column| %.3f d in 0.3 s\n",
      r.blob / d, r.column / d, r.maxRelative / d);
  // A blob with the water's properties is water: nothing but the flow around it moves it, so it
  // must follow the water above and below it (the settling circulation moves both alike). Bound
  // 0.3 d over 0.3 s: a sixth of the 1.8 d that a 3 % density difference moves it without drag
  // (0.5 a t^2, a = 0.03 g / 1.5 with the added mass of a sphere), so that a buoyancy signal
  // would stand clear of it; measured 0.13 d. The bound holds for the whole run, not only at its
  // end.
  CHECK(r.maxRelative < 0.3 * d);
}

// [!mayfail], a known open defect: against the neutral blob (the control, same settling flow) the
// 970 blob rises only +0.28 d and the 1060 blob sinks -0.20 d in 0.3 s, against 1.8 d / 3.4 d
// without drag. Cause measured (docs/methods/interface.md, validation 6): XSPH smoothing across
// phases damped it (+0.07 d / -0.33 d before XSPH was restricted to one material); what is left is
// resolution: with XSPH off the signal grows to +0.86 d / -1.74 d at d = 2.5 mm (8x the particles,
// too slow for CI). Measured: the blob stalls, and the stall grows with depth (8 cm deep neither
// blob moves): the particle arrangement under hydrostatic pressure has a shear yield, because the
// symmetric pressure force is not zero for a uniform pressure on an imperfect arrangement. A
// solver defect, analysed in docs/methods/interface.md (validation 6); this test is its acceptance
// test. In a closed, filled domain the background can be removed exactly
// (World::gravityReferenceDensity): the closed-box test below passes that way; with a free surface,
// as here, it cannot.
TEST_CASE("INDSPH near-neutral buoyancy: 970 rises and 1060 sinks against the neutral blob",
          "[validation][solvers][indsph][buoyancy][!mayfail]") {
  const Real d = kBlobSpacing;
  const Real neutral = runBlob(1000.0, 0.3).blob;
  const Real light = runBlob(970.0, 0.3).blob - neutral,
             heavy = runBlob(1060.0, 0.3).blob - neutral;
  std::printf("INDSPH 3 %% buoyancy against the neutral blob: 970 %+.3f d, 1060 %+.3f d in 0.3 s\n",
              light / d, heavy / d);
  // The signal must stand clear of the neutral bound above (0.3 d).
  CHECK(light > 0.3 * d);
  CHECK(heavy < -0.3 * d);
}

// Validation 6 the way the eye needs it: a closed box filled to the lid (no free surface, like the
// eye), the hydrostatic background taken out of the pressure (World::gravityReferenceDensity =
// the water's density: each particle feels g (1 - 1000 / rho), exact in a closed filled domain),
// and a relaxed, disordered start (the lattice jittered by up to 0.2 d per axis, fixed seed, then
// 20 steps with the velocities reset after each: a fluid at rest is not a lattice, and the exact
// lattice locks). Without the first, the [!mayfail] test above shows the blob pinned; without
// the relaxation the answer depended on the jitter's realization (docs/methods/interface.md).
namespace {

// An 8 x 6 x 8 cm closed box of water with a 2 cm cube of blobDensity (material 1), d = 5 mm,
// layered walls, the lattice jittered by up to 0.2 d per axis (`seed`), gravity relative to the
// water; maxDisplacement: WorldParameters::maxDisplacement [d].
std::unique_ptr<World> closedBox(Real blobDensity, unsigned seed, Real maxDisplacement = 0.3) {
  const Real d = kBlobSpacing, width = 0.08, height = 0.06, blob = 0.02;  // [m]
  TankSpec spec;
  spec.innerMax = Vec3(width, height, width);
  spec.closedTop = true;
  WorldParameters params;
  params.particleSpacing = d;
  params.maxDisplacement = maxDisplacement;
  params.domain = tankDomain(spec, d);
  params.domain.extend(spec.innerMin - Vec3::Constant(4 * d));
  params.domain.extend(spec.innerMax + Vec3::Constant(4 * d));
  auto world = std::make_unique<World>(params);
  World& w = *world;
  w.materials.add(fluid("water", 1000.0));
  w.materials.add(fluid("blob", blobDensity));
  addTankWalls(w, spec, d, 0, WallLayers{});
  const Vec3 blobMin(0.5 * (width - blob), 0.02, 0.5 * (width - blob)),
      blobMax = blobMin + Vec3::Constant(blob);
  // std::mt19937's sequence is fixed by the standard (unlike the distributions'): the same
  // jitter on every platform.
  std::mt19937 random(seed);
  const auto jitter = [&] {
    return 0.2 * d * (2.0 * static_cast<Real>(random()) / 4294967295.0 - 1.0);
  };
  const int n = static_cast<int>(std::lround(width / d)),
            ny = static_cast<int>(std::lround(height / d));
  for (int j = 0; j < ny; ++j)
    for (int k = 0; k < n; ++k)
      for (int i = 0; i < n; ++i) {
        const Vec3 site = Vec3(i + 0.5, j + 0.5, k + 0.5) * d;
        const int material =
            (site.array() > blobMin.array()).all() && (site.array() < blobMax.array()).all();
        const Vec3 x = site + Vec3(jitter(), jitter(), jitter());
        w.particles.add(x, Vec3::Zero(), w.materials[material].restDensity * d * d * d, material);
      }
  w.gravityReferenceDensity = 1000.0;
  w.initialize();
  return world;
}

Pipeline indsphPipeline(World& w) {
  PipelineOptions options;
  options.solver = "indsph";
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  return pipeline;
}

// Mean height change [m] of the blob of closedBox(blobDensity, seed) after `duration`, INDSPH,
// from a start relaxed by 20 steps whose velocities are reset.
Real closedBoxBlobShift(Real blobDensity, Real duration, unsigned seed) {
  const std::unique_ptr<World> world = closedBox(blobDensity, seed);
  World& w = *world;
  Pipeline pipeline = indsphPipeline(w);
  for (int k = 0; k < 20; ++k) {  // relax the jittered start to rest
    pipeline.step(w);
    for (Vec3& v : w.particles.v) v.setZero();
  }
  const Real start = meanHeight(w, 1), t0 = w.time;
  while (w.time - t0 < duration) pipeline.step(w);
  REQUIRE(allFinite(w));
  return meanHeight(w, 1) - start;
}

// Added-mass coefficient C_m that a uniformly accelerated blob's shift s after t implies:
// s = a t^2 / 2 with a = |1000 - rho| g / (rho + C_m 1000).
Real impliedAddedMass(Real rho, Real shift, Real t) {
  const Real a = 2 * std::abs(shift) / (t * t);  // [m/s^2]
  return (std::abs(1000.0 - rho) * 9.81 / a - rho) / 1000.0;
}

}  // namespace

TEST_CASE("INDSPH near-neutral buoyancy in a closed filled box without the hydrostatic background",
          "[validation][solvers][indsph][buoyancy]") {
  const Real d = kBlobSpacing, t = 0.3;
  // Three jittered starts, each checked. Seeds 7 and 11 are the starts whose relaxation once ran
  // away: a pressure-solve correction of 0.31 d in the first step tripped the displacement guard,
  // whose shorter retries could not shrink it (a correction moves a particle the same distance
  // at any dt) and only raised the velocities, to 200 m/s at the minimum step; the box then
  // stirred for 0.1 s and carried the blobs (neutral +0.40 and +0.47 d). Since the guard keeps the
  // longer step when a retry does not help (Pipeline::step), every start of seeds 7-11 agrees:
  // neutral -0.004 to +0.006 d, 970 +1.22 to +1.25 d, 1060 -1.94 to -2.00 d.
  for (const unsigned seed : {7u, 11u, 9u}) {
    const Real neutral = closedBoxBlobShift(1000.0, t, seed),
               light = closedBoxBlobShift(970.0, t, seed),
               heavy = closedBoxBlobShift(1060.0, t, seed);
    const Real cLight = impliedAddedMass(970.0, light, t),
               cHeavy = impliedAddedMass(1060.0, heavy, t);
    std::printf(
        "closed box, background removed, relaxed start (seed %u), 0.3 s: neutral %+.3f d, 970 "
        "%+.3f d (C_m %.2f), 1060 %+.3f d (C_m %.2f)\n",
        seed, neutral / d, light / d, cLight, heavy / d, cHeavy);
    INFO("seed " << seed);
    // A blob of the water's density feels no net force (g (1 - 1000/1000) = 0): it stays put.
    // Bound 0.1 d over 0.3 s, a tenth of the 970 blob's expected shift (measured -0.004 to
    // +0.006 d).
    CHECK(std::abs(neutral) < 0.1 * d);
    // Direction: Archimedes, up for the lighter, down for the heavier blob.
    CHECK(light > 0);
    CHECK(heavy < 0);
    // Magnitude, as the added-mass coefficient each blob's uniform acceleration implies (drag is
    // small: v < 7 cm/s, Re < 1400, 0.5 rho v^2 C_d A below ~18 % of the buoyant force at the end,
    // less on average). Lower bound 0.5, a sphere's in unbounded fluid (a cube's is ~0.7; walls
    // only add): below it the blob would move faster than inertia allows. Upper bound 3: the
    // "piston" estimate H / h - 1 = 2 (the water in the blob's own footprint column, 6 cm tall,
    // moving with the 2 cm blob) plus half again for the flow turning at the lid and floor and for
    // drag; an SPH yield pins the blob far above it (full hydrostatic background: implied C_m ~
    // 17). Measured (seeds 7-11): 1.2 (970) and 1.6-1.7 (1060; more drag, it is faster).
    CHECK(cLight > 0.5);
    CHECK(cLight < 3.0);
    CHECK(cHeavy > 0.5);
    CHECK(cHeavy < 3.0);
  }
}

// The displacement guard (Pipeline::step) redoes a step whose velocities would move a particle
// further than maxDisplacement with a shorter one. A pressure solve's density correction moves a
// particle the same distance at any dt (at distance / dt), so shortening it cannot help: retries
// of it used to drive the step to the minimum and the speed to hundreds of m/s (the closed box's
// seed 7 reached 200 m/s and 80 J in four steps). A jittered start with the guard at 0.1 d, which
// its first corrections (up to about 0.3 d) exceed whatever the start, must keep its steps and
// stay slow.
TEST_CASE("the displacement guard keeps a step that a shorter one cannot help",
          "[stability][pipeline]") {
  const std::unique_ptr<World> world = closedBox(1000.0, 7, 0.1);
  World& w = *world;
  Pipeline pipeline = indsphPipeline(w);
  Real slowest = 1.0, fastest = 0.0;  // [s] and [m/s] over the steps
  for (int k = 0; k < 10; ++k) {
    pipeline.step(w);
    slowest = std::min(slowest, pipeline.lastTimeStep().dt);
    fastest = std::max(fastest, maxSpeed(w));
    for (Vec3& v : w.particles.v) v.setZero();
  }
  std::printf("guard at 0.1 d: %ld retries, shortest step %.2e s, fastest particle %.3f m/s\n",
              pipeline.rejectedSteps(), slowest, fastest);
  REQUIRE(pipeline.rejectedSteps() > 0);  // the guard did act
  // The steps stay CFL-sized: the first is 3.4 ms (the box at rest); a runaway halves it down to
  // the 1 us minimum. Bound 1e-4 s, 30 times below the first.
  CHECK(slowest > 1e-4);
  // A correction of at most 0.3 d = 1.5 mm in a 3.4 ms step is about 0.45 m/s (measured 0.46 at
  // the guard's default); bound 1 m/s. The runaway reached 200 m/s.
  CHECK(fastest < 1.0);
  CHECK(allFinite(w));
}

// The interface-gap diagnostic on constructed states with a known answer: two lattice blocks of
// different phases touching (no gap), and the same blocks 0.5 d apart (a gap of half a spacing).
TEST_CASE("interface gap diagnostic: 1 without a gap, clearly below 1 with a 0.5 d gap",
          "[unit][solvers][gap]") {
  const Real d = 0.005;
  const Real separation = GENERATE(0.0, 0.5);  // [d]
  WorldParameters params;
  params.particleSpacing = d;
  params.gravity = Vec3::Zero();
  params.domain = Box(Vec3::Constant(-0.02), Vec3::Constant(0.1));
  World w(params);
  w.materials.add(fluid("heavy", 1000.0));
  w.materials.add(fluid("light", 500.0));
  const Real side = 10 * d;
  addFluidBlock(w, Vec3::Zero(), Vec3(side, 5 * d, side), d, 0);
  addFluidBlock(w, Vec3(0, (5 + separation) * d, 0), Vec3(side, (10 + separation) * d, side), d, 1);
  w.initialize();
  const InterfaceGap gap = interfaceGap(w, 1, 0);
  std::printf("separation %.1f d: nearest %.3f d, number density ratio %.4f\n", separation,
              gap.meanNearestDistance, gap.numberDensityRatio);
  if (separation == 0.0) {
    // Every counted particle has the same full lattice neighbourhood: exactly 1 (round-off).
    CHECK(gap.numberDensityRatio == Approx(1.0).epsilon(1e-9));
  } else {
    // Moving the interface neighbours 0.5 d away removes kernel weight: the layer at d from the
    // interface loses its W(d) neighbour pair contributions (~8 % of the lattice sum for the cubic
    // spline at h = 2d) to W(1.5 d) ones; the second layer little. Averaged over the interface
    // particles (two layers per side), the ratio drops by several per cent; 0.98 is far above it.
    CHECK(gap.numberDensityRatio < 0.98);
    CHECK(gap.numberDensityRatio > 0.5);
  }
}
