// Retinal regions and breaks on a spherical cavity, where every landmark has a closed form:
// wall distance = R x angle, chord = 2 R sin(angle / 2).
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>

#include "anatomy/anatomy_error.h"
#include "anatomy/clock_hour.h"
#include "anatomy/retinal_break.h"
#include "anatomy/retinal_regions.h"
#include "anatomy/vitreous_cavity.h"
#include "sphere_eye.h"

using namespace anatomy;

namespace {

constexpr double kMm = 1e-3;
constexpr double R = test::kSphereRadius;

// Point on the sphere at `distance` [m] posterior to the limbus on clock hour `hour`, built from
// the closed form (not from Eye::wallPointAt): polar angle from the posterior pole
// theta = rimTheta - (distance - limbusToRim) / R.
Vec3 spherePoint(const Eye& eye, double hour, double distance) {
  const double theta = eye.cavity().rimTheta() - (distance - eye.landmarks().limbusToRim) / R;
  const Vec3 d = clockHourDirection(hour);
  const Vec3 pole = eye.cavity().posteriorPole();
  return {R * std::sin(theta) * d.x(), R * std::sin(theta) * d.y(),
          pole.z() + R * (1.0 - std::cos(theta))};
}

}  // namespace

TEST_CASE("known points on a sphere fall in the right regions", "[unit][regions]") {
  const CavityShape sphere(test::sphereGeometry());
  const Eye od(Laterality::kRight, sphere), os(Laterality::kLeft, sphere);
  const double ora = od.landmarks().oraFromLimbus;
  const double pole = od.distanceToPosteriorPole(0.0);
  CHECK(pole == Approx(4.5 * kMm + R * sphere.rimTheta()).margin(1e-7));
  const double equator = od.landmarks().limbusToRim + R * (sphere.rimTheta() - M_PI / 2);

  // Quadrants: centred on 12, 6 and 3/9; nasal = 3 o'clock for OD and 9 o'clock for OS.
  const double mid = 0.5 * (ora + equator);
  CHECK(regionsAt(od, spherePoint(od, 12.0, mid)) == (kRetina | kSuperior | kPeriphery));
  CHECK(regionsAt(od, spherePoint(od, 6.0, mid)) == (kRetina | kInferior | kPeriphery));
  CHECK(regionsAt(od, spherePoint(od, 3.0, mid)) == (kRetina | kNasal | kPeriphery));
  CHECK(regionsAt(od, spherePoint(od, 9.0, mid)) == (kRetina | kTemporal | kPeriphery));
  CHECK(regionsAt(os, spherePoint(os, 3.0, mid)) == (kRetina | kTemporal | kPeriphery));
  CHECK(regionsAt(os, spherePoint(os, 9.0, mid)) == (kRetina | kNasal | kPeriphery));
  // Sector edges are half-open [centre - 1.5 h, centre + 1.5 h).
  CHECK((regionsAt(od, spherePoint(od, 1.4, mid)) & kSuperior) != 0);
  CHECK((regionsAt(od, spherePoint(od, 1.6, mid)) & kNasal) != 0);
  CHECK((regionsAt(od, spherePoint(od, 10.6, mid)) & kSuperior) != 0);
  CHECK((regionsAt(od, spherePoint(od, 10.4, mid)) & kTemporal) != 0);

  // Ora serrata: 0.1 mm anterior -> not retina; 0.1 mm posterior -> retina.
  CHECK(regionsAt(od, spherePoint(od, 2.0, ora - 0.1 * kMm)) == 0);
  CHECK((regionsAt(od, spherePoint(od, 2.0, ora + 0.1 * kMm)) & kRetina) != 0);
  // Equator: periphery anterior to it, mid-periphery posterior to it.
  CHECK((regionsAt(od, spherePoint(od, 2.0, equator - 0.1 * kMm)) & kPeriphery) != 0);
  CHECK((regionsAt(od, spherePoint(od, 2.0, equator + 0.1 * kMm)) & kMidPeriphery) != 0);

  // Fovea at the posterior pole: macula and posterior pole, no quadrant (on the axis).
  CHECK(regionsAt(od, od.fovea()) == (kRetina | kMacula | kPosteriorPole));
  // Macula edge: chord 2 mm from the fovea = arc 2 R asin(1 mm / R).
  const double maculaArc = 2.0 * R * std::asin(1.0 * kMm / R);
  CHECK((regionsAt(od, spherePoint(od, 9.0, pole - maculaArc + 0.05 * kMm)) & kMacula) != 0);
  CHECK((regionsAt(od, spherePoint(od, 9.0, pole - maculaArc - 0.05 * kMm)) & kMacula) == 0);
  // Posterior pole edge: chord 6 mm.
  const double poleArc = 2.0 * R * std::asin(3.0 * kMm / R);
  CHECK((regionsAt(od, spherePoint(od, 7.0, pole - poleArc + 0.05 * kMm)) & kPosteriorPole) != 0);
  CHECK((regionsAt(od, spherePoint(od, 7.0, pole - poleArc - 0.05 * kMm)) &
         (kPosteriorPole | kMidPeriphery)) == kMidPeriphery);
  // Optic disc: 4.76 mm nasal of the fovea along the wall (3 o'clock in OD, 9 in OS), so the
  // macula is temporal to the disc.
  CHECK((od.opticDisc() - spherePoint(od, 3.0, pole - 4.76 * kMm)).norm() < 1e-6);
  CHECK((os.opticDisc() - spherePoint(os, 9.0, pole - 4.76 * kMm)).norm() < 1e-6);
  CHECK((regionsAt(od, od.opticDisc()) & (kOpticDisc | kNasal | kPosteriorPole)) ==
        (kOpticDisc | kNasal | kPosteriorPole));

  // The lens/IOL cap is not retina.
  CHECK(regionsAt(od, sphere.capPoint(0.5, 1.0)) == 0);
  CHECK(describeRegions(kRetina | kSuperior | kMacula) == "retina|superior|macula");
  CHECK(describeRegions(0) == "none");
}

