// Coverage metrics on constructed particle states with known answers: a flat
// oil/aqueous interface in a sphere against the spherical-zone closed form, breaks above and
// below the interface, dry walls, the Shepard weights themselves, and time averages.
#include <catch2/catch.hpp>

#include <cmath>

#include "meshing/make_icosphere.h"
#include "meshing/sample_surface.h"
#include "meshing/sample_volume.h"
#include "protocols/coverage/coverage_error.h"
#include "protocols/coverage/frame_coverage.h"
#include "protocols/coverage/schedule_coverage.h"
#include "protocols/coverage/wall_oil_fraction.h"

using namespace protocols;

namespace {

constexpr double kRadius = 11e-3;                 // [m] sphere of about an eye's 5.6 mL
constexpr double kDraftSpacing = 0.8e-3;          // [m] the draft preset's d (protocol.h)
constexpr double kWallGap = 1.2 * kDraftSpacing;  // [m] fluid starts 1.2 d from the wall
// [m] h_c = g + sqrt(3) d, the coverage kernel's support (wall_oil_fraction.h)
const double kCoverageRadius = coverageSupportRadius(kDraftSpacing, kWallGap);

struct SphereState {
  meshing::SurfaceSamples walls;
  std::vector<sim::Vec3> fluid;
  std::vector<std::uint8_t> isOil;
  RetinaMap map;
};

// Wall particles on a sphere (the whole wall is retina), fluid on a lattice whose planes sit at
// z0 +- d/2, +- 3d/2, ...: oil above z0, aqueous below, so the discrete interface is exactly z0.
SphereState sphereWithInterface(double z0) {
  SphereState s;
  // 5 subdivisions: edge ~0.4 mm, chordal sag ~2 um, negligible against d.
  const meshing::TriangleMesh mesh = meshing::makeIcosphere(kRadius, 5);
  s.walls = meshing::sampleSurface(mesh, kDraftSpacing);
  meshing::VolumeSamplingOptions o;
  o.spacing = kDraftSpacing;
  o.wallGap = kWallGap;
  o.latticeOrigin = sim::Vec3(0, 0, z0 + 0.5 * kDraftSpacing);
  s.fluid = meshing::sampleVolume(mesh, o);
  for (const auto& p : s.fluid) s.isOil.push_back(p.z() >= z0 ? 1 : 0);
  s.map.areas = s.walls.areas;
  s.map.regions.assign(s.walls.size(), anatomy::kRetina);
  return s;
}

WallOilFractions fractionsOf(const SphereState& s) {
  const sim::Kernel kernel(sim::KernelKind::kCubicSpline, kCoverageRadius);
  return computeWallOilFractions(s.walls.points, {&s.fluid, &s.isOil, nullptr}, kernel);
}

std::vector<std::size_t> wallsWithin(const SphereState& s, const sim::Vec3& centre, double radius) {
  std::vector<std::size_t> out;
  for (std::size_t w = 0; w < s.walls.size(); ++w)
    if ((s.walls.points[w] - centre).norm() <= radius) out.push_back(w);
  return out;
}

}  // namespace

