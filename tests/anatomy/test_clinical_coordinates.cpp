// Clock hours, OD/OS, clinical coordinates <-> wall points, and postures.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "anatomy/anatomy_error.h"
#include "anatomy/clock_hour.h"
#include "anatomy/eye.h"
#include "anatomy/posture.h"
#include "anatomy/vitreous_cavity.h"
#include "sphere_eye.h"

using namespace anatomy;

namespace {
constexpr double kMm = 1e-3;
constexpr double kDegree = std::numbers::pi / 180.0;
}  // namespace

TEST_CASE("clock hours: 12 superior, 3 toward the patient's left", "[unit][clinical]") {
  CHECK((clockHourDirection(12.0) - Vec3(0, 1, 0)).norm() < 1e-15);
  CHECK((clockHourDirection(3.0) - Vec3(1, 0, 0)).norm() < 1e-15);
  CHECK((clockHourDirection(6.0) - Vec3(0, -1, 0)).norm() < 1e-15);
  CHECK((clockHourDirection(9.0) - Vec3(-1, 0, 0)).norm() < 1e-15);
  for (double h = 0.25; h <= 12.0; h += 0.25)
    CHECK(clockHourOf(clockHourDirection(h)) == Approx(h).margin(1e-12));
  CHECK(clockHourDifference(11.0, 1.0) == Approx(-2.0));
  CHECK(clockHourDifference(1.0, 11.0) == Approx(2.0));
  CHECK_THROWS_AS(clockHourOf(Vec3(0, 0, 1)), AnatomyError);
}

TEST_CASE("OD: 3 o'clock is nasal, OS: 3 o'clock is temporal", "[unit][clinical]") {
  // The patient's left (+x) is toward the nose for the right eye and away from it for the left.
  CHECK(clockHourDirection(3.0).dot(nasalDirection(Laterality::kRight)) == Approx(1.0));
  CHECK(clockHourDirection(9.0).dot(temporalDirection(Laterality::kRight)) == Approx(1.0));
  CHECK(clockHourDirection(3.0).dot(temporalDirection(Laterality::kLeft)) == Approx(1.0));
  CHECK(clockHourDirection(9.0).dot(nasalDirection(Laterality::kLeft)) == Approx(1.0));
  CHECK(parseLaterality("od") == Laterality::kRight);
  CHECK(parseLaterality("OS") == Laterality::kLeft);
  CHECK_THROWS_WITH(parseLaterality("OU"), Catch::Contains("OD (right eye) or OS (left eye)"));
}

TEST_CASE("clinical position round trip on parametric eyes", "[unit][clinical]") {
  StaphylomaCavityParameters p;
  const CavityShape shapes[] = {CavityShape(emmetropicGeometry({})),
                                CavityShape(myopicGeometry({})),
                                CavityShape(staphylomaGeometry(p))};
  for (const CavityShape& shape : shapes)
    for (Laterality side : {Laterality::kRight, Laterality::kLeft}) {
      const Eye eye(side, shape);
      for (double hour : {0.5, 1.5, 3.0, 4.25, 6.0, 7.5, 9.0, 10.75, 12.0})
        for (double distance : {5.0, 6.2, 10.0, 15.0, 20.0}) {
          const WallPoint w = eye.wallPointAt({hour, distance * kMm});
          // The point lies on the wall (its own nearest wall point) ...
          const WallCoordinate c = shape.closestWallCoordinate(w.position);
          CHECK((shape.wallPoint(c) - w.position).norm() < 1e-9);
          CHECK(w.normal.norm() == Approx(1.0));
          // ... and maps back to the same clock hour and distance. Tolerance 1 um: the distance
          // table interpolates to < 1 um (eye.cpp), the inverse uses the same table.
          const ClinicalPosition back = eye.clinicalPositionOf(w.position);
          CHECK(clockHourDifference(back.clockHour, hour) == Approx(0.0).margin(1e-9));
          CHECK(back.distance == Approx(distance * kMm).margin(1e-6));
          const ClinicalPosition fromOra =
              eye.clinicalPositionOf(w.position, DistanceReference::kOraSerrata);
          CHECK(fromOra.distance == Approx((distance - 6.2) * kMm).margin(1e-6));
        }
    }
}