TEST_CASE("every retinal point is in exactly one quadrant and one zone", "[unit][regions]") {
  const CavityShape sphere(test::sphereGeometry());
  const Eye eye(Laterality::kLeft, sphere);
  const auto mesh = sphere.triangulate(48);
  const auto regions = assignRegions(eye, mesh.vertices);
  int retinal = 0;
  for (size_t i = 0; i < regions.size(); ++i) {
    const RegionSet r = regions[i];
    if (!(r & kRetina)) continue;
    ++retinal;
    const auto count = [&](RegionSet bits) { return __builtin_popcount(r & bits); };
    const bool onAxis = std::hypot(mesh.vertices[i].x(), mesh.vertices[i].y()) < 1e-9;
    CHECK(count(kSuperior | kInferior | kNasal | kTemporal) == (onAxis ? 0 : 1));
    CHECK(count(kPosteriorPole | kMidPeriphery | kPeriphery) == 1);
  }
  CHECK(retinal > 0);
}

TEST_CASE("retinal breaks: membership on a sphere, rejection anterior to the ora",
          "[unit][regions]") {
  const CavityShape sphere(test::sphereGeometry());
  const Eye od(Laterality::kRight, sphere);
  const double ora = od.landmarks().oraFromLimbus;
  const RetinalBreak tear(
      od, {"horseshoe tear", {10.5, 2.0 * kMm, DistanceReference::kOraSerrata}, 3.0 * kMm});
  // Centre: 2 mm posterior to the ora at 10:30.
  CHECK((tear.centre().position - spherePoint(od, 10.5, ora + 2.0 * kMm)).norm() < 1e-6);
  CHECK(tear.isInBreak(tear.centre().position));
  // Along the meridian the chord for an arc s is 2 R sin(s / 2R); radius 1.5 mm.
  const double edgeArc = 2.0 * R * std::asin(1.5 * kMm / (2.0 * R));
  CHECK(tear.isInBreak(spherePoint(od, 10.5, ora + 2.0 * kMm + edgeArc - 0.02 * kMm)));
  CHECK_FALSE(tear.isInBreak(spherePoint(od, 10.5, ora + 2.0 * kMm + edgeArc + 0.02 * kMm)));
  CHECK_FALSE(tear.isInBreak(spherePoint(od, 4.5, ora + 2.0 * kMm)));  // opposite side
  // The same break given from the limbus.
  const RetinalBreak same(od, {"same", {10.5, ora + 2.0 * kMm}, 3.0 * kMm});
  CHECK((same.centre().position - tear.centre().position).norm() < 1e-9);

  // Anterior to the ora serrata: rejected, naming the break and the ora.
  CHECK_THROWS_AS(RetinalBreak(od, {"dialysis 1", {6.0, 5.0 * kMm}, 1.0 * kMm}), AnatomyError);
  CHECK_THROWS_WITH(RetinalBreak(od, {"dialysis 1", {6.0, 5.0 * kMm}, 1.0 * kMm}),
                    Catch::Contains("retinal break 'dialysis 1'") &&
                        Catch::Contains("anterior to the ora serrata"));
  CHECK_THROWS_WITH(
      RetinalBreak(od, {"hole 2", {6.0, -0.5 * kMm, DistanceReference::kOraSerrata}, 1.0 * kMm}),
      Catch::Contains("'hole 2'") && Catch::Contains("anterior to the ora serrata"));
  CHECK_THROWS_WITH(RetinalBreak(od, {"hole 3", {6.0, 10.0 * kMm}, 0.0}),
                    Catch::Contains("'hole 3'") && Catch::Contains("diameter"));
  CHECK_THROWS_WITH(RetinalBreak(od, {"hole 4", {6.0, 80.0 * kMm}, 1.0 * kMm}),
                    Catch::Contains("'hole 4'") && Catch::Contains("beyond the posterior pole"));
}

TEST_CASE("retinal area of the emmetropic model matches MRI data", "[validation][regions]") {
  // Nagra M et al., J Anat 2017;231(3):319-324 (reference-data.md 4.4): retinal area
  // 1363 +- 160 mm^2 by 3-T MRI in 73 adults with AL 24.51 +- 1.57 mm. The model eye of that
  // axial length must lie within one standard deviation: the cohort's spread, which also covers
  // the model's [U] landmarks (ora 6.2 mm, rim 4.5 mm behind the limbus). Measured: ~1292 mm^2.
  EmmetropicCavityParameters p;
  p.axialLength = 24.51 * kMm;
  p.resolution = 128;
  const VitreousCavity cavity = makeEmmetropicCavity(p);
  const Eye eye(Laterality::kRight, cavity.shape);
  double retinalArea = 0.0;  // [m^2] faces whose centroid is retina
  for (const auto& f : cavity.mesh.faces) {
    const Vec3& a = cavity.mesh.vertices[static_cast<size_t>(f[0])];
    const Vec3& b = cavity.mesh.vertices[static_cast<size_t>(f[1])];
    const Vec3& c = cavity.mesh.vertices[static_cast<size_t>(f[2])];
    const Vec3 normal = (b - a).cross(c - a).normalized();
    if (regionsAt(eye, (a + b + c) / 3.0, &normal) & kRetina)
      retinalArea += 0.5 * (b - a).cross(c - a).norm();
  }
  INFO("retinal area " << retinalArea * 1e6 << " mm^2");
  CHECK(std::abs(retinalArea - 1363e-6) <= 160e-6);
}
