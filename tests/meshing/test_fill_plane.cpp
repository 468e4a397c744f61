// Fill level: exact clipped volumes, spherical caps, and which side fills.
#include <catch2/catch.hpp>

#include <cmath>

#include "meshing/find_fill_plane.h"
#include "meshing/mesh_error.h"
#include "meshing/mesh_measures.h"
#include "test_meshes.h"

using namespace meshing;

namespace {
constexpr double kR = 0.012;                                                     // [m]
double capVolume(double R, double h) { return M_PI * h * h * (3 * R - h) / 3; }  // [m^3]
}  // namespace

TEST_CASE("clipped volume is exact on a polyhedron and conserves volume in any direction",
          "[unit][fill]") {
  // Above + below == total for arbitrary directions and offsets, to round-off: the clip adds
  // no volume and loses none.
  const TriangleMesh m = meshing_test::eyeSphere(3);
  const double total = measureMesh(m).signedVolume;
  for (const Vec3& u :
       {Vec3(0, 0, 1), Vec3(1, 2, -3).normalized(), Vec3(-0.3, 0.1, 0.9).normalized()})
    for (double c : {-0.011, -0.004, 0.0, 0.0023, 0.0119}) {
      const double above = clippedVolume(m, u, c), below = clippedVolume(m, -u, -c);
      CHECK(above + below == Approx(total).epsilon(1e-12));
    }
  // Symmetric polyhedron (icosphere is centrally symmetric): half on each side of a plane
  // through the centre, exactly.
  CHECK(clippedVolume(m, Vec3(0.2, -0.5, 0.7).normalized(), 0.0) ==
        Approx(0.5 * total).epsilon(1e-12));
}

TEST_CASE("fill plane on a sphere matches the spherical cap", "[validation][fill]") {
  // 20480 faces: the polyhedron's volume is 0.05 % below the sphere's, caps alike, so the
  // closed form holds to ~0.1 %; the brief's 0.5 % leaves room for the cap's slightly different
  // chordal error near the rim.
  const TriangleMesh m = meshing_test::eyeSphere(5);
  const double sphereVolume = 4.0 / 3.0 * M_PI * kR * kR * kR;
  const Vec3 gravity(0, -1, 0);  // upright patient: -y is inferior in the eye frame
  for (double f : {0.05, 0.2, 0.5, 0.8, 0.95}) {
    INFO("fill fraction " << f);
    // Silicone oil floats: it fills from the top, u = -gravity.
    const FillPlane plane = findFillPlane(m, f, -gravity);
    const double h = kR - plane.offset;  // cap height above the plane
    CHECK(plane.volumeAbove == Approx(capVolume(kR, h)).epsilon(0.005));
    CHECK(plane.volumeBelow == Approx(capVolume(kR, 2 * kR - h)).epsilon(0.005));
    CHECK(plane.volumeAbove / (plane.volumeAbove + plane.volumeBelow) == Approx(f).epsilon(1e-9));
    // And the offset itself: solve the closed-form cap for f of the sphere by bisection.
    double lo = 0, hi = 2 * kR;
    for (int i = 0; i < 100; ++i) {
      const double mid = 0.5 * (lo + hi);
      (capVolume(kR, mid) < f * sphereVolume ? lo : hi) = mid;
    }
    CHECK(h == Approx(lo).margin(0.005 * kR));
  }
}

TEST_CASE("fill plane on a prolate (myopic) cavity and in a tilted direction",
          "[validation][fill]") {
  const TriangleMesh sphere = meshing_test::eyeSphere(4);
  // A prolate spheroid is the sphere stretched along z by 1.25 (a 30 mm axial length from a 24 mm
  // sphere). Volumes of polyhedra scale exactly by the determinant under a linear map, so the
  // plane across z moves by exactly the stretch factor: only bisection round-off (1e-12 of the
  // extent) separates the two.
  TriangleMesh prolate = sphere;
  for (Vec3& v : prolate.vertices) v.z() *= 1.25;
  for (double f : {0.1, 0.6, 0.9}) {
    const FillPlane round = findFillPlane(sphere, f, Vec3::UnitZ());
    const FillPlane longEye = findFillPlane(prolate, f, Vec3::UnitZ());
    CHECK(longEye.offset == Approx(1.25 * round.offset).margin(1e-12 * 0.03));
    CHECK(longEye.volumeAbove == Approx(1.25 * round.volumeAbove).epsilon(1e-9));
  }
  // On the sphere every direction is alike: a tilted gravity gives the same cap height (the
  // icosphere is not perfectly round: 5120 faces, cap volumes within ~0.2 %, heights closer).
  const FillPlane upright = findFillPlane(sphere, 0.7, Vec3::UnitY());
  const FillPlane tilted = findFillPlane(sphere, 0.7, Vec3(0.3, 0.8, -0.52).normalized());
  CHECK(tilted.offset == Approx(upright.offset).margin(0.002 * kR));
}

TEST_CASE("which side fills: light oil rises, heavy oil sinks", "[unit][fill]") {
  const TriangleMesh m = meshing_test::eyeSphere(3);
  const Vec3 gravity(0, -1, 0);  // [unit direction] upright patient: -y inferior
  VolumeSamplingOptions o;
  o.spacing = 0.001;
  // 30 % silicone oil (floats): the oil is the +u side with u = -gravity, above the plane.
  const FillPlane light = findFillPlane(m, 0.3, -gravity);
  CHECK(light.offset > 0);  // less than half: the plane is above the centre
  const PhaseSamples lightPhases = sampleFillPhases(m, light, o);
  for (const Vec3& p : lightPhases.above) CHECK(p.y() >= light.offset);
  for (const Vec3& p : lightPhases.below) CHECK(p.y() < light.offset);
  // 30 % heavy silicone oil (sinks): u = +gravity, the oil sits at the bottom.
  const FillPlane heavy = findFillPlane(m, 0.3, gravity);
  const PhaseSamples heavyPhases = sampleFillPhases(m, heavy, o);
  for (const Vec3& p : heavyPhases.above) CHECK(p.y() <= -heavy.offset);
  // Symmetric sphere: the two fills are mirror images, same particle counts as each other.
  CHECK(heavy.offset == Approx(light.offset).epsilon(1e-9));
  CHECK(heavyPhases.above.size() == lightPhases.above.size());
  // Each phase's share of particles follows the fill fraction; a phase's lattice count has the
  // same O(rho^{3/2}) boundary error as the whole, about 5 % of the oil count at d = 1 mm.
  const double share = static_cast<double>(lightPhases.above.size()) /
                       static_cast<double>(lightPhases.above.size() + lightPhases.below.size());
  CHECK(share == Approx(0.3).epsilon(0.1));
}

TEST_CASE("fill plane rejects bad fractions and directions", "[unit][fill]") {
  const TriangleMesh m = meshing_test::eyeSphere(1);
  CHECK_THROWS_AS(findFillPlane(m, 1.2, Vec3::UnitZ()), MeshError);
  CHECK_THROWS_WITH(findFillPlane(m, -0.1, Vec3::UnitZ()), Catch::Contains("outside [0, 1]"));
  CHECK_THROWS_WITH(findFillPlane(m, 0.5, Vec3::Zero()), Catch::Contains("direction is zero"));
  const FillPlane empty = findFillPlane(m, 0.0, Vec3::UnitZ());
  CHECK(empty.volumeAbove == Approx(0).margin(1e-15));
  const FillPlane full = findFillPlane(m, 1.0, Vec3::UnitZ());
  CHECK(full.volumeBelow == Approx(0).margin(1e-15));
}