TEST_CASE("flat interface in a sphere gives the spherical-zone fraction at draft spacing",
          "[validation][coverage]") {
  // Closed form: the sphere's area above z = z0 is 2 pi R (R - z0) (Archimedes' hat-box
  // theorem), i.e. the fraction (R - z0) / (2R).
  //
  // Tolerance, derived before running:
  // (1) bias: the Shepard sum reads phi at the weighted centroid of the wall particle's fluid
  //     neighbours, not at the wall. They lie at depth delta in [g, h_c] (the wall gap to the
  //     coverage support radius h_c = g + sqrt(3) d = 2.93 d) along the inward normal, whose
  //     z-component is -z/R. phi = 0.5 therefore sits where z (1 - delta/R) = z0, i.e. the wall
  //     boundary moves by dz = z0 delta / R away from the centre, and the fraction by
  //     -dz / (2R): |bias| <= |z0| h_c / (2 R^2), and its sign is opposite to z0's;
  // (2) noise: about 2 pi R / d ~ 86 wall particles straddle the boundary, each of area
  //     ~d^2 / 0.86 (RSA density, sample_surface.h); if each landed on the wrong side at random
  //     the fraction would scatter by sqrt(86) * 0.74 mm^2 / (4 pi R^2) ~ 0.005. 0.01 = 2 sigma
  //     of that worst case.
  constexpr double kNoise = 0.01;
  for (double z0 : {-0.6 * kRadius, -0.2 * kRadius, 0.0, 0.3 * kRadius, 0.7 * kRadius}) {
    const SphereState s = sphereWithInterface(z0);
    const FrameCoverage frame = measureFrameCoverage(s.map, fractionsOf(s), 0.0);
    const double exact = (kRadius - z0) / (2.0 * kRadius);
    const double maxBias = std::abs(z0) * kCoverageRadius / (2.0 * kRadius * kRadius);
    const double error = frame.retina().fraction - exact;
    INFO("z0 = " << z0 * 1e3 << " mm: coverage " << frame.retina().fraction << ", exact " << exact
                 << ", error " << error << ", bias bound " << maxBias);
    CHECK(std::abs(error) <= maxBias + kNoise);
    // The bias has the predicted sign: toward the equator's value 0.5.
    if (z0 > 0) CHECK(error <= kNoise);
    if (z0 < 0) CHECK(error >= -kNoise);
    // Every wall particle has a lattice point within h_c (wall_oil_fraction.h): nothing is dry.
    CHECK(frame.retina().dryArea == 0.0);
    // The areas sum to the mesh area (4 pi R^2 up to the icosphere's 0.03 % deficit).
    CHECK(frame.retina().area == Approx(4.0 * M_PI * kRadius * kRadius).epsilon(1e-3));
  }
}

TEST_CASE("a break entirely above the interface is covered, one below is not",
          "[validation][coverage]") {
  const double z0 = 0.3 * kRadius;
  SphereState s = sphereWithInterface(z0);
  // 3 mm breaks at the top and the bottom of the sphere, and one on the equator, i.e. well
  // below the interface: its wall particles are 0.3 R = 3.3 mm below z0, beyond h_c = 2.3 mm.
  s.map.breakNames = {"top", "bottom", "equator"};
  s.map.breakWalls = {wallsWithin(s, {0, 0, kRadius}, 1.5e-3),
                      wallsWithin(s, {0, 0, -kRadius}, 1.5e-3),
                      wallsWithin(s, {kRadius, 0, 0}, 1.5e-3)};
  for (const auto& walls : s.map.breakWalls) REQUIRE(walls.size() >= 5);
  const FrameCoverage frame = measureFrameCoverage(s.map, fractionsOf(s), 2.0);
  CHECK(frame.time == 2.0);
  CHECK(frame.breaks[0].covered);
  CHECK(frame.breaks[0].area.fraction == 1.0);
  CHECK_FALSE(frame.breaks[1].covered);
  CHECK(frame.breaks[1].area.fraction == 0.0);
  CHECK_FALSE(frame.breaks[2].covered);
  CHECK(frame.breaks[2].area.fraction == 0.0);
}

TEST_CASE("regions are measured separately, walls without fluid are dry", "[unit][coverage]") {
  // The same sphere with oil above z = 0, and the fluid with y > 0 removed: the superior half
  // of the wall (y > h_c) has no fluid within h_c and is dry, so it counts as not covered.
  SphereState s = sphereWithInterface(0.0);
  std::vector<sim::Vec3> fluid;
  std::vector<std::uint8_t> isOil;
  for (std::size_t j = 0; j < s.fluid.size(); ++j)
    if (s.fluid[j].y() <= 0) {
      fluid.push_back(s.fluid[j]);
      isOil.push_back(s.isOil[j]);
    }
  for (std::size_t w = 0; w < s.walls.size(); ++w)
    s.map.regions[w] |= s.walls.points[w].y() > 0 ? anatomy::kSuperior : anatomy::kInferior;
  const sim::Kernel kernel(sim::KernelKind::kCubicSpline, kCoverageRadius);
  const WallOilFractions f =
      computeWallOilFractions(s.walls.points, {&fluid, &isOil, nullptr}, kernel);
  for (std::size_t w = 0; w < s.walls.size(); ++w)
    if (s.walls.points[w].y() > kCoverageRadius) CHECK(f.wetting[w] == WallWetting::kDry);
  const FrameCoverage frame = measureFrameCoverage(s.map, f, 0.0);
  const AreaCoverage& superior = frame.regions[1];
  const AreaCoverage& inferior = frame.regions[2];
  REQUIRE(kReportedRegions[1].bit == anatomy::kSuperior);
  // Superior: all dry except a band at y in (0, h_c]: at most h_c / R = 21 % of the
  // hemisphere's height, hence of its area (hat-box theorem again).
  CHECK(superior.dryArea / superior.area >= 1.0 - kCoverageRadius / kRadius);
  CHECK(superior.fraction <= kCoverageRadius / kRadius);
  // Inferior: wet, half of it above z = 0 by symmetry; noise as in the zone test.
  CHECK(inferior.dryArea == 0.0);
  CHECK(inferior.fraction == Approx(0.5).margin(0.01));
  // The whole retina adds the two.
  CHECK(frame.retina().area == Approx(superior.area + inferior.area).epsilon(1e-12));
}

