// The static equilibrium solver (sim/equilibrium/) in a sphere of R = 12 mm, against references
// that share no code with it: the closed form of a flat fill plane, the axisymmetric Young-Laplace
// meniscus and the zero-gravity spherical cap (young_laplace_sphere.h), and symmetries of the
// energy. Clinical parameters: silicone oil 970 in aqueous 1004 kg/m^3, sigma = 40 mN/m, 1 g
// (Bond number R^2 delta rho g / sigma = 1.2), at the draft preset's 0.5 mm voxel.
//
// Where the tolerance is a measured error and not a derived bound, the test says so: the method's
// error at small contact angles (docs/methods/equilibrium.md "Accuracy") is larger than the
// 1 point the toolkit aims for, and these tests hold it at what it is so that it cannot grow.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "sim/core/error.h"
#include "sim/equilibrium/interface_surface.h"
#include "sim/equilibrium/threshold_dynamics_xu2017.h"
#include "sim/equilibrium/wall_oil.h"
#include "sphere_points.h"
#include "young_laplace_sphere.h"

using namespace sim;
using namespace sim::equilibrium;

namespace {

constexpr double kR = 12e-3, kSigma = 0.04, kOil = 970.0, kAqueous = 1004.0, kG = 9.81;
constexpr double kVoxel = 0.5e-3;
constexpr double kDeg = std::numbers::pi / 180.0;

EquilibriumProblem sphereProblem(double thetaDeg, double fill, const Vec3& gravity,
                                 double oilDensity = kOil, double tension = kSigma,
                                 double voxel = kVoxel) {
  EquilibriumProblem p;
  p.grid = gridAround(Vec3::Constant(-kR), Vec3::Constant(kR), voxel, 2);
  p.fluidFraction = fluidFractionsFromDistance(p.grid, [](const Vec3& x) { return x.norm() - kR; });
  p.oilDensity = oilDensity;
  p.aqueousDensity = kAqueous;
  p.tension = tension;
  p.contactAngle = thetaDeg * kDeg;
  p.gravity = gravity;
  p.oilFraction = fill;
  p.wallArea = 4 * std::numbers::pi * kR * kR;
  return p;
}

using testref::sphereNormals;

struct Coverage {
  double fraction = 0.0;         // [1] of the wall, oil-covered
  Vec3 centroid = Vec3::Zero();  // [1] mean normal of the covered wall
};

Coverage coverageOf(const EquilibriumSolution& s, double thetaDeg) {
  const WallOilReader reader(s, thetaDeg * kDeg);
  Coverage c;
  const std::vector<Vec3> normals = sphereNormals(20000);
  for (const Vec3& n : normals)
    if (reader.oilCovered(kR * n, n)) {
      c.fraction += 1.0;
      c.centroid += n;
    }
  if (c.fraction > 0) c.centroid /= c.fraction;
  c.fraction /= static_cast<double>(normals.size());
  return c;
}

// The wall fraction above a flat plane that holds `fill` of the sphere: f = 3x^2 - 2x^3.
double flatCoverage(double fill) {
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 100; ++it) {
    const double x = 0.5 * (lo + hi);
    (3 * x * x - 2 * x * x * x < fill ? lo : hi) = x;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("The Young-Laplace reference meets the zero-gravity closed form", "[unit][equilibrium]") {
  // Two derivations that share nothing: the meridian ODE shot at a vanishing capillary constant
  // (c R^2 = 1e-6) and the spherical cap on the contact circle. Their difference is the shooting's
  // resolution (RK4, R / 1000 per step) and the residual gravity: 0.05 points.
  for (const double theta : {40.0, 90.0, 140.0})
    for (const double fill : {0.5, 0.8}) {
      const testref::SphereMeniscus m =
          testref::youngLaplaceSphere(kR, 1e-6 / (kR * kR), theta * kDeg, 1 - fill);
      const double closed = testref::zeroGravityWetFraction((180.0 - theta) * kDeg, fill);
      INFO("theta " << theta << " fill " << fill);
      CHECK(m.upperWetFraction == Approx(closed).margin(5e-4));
    }
}

TEST_CASE("Equilibrium: vanishing tension gives the flat fill plane", "[validation][equilibrium]") {
  // sigma = 1e-7 N/m makes the Bond number 1e8: the interface is the fill plane, f = 3x^2 - 2x^3.
  // The plane lies normal to a grid axis, so its last voxel layer is partly filled: the voxels
  // of that layer tie and share the volume evenly, the reader places the interface inside them by
  // their oil share, and with a capillary length of 17 um the interface keeps its own angle down
  // to the wall (docs/methods/equilibrium.md). Measured 0.0 / +0.32 / +0.16 points at fill 0.5 /
  // 0.9 / 0.95 (the plane's height within 0.01 mm; the rest is the reading's interface normal next
  // to the wall). Bound 0.5 points, a fifth of a voxel of height (coverage changes by dz / 2R):
  // the sub-voxel placement must hold; a voxel layer off reads 2 points.
  for (const double fill : {0.5, 0.9, 0.95}) {
    const EquilibriumSolution s =
        solveEquilibrium(sphereProblem(90, fill, Vec3(0, 0, -kG), kOil, 1e-7));
    INFO("fill " << fill);
    CHECK(s.oilVolume / s.cavityVolume == Approx(fill).margin(1e-9));
    CHECK(std::abs(coverageOf(s, 90).fraction - flatCoverage(fill)) < 0.005);
  }
}

namespace {

// [1] Covered fraction of the Bond 1.2 sphere, minus its axisymmetric Young-Laplace equilibrium.
double bond12Error(double theta, double fill, double voxel) {
  const double c = (kAqueous - kOil) * kG / kSigma;
  const double reference =
      testref::youngLaplaceSphere(kR, c, theta * kDeg, 1 - fill).upperWetFraction;
  const EquilibriumSolution s =
      solveEquilibrium(sphereProblem(theta, fill, Vec3(0, 0, -kG), kOil, kSigma, voxel));
  CHECK(s.converged);
  const double measured = coverageOf(s, theta).fraction;
  INFO("theta " << theta << " fill " << fill << " voxel " << voxel << ": " << measured << " vs "
                << reference);
  return measured - reference;
}

constexpr double kDraftVoxel = 0.3e-3;  // [m] protocols' equilibriumVoxelSpacing("draft")

}  // namespace

TEST_CASE("Equilibrium at Bond 1.2 in a sphere against Young-Laplace",
          "[validation][equilibrium]") {
  // The clinical case of the toolkit: the retina's 18 deg, and 40, 90, 140 deg, at 80 and 90 %
  // fill, at the draft preset's 0.3 mm voxel (what a run uses by default). The wall kernel's
  // ratio was calibrated on these fills at 18 and 40 deg (wallKernelRatio), so there this test
  // holds the calibration: measured +0.4 / +0.1 (whole voxels) and +0.1 / -0.1 points
  // (fractional final stage), bound 1 point (the toolkit's aim). 90 and 140 deg were not
  // calibrated (90 deg has no wall term; 140 deg takes 40 deg's ratio by the phases' symmetry):
  // measured -0.1 / -0.2 and -0.4 / -0.3, bound 1 point (docs/methods/equilibrium.md, the table
  // and its command).
  for (const double theta : {18.0, 40.0, 90.0, 140.0})
    for (const double fill : {0.8, 0.9})
      CHECK(std::abs(bond12Error(theta, fill, kDraftVoxel)) < 0.01);
}

TEST_CASE("Equilibrium at Bond 1.2: fills and voxels the wall kernel was not calibrated on",
          "[validation][equilibrium]") {
  // Independent of the calibration (fill 0.8 and 0.9 at 0.3 mm): half fill and 95 % at the draft
  // voxel, and the standard preset's 0.25 mm voxel. Measured at 18 deg +0.6 (fill 0.5), -0.2
  // (0.25 mm, fill 0.9), +0.3 (fill 0.95); at 40 deg +0.4 (fill 0.5), +0.2 (fill 0.95), -0.1
  // (0.25 mm, fill 0.9). Bound 1 point, the toolkit's aim.
  CHECK(std::abs(bond12Error(18, 0.5, kDraftVoxel)) < 0.01);
  CHECK(std::abs(bond12Error(18, 0.95, kDraftVoxel)) < 0.01);
  CHECK(std::abs(bond12Error(40, 0.5, kDraftVoxel)) < 0.01);
  CHECK(std::abs(bond12Error(40, 0.95, kDraftVoxel)) < 0.01);
  CHECK(std::abs(bond12Error(18, 0.9, 0.25e-3)) < 0.01);
  CHECK(std::abs(bond12Error(40, 0.9, 0.25e-3)) < 0.01);
}

TEST_CASE("Equilibrium without gravity: the spherical cap", "[validation][equilibrium]") {
  // Zero gravity at the draft voxel against the closed form; none of these was calibrated on.
  // From 40 deg on (the fractional final stage) measured +0.05 / -0.03 at 40 deg (fill 0.8 /
  // 0.9), -0.2 / -0.2 at 90 deg and -0.4 / -0.4 at 140 deg: bound 0.5 points, the toolkit's aim
  // for this case. 18 deg (whole voxels) reads -3.5 / -3.8: bound 4.5 points, the measured error
  // and not the aim (the fractional stage meets it, the next test, but reads thin pools low).
  // (With a single kernel for wall and interface it missed by 11 and 23 points: the aqueous ran
  // along the wall as a film; docs/methods/equilibrium.md, "The wall kernel".)
  struct Case {
    double theta, fill, bound;
  };
  for (const Case c :
       {Case{18, 0.8, 0.045}, Case{18, 0.9, 0.045}, Case{40, 0.8, 0.005}, Case{40, 0.9, 0.005},
        Case{90, 0.8, 0.005}, Case{90, 0.9, 0.005}, Case{140, 0.8, 0.005}, Case{140, 0.9, 0.005}}) {
    const EquilibriumSolution s =
        solveEquilibrium(sphereProblem(c.theta, c.fill, Vec3::Zero(), kOil, kSigma, kDraftVoxel));
    const double closed = testref::zeroGravityWetFraction((180.0 - c.theta) * kDeg, c.fill);
    const double measured = coverageOf(s, c.theta).fraction;
    INFO("theta " << c.theta << " fill " << c.fill << ": " << measured << " vs " << closed);
    CHECK(std::abs(measured - closed) < c.bound);
  }
}

TEST_CASE("Fractional final stage: the 18 deg lens without gravity and the pool with it",
          "[validation][equilibrium]") {
  // The fractional final stage (FinalThreshold::kFractional) at 18 deg, where it is not the
  // default, with its own ratio there (0.97, calibrated with gravity at fills 0.8 and 0.9).
  // Without gravity, not calibrated on: measured +0.13 / +0.18 points against the lens's closed
  // form at fill 0.8 / 0.9, bound 0.5 points (the toolkit's aim for this case; whole voxels miss
  // it by 3.5 / 3.8, the test above). With gravity at fill 0.9: +0.49, bound 1 point.
  ThresholdDynamicsOptions fractional;
  fractional.finalThreshold = FinalThreshold::kFractional;
  for (const double fill : {0.8, 0.9}) {
    const EquilibriumSolution s = solveEquilibrium(
        sphereProblem(18, fill, Vec3::Zero(), kOil, kSigma, kDraftVoxel), fractional);
    const double closed = testref::zeroGravityWetFraction((180.0 - 18.0) * kDeg, fill);
    const double measured = coverageOf(s, 18).fraction;
    INFO("fill " << fill << ": " << measured << " vs " << closed);
    CHECK(std::abs(measured - closed) < 0.005);
  }
  const EquilibriumSolution pool = solveEquilibrium(
      sphereProblem(18, 0.9, Vec3(0, 0, -kG), kOil, kSigma, kDraftVoxel), fractional);
  const double reference =
      testref::youngLaplaceSphere(kR, (kAqueous - kOil) * kG / kSigma, 18 * kDeg, 0.1)
          .upperWetFraction;
  CHECK(std::abs(coverageOf(pool, 18).fraction - reference) < 0.01);
}

TEST_CASE("Equilibrium: heavy oil mirrors light oil", "[validation][equilibrium]") {
  // Swapping the phases (u -> 1 - u) maps a light oil at fill f and angle theta (through the
  // aqueous) to a heavy one (the same density difference) at fill 1 - f and 180 - theta under the
  // same gravity, and the energy onto itself up to a constant: the heavy oil covers what the light
  // oil leaves. The voxels are the same, so only the threshold's tie-breaking differs: 0.5 points.
  const double light =
      coverageOf(solveEquilibrium(sphereProblem(40, 0.8, Vec3(0, 0, -kG), kAqueous - 34.0)), 40)
          .fraction;
  const double heavy =
      coverageOf(solveEquilibrium(sphereProblem(140, 0.2, Vec3(0, 0, -kG), kAqueous + 34.0)), 140)
          .fraction;
  CHECK(heavy == Approx(1.0 - light).margin(0.005));
  // And a heavy oil pools below: its covered wall lies on the side gravity points to.
  const Coverage pooled =
      coverageOf(solveEquilibrium(sphereProblem(18, 0.3, Vec3(0, 0, -kG), 1060.0)), 18);
  CHECK(pooled.centroid.z() < -0.5);
}

TEST_CASE("Equilibrium in a sphere does not depend on the gravity direction",
          "[validation][equilibrium]") {
  // The sphere has no preferred direction, so the covered fraction must not change when gravity
  // turns off the grid axes, and the covered region (oil floats) must face away from gravity.
  // At the draft preset's voxel, what runs use. Both must meet the axisymmetric Young-Laplace
  // equilibrium within 1 point, the toolkit's aim: measured +0.1 along the axis and -0.9 turned
  // (at small angles the grid's anisotropy is worth about a point).
  const Vec3 tilted = Vec3(1, 2, -3).normalized() * kG;
  const Coverage axis = coverageOf(
      solveEquilibrium(sphereProblem(18, 0.9, Vec3(0, 0, -kG), kOil, kSigma, kDraftVoxel)), 18);
  const Coverage turned =
      coverageOf(solveEquilibrium(sphereProblem(18, 0.9, tilted, kOil, kSigma, kDraftVoxel)), 18);
  const double reference =
      testref::youngLaplaceSphere(kR, (kAqueous - kOil) * kG / kSigma, 18 * kDeg, 0.1)
          .upperWetFraction;
  INFO("along an axis " << axis.fraction << ", turned " << turned.fraction << ", Young-Laplace "
                        << reference);
  CHECK(std::abs(axis.fraction - reference) < 0.01);
  CHECK(std::abs(turned.fraction - reference) < 0.01);
  const double angle =
      std::acos(std::clamp(turned.centroid.normalized().dot(-tilted.normalized()), -1.0, 1.0));
  CHECK(angle < 3.0 * kDeg);
}

TEST_CASE("Equilibrium refuses problems without a contact line or an interface",
          "[unit][equilibrium]") {
  CHECK_THROWS_AS(solveEquilibrium(sphereProblem(0, 0.9, Vec3(0, 0, -kG))), SimError);
  CHECK_THROWS_AS(solveEquilibrium(sphereProblem(180, 0.9, Vec3(0, 0, -kG))), SimError);
  CHECK_THROWS_AS(solveEquilibrium(sphereProblem(18, 1.0, Vec3(0, 0, -kG))), SimError);
  CHECK_THROWS_AS(solveEquilibrium(sphereProblem(18, 0.0, Vec3(0, 0, -kG))), SimError);
}

TEST_CASE("The equilibrium interface surface lies on the Young-Laplace meridian",
          "[validation][equilibrium]") {
  // 90 deg, 90 % fill: every vertex of the extracted surface within 1.5 voxels of the
  // axisymmetric meridian: a surface-nets vertex is the mean of its cell's edge crossings (up to
  // half a cell diagonal, 0.87 h, off the interface they sample), and the binary state places the
  // interface to half a voxel.
  const double c = (kAqueous - kOil) * kG / kSigma;
  const testref::SphereMeniscus m = testref::youngLaplaceSphere(kR, c, 90 * kDeg, 0.1);
  const EquilibriumSolution s = solveEquilibrium(sphereProblem(90, 0.9, Vec3(0, 0, -kG)));
  const InterfaceSurface surface = interfaceSurface(s);
  REQUIRE(surface.triangles.size() > 100);
  double worst = 0.0;
  for (const Vec3& v : surface.vertices) {
    const double r = std::hypot(v.x(), v.y());
    double best = 1e9;
    for (const auto& [mr, mz] : m.meridian) best = std::min(best, std::hypot(r - mr, v.z() - mz));
    worst = std::max(worst, best);
  }
  CHECK(worst < 1.5 * kVoxel);
}