TEST_CASE("distance table agrees with direct integration and the sphere's R theta",
          "[unit][clinical]") {
  const CavityShape sphere(test::sphereGeometry());
  const Eye eye(Laterality::kRight, sphere);
  const double R = test::kSphereRadius;
  for (double theta : {0.0, 0.3, 1.0, 1.5, 2.0}) {
    // On a sphere the wall distance is R x angle (exact; quadrature error < 1e-12 m).
    CHECK(sphere.arcLength(theta, sphere.rimTheta(), 0.7) ==
          Approx(R * (sphere.rimTheta() - theta)).margin(1e-12));
    CHECK(eye.distanceFromLimbus({theta, 0.7}) ==
          Approx(4.5 * kMm + R * (sphere.rimTheta() - theta)).margin(1e-7));
  }
  // Triaxial eye: table vs direct integration, 1 um.
  const CavityShape myopic(myopicGeometry({}));
  const Eye myopicEye(Laterality::kLeft, myopic);
  for (double m : {0.1, 1.0, 2.5, 4.0})
    for (double theta : {0.2, 1.2, 2.0})
      CHECK(myopicEye.distanceFromLimbus({theta, m}) ==
            Approx(4.5 * kMm + myopic.arcLength(theta, myopic.rimTheta(), m)).margin(1e-6));
}

TEST_CASE("OD and OS are mirror images across the vertical midplane", "[unit][clinical]") {
  // Reflection x -> -x maps clock hour h to 12 - h and the right eye onto the left eye.
  const CavityShape shape(myopicGeometry({}));
  const Eye right(Laterality::kRight, shape), left(Laterality::kLeft, shape);
  for (double hour : {1.0, 2.5, 3.0, 4.0, 8.0, 10.5})
    for (double distance : {7.0, 12.0, 18.0}) {
      const Vec3 od = right.wallPointAt({hour, distance * kMm}).position;
      const Vec3 os = left.wallPointAt({12.0 - hour, distance * kMm}).position;
      CHECK((Vec3(-od.x(), od.y(), od.z()) - os).norm() < 1e-9);
    }
  CHECK(right.opticDisc().x() > 0.0);  // nasal = +x for OD
  CHECK(left.opticDisc().x() < 0.0);
  CHECK((Vec3(-right.opticDisc().x(), right.opticDisc().y(), right.opticDisc().z()) -
         left.opticDisc())
            .norm() < 1e-9);
}

TEST_CASE("positions off the modelled wall are rejected", "[unit][clinical]") {
  const Eye eye(Laterality::kRight, CavityShape(emmetropicGeometry({})));
  CHECK_THROWS_WITH(eye.wallPointAt({3.0, 2.0 * kMm}),
                    Catch::Contains("anterior to the modelled wall"));
  CHECK_THROWS_WITH(eye.wallPointAt({3.0, 60.0 * kMm}),
                    Catch::Contains("beyond the posterior pole"));
  CHECK_THROWS_WITH(eye.wallPointAt({13.0, 10.0 * kMm}), Catch::Contains("clock hour"));
  CHECK_THROWS_WITH(eye.clinicalPositionOf(eye.cavity().capPoint(0.2, 1.0)),
                    Catch::Contains("lens/IOL cap"));
}

TEST_CASE("postures: unit gravity vectors in the documented directions", "[unit][posture]") {
  CHECK(gravityDirection(Posture::kUpright) == Vec3(0, -1, 0));
  CHECK(gravityDirection(Posture::kSupine) == Vec3(0, 0, -1));
  CHECK(gravityDirection(Posture::kFaceDown) == Vec3(0, 0, 1));
  CHECK(gravityDirection(Posture::kLeftSide) == Vec3(1, 0, 0));
  CHECK(gravityDirection(Posture::kRightSide) == Vec3(-1, 0, 0));
  // Head angles reproduce every named posture (posture.h).
  const auto close = [](const Vec3& a, const Vec3& b) { return (a - b).norm() < 1e-15; };
  CHECK(close(gravityFromHeadAngles(0, 0), gravityDirection(Posture::kUpright)));
  CHECK(close(gravityFromHeadAngles(90 * kDegree, 0), gravityDirection(Posture::kFaceDown)));
  CHECK(close(gravityFromHeadAngles(-90 * kDegree, 0), gravityDirection(Posture::kSupine)));
  CHECK(close(gravityFromHeadAngles(0, 90 * kDegree), gravityDirection(Posture::kLeftSide)));
  CHECK(close(gravityFromHeadAngles(0, -90 * kDegree), gravityDirection(Posture::kRightSide)));
  for (double pitch = -90; pitch <= 90; pitch += 15)
    for (double roll = -180; roll <= 180; roll += 20)
      CHECK(gravityFromHeadAngles(pitch * kDegree, roll * kDegree).norm() == Approx(1.0));
  // 30 deg forward flexion: gravity tilts from -y toward +z (anterior) by 30 deg.
  CHECK(gravityFromHeadAngles(30 * kDegree, 0).dot(Vec3(0, -1, 0)) ==
        Approx(std::cos(30 * kDegree)));
  CHECK(gravityFromHeadAngles(30 * kDegree, 0).z() > 0.0);
  CHECK(parsePosture("prone") == Posture::kFaceDown);
  CHECK(parsePosture(toString(Posture::kLeftSide)) == Posture::kLeftSide);
  CHECK_THROWS_WITH(parsePosture("sideways"), Catch::Contains("unknown posture 'sideways'"));
}