TEST_CASE("wall oil fraction is the Shepard-normalised, volume-weighted indicator",
          "[unit][coverage]") {
  const sim::Kernel kernel(sim::KernelKind::kCubicSpline, 1.0);
  const std::vector<sim::Vec3> walls = {{0, 0, 0}, {10, 0, 0}};
  const std::vector<sim::Vec3> fluid = {{0.3, 0, 0}, {-0.3, 0, 0}, {0, 0.9, 0}};
  const std::vector<std::uint8_t> isOil = {1, 0, 1};
  // Equal volumes: W(0.3) each for the first two, W(0.9) for the third.
  const double w3 = kernel.W(0.3), w9 = kernel.W(0.9);
  auto f = computeWallOilFractions(walls, {&fluid, &isOil, nullptr}, kernel);
  CHECK(f.oilFraction[0] == Approx((w3 + w9) / (2 * w3 + w9)).epsilon(1e-14));
  CHECK(f.wetting[0] == WallWetting::kOil);
  CHECK(f.wetting[1] == WallWetting::kDry);  // nothing within h = 1
  CHECK(f.oilFraction[1] == 0.0);
  // Volumes weight the sum: an aqueous particle of 3x the volume turns the wall aqueous.
  const std::vector<double> volumes = {1.0, 3.0, 0.0};
  f = computeWallOilFractions(walls, {&fluid, &isOil, &volumes}, kernel);
  CHECK(f.oilFraction[0] == Approx(0.25).epsilon(1e-14));
  CHECK(f.wetting[0] == WallWetting::kAqueous);
  // Bad input names the sizes.
  const std::vector<std::uint8_t> shortFlags = {1};
  CHECK_THROWS_WITH(computeWallOilFractions(walls, {&fluid, &shortFlags, nullptr}, kernel),
                    Catch::Contains("3 fluid positions but 1 phase flags"));
}

TEST_CASE("schedule coverage is the time-weighted mean of the frames", "[unit][coverage]") {
  auto frame = [](double t, double fraction, bool covered) {
    FrameCoverage f;
    f.time = t;
    f.regions[0].fraction = fraction;
    f.breaks.resize(1);
    f.breaks[0].area.fraction = fraction;
    f.breaks[0].covered = covered;
    return f;
  };
  // Frames at 0, 1, 3 s stand for [0, 0.5], [0.5, 2], [2, 3]: weights 1/6, 1/2, 1/3.
  const ScheduleCoverage s =
      summarizeSchedule({frame(0, 0.0, false), frame(1, 1.0, true), frame(3, 0.4, true)});
  CHECK(s.duration == 3.0);
  CHECK(s.regions[0] == Approx(0.5 + 0.4 / 3.0).epsilon(1e-14));
  CHECK(s.breakFraction[0] == Approx(0.5 + 0.4 / 3.0).epsilon(1e-14));
  CHECK(s.breakTimeCovered[0] == Approx(5.0 / 6.0).epsilon(1e-14));
  CHECK(summarizeSchedule({frame(5, 0.7, true)}).regions[0] == 0.7);
  CHECK_THROWS_AS(summarizeSchedule({}), CoverageError);
  CHECK_THROWS_WITH(summarizeSchedule({frame(1, 0, false), frame(1, 0, false)}),
                    Catch::Contains("frames must be in increasing time"));
}
