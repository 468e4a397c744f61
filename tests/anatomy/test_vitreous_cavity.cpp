// Parametric cavities: axial length, watertightness, volume against the closed form of the
// defining surface, and parameter validation.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

#include "anatomy/anatomy_error.h"
#include "anatomy/mesh_properties.h"
#include "anatomy/vitreous_cavity.h"
#include "sphere_eye.h"

using namespace anatomy;

namespace {

constexpr double kMm = 1e-3;
constexpr double kMl = 1e-6;  // [m^3]

double longestEdge(const meshing::TriangleMesh& mesh) {
  double h = 0.0;
  for (const auto& f : mesh.faces)
    for (int k = 0; k < 3; ++k)
      h = std::max(h, (mesh.vertices[static_cast<size_t>(f[static_cast<size_t>(k)])] -
                       mesh.vertices[static_cast<size_t>(f[static_cast<size_t>((k + 1) % 3)])])
                          .norm());
  return h;
}

// Checks one generated cavity against its analytic surface.
void checkCavity(const VitreousCavity& cavity, double requestedAxialLength) {
  const MeshProperties m = measureMesh(cavity.mesh);
  INFO(cavity.type << ": " << cavity.mesh.vertices.size() << " vertices");
  // Watertight: every edge in exactly two faces with opposite orientation; outward: V > 0.
  CHECK(m.isWatertight());
  CHECK(m.boundaryEdges == 0);
  CHECK(m.misorientedEdges == 0);
  CHECK(m.signedVolume > 0.0);
  // Axial length: the pole vertex lies exactly on the analytic surface, so the mesh reproduces
  // the requested biometric length to rounding (1 nm allows for float sums of ~25 mm).
  CHECK(std::abs(cavity.shape.cornealApex().z() - m.boundsMin.z() - requestedAxialLength) < 1e-9);
  CHECK(std::abs(cavity.axialLength - requestedAxialLength) < 1e-9);
  // Volume: every vertex lies on the surface, so the surface is within
  // delta = h^2 / (2 rho_min) of the mesh (h the longest edge, rho_min the smallest radius of
  // curvature: the deviation of a smooth surface from a chord of length h); the volume between
  // them is at most delta x area.
  const double h = longestEdge(cavity.mesh);
  const double delta = h * h / (2.0 * cavity.shape.minimumCurvatureRadius());
  CHECK(std::abs(cavity.volume - cavity.analyticVolume) <= delta * cavity.area);
}

}  // namespace

TEST_CASE("emmetropic cavity: axial length, watertight, volume", "[unit][cavity]") {
  EmmetropicCavityParameters p;
  const VitreousCavity c = makeEmmetropicCavity(p);
  checkCavity(c, p.axialLength);
  // Sanity against MRI volumes (reference-data.md 4.1: 4.26 mL (Zhou 2020) to 5.41 mL (Feng
  // 2011) for emmetropes): the model lies between them.
  CHECK(c.analyticVolume > 4.26 * kMl);
  CHECK(c.analyticVolume < 5.41 * kMl);
  // Atchison's emmetropic eye is oblate (wider than long): semi-axes 10.176 < 11.456 mm.
  CHECK(c.shape.geometry().semiAxisAxial < c.shape.geometry().semiAxisHorizontal);

  p.axialLength = 25.0 * kMm;
  checkCavity(makeEmmetropicCavity(p), p.axialLength);
}

TEST_CASE("myopic cavities over 26-32 mm: prolate, growing, watertight", "[unit][cavity]") {
  double previousVolume = 0.0;
  for (double al : {26.0, 28.0, 30.0, 32.0}) {
    MyopicCavityParameters p;
    p.axialLength = al * kMm;
    const VitreousCavity c = makeMyopicCavity(p);
    checkCavity(c, p.axialLength);
    CHECK(c.analyticVolume > previousVolume);
    previousVolume = c.analyticVolume;
  }
  // At 32 mm (SR = -28 D in the Atchison fit) the axial semi-axis exceeds both transverse ones.
  MyopicCavityParameters p;
  p.axialLength = 32.0 * kMm;
  const CavityGeometry g = myopicGeometry(p);
  CHECK(g.semiAxisAxial > g.semiAxisHorizontal);
  CHECK(g.semiAxisAxial > g.semiAxisVertical);
  // The fit's radii (reference-data.md 4.3): at -10 D, (11.67, 11.85, 12.24) mm.
  p.axialLength = 23.58 * kMm + 10.0 * 0.299 * kMm;
  const CavityGeometry g10 = myopicGeometry(p);
  CHECK(refractionForAxialLength(p.axialLength) == Approx(-10.0).epsilon(1e-12));
  CHECK(g10.semiAxisAxial / kMm == Approx(11.671).margin(1e-9));
  CHECK(g10.semiAxisHorizontal / kMm == Approx(11.849).margin(1e-9));
  CHECK(g10.semiAxisVertical / kMm == Approx(12.241).margin(1e-9));
}

TEST_CASE("staphyloma cavity: depth added at the pole, volume of the bulge", "[unit][cavity]") {
  StaphylomaCavityParameters p;
  p.axialLength = 29.0 * kMm;
  p.staphylomaDepth = 2.0 * kMm;
  p.staphylomaWidth = 12.0 * kMm;
  const VitreousCavity c = makeStaphylomaCavity(p);
  checkCavity(c, p.axialLength);
  // Same eye without the staphyloma: the base myopic globe of AL - depth. The difference of the
  // analytic volumes is the bulge's closed form pi d R^2 (1/2 - 2/pi^2) (cavity_shape.h).
  MyopicCavityParameters base;
  base.axialLength = p.axialLength - p.staphylomaDepth;
  base.anterior = p.anterior;
  const VitreousCavity b = makeMyopicCavity(base);
  const double R = 0.5 * p.staphylomaWidth;
  const double pi = std::numbers::pi;
  CHECK(c.analyticVolume - b.analyticVolume ==
        Approx(pi * p.staphylomaDepth * R * R * (0.5 - 2.0 / (pi * pi))).epsilon(1e-12));
  // The bulge sits at the posterior pole: the pole lies `depth` behind the base eye's pole.
  CHECK((c.shape.cornealApex() - c.shape.posteriorPole()).norm() -
            (b.shape.cornealApex() - b.shape.posteriorPole()).norm() ==
        Approx(p.staphylomaDepth).margin(1e-12));
}

TEST_CASE("cavity volume converges at second order to the closed form", "[validation][cavity]") {
  // The mesh is an inscribed polyhedron of a smooth surface: its volume error is c h^2 + O(h^4).
  // Richardson extrapolation from N and 2N segments removes the h^2 term, so the extrapolated
  // volume must match the closed form far better than either mesh does: we require 0.01 % (the
  // raw N = 96 error is ~0.15 %), which a wrong term in the closed form (the staphyloma bulge is
  // ~1 % of the volume, the lens dent ~2 %) would fail. N = 96 and 192 are both above the
  // minimum ring count the staphyloma imposes, so every edge halves between them.
  StaphylomaCavityParameters p;
  p.resolution = 96;
  const VitreousCavity coarse = makeStaphylomaCavity(p);
  p.resolution = 192;
  const VitreousCavity fine = makeStaphylomaCavity(p);
  const double extrapolated = fine.volume + (fine.volume - coarse.volume) / 3.0;
  const double exact = fine.analyticVolume;
  INFO("coarse " << coarse.volume / kMl << " fine " << fine.volume / kMl << " extrapolated "
                 << extrapolated / kMl << " exact " << exact / kMl << " mL");
  CHECK(std::abs(extrapolated - exact) < 1e-4 * exact);
  CHECK(std::abs(fine.volume - exact) < std::abs(coarse.volume - exact));
  // Error ratio between N and 2N ~ 4 for a second-order error (3..5 allows the O(h^4) term).
  const double ratio = (coarse.volume - exact) / (fine.volume - exact);
  CHECK(ratio > 3.0);
  CHECK(ratio < 5.0);
}

TEST_CASE("spherical cavity: mesh volume matches the truncated sphere", "[unit][cavity]") {
  // Sphere R = 11 mm cut 6 mm in front of its centre with a paraboloid dent of 1 mm: the closed
  // form pi R^2 [(h + R) - (h^3 + R^3)/(3 R^2)] - pi A^2 sag / 2, A = sqrt(R^2 - h^2).
  const CavityShape shape(test::sphereGeometry(1.0e-3));
  const double R = test::kSphereRadius, h = 6.0e-3, sag = 1.0e-3;
  const double pi = std::numbers::pi;
  const double exact = pi * R * R * ((h + R) - (h * h * h + R * R * R) / (3 * R * R)) -
                       pi * (R * R - h * h) * sag / 2;
  CHECK(shape.volume() == Approx(exact).epsilon(1e-12));
  const auto mesh = shape.triangulate(256);
  const MeshProperties m = measureMesh(mesh);
  // Tessellation bound as in checkCavity.
  const double edge = longestEdge(mesh);
  CHECK(std::abs(m.signedVolume - exact) <=
        edge * edge / (2 * shape.minimumCurvatureRadius()) * m.area);
  // Centroid at the origin of the eye frame (docs/conventions.md): the mesh's volume centroid is
  // ~0.
  Vec3 moment = Vec3::Zero();
  for (const auto& f : mesh.faces) {
    const Vec3& a = mesh.vertices[static_cast<size_t>(f[0])];
    const Vec3& b = mesh.vertices[static_cast<size_t>(f[1])];
    const Vec3& c = mesh.vertices[static_cast<size_t>(f[2])];
    moment += a.dot(b.cross(c)) / 6.0 * (a + b + c) / 4.0;
  }
  // 1 um: the missing volume is a layer < delta (~5 um at N = 256) thick spread over the whole
  // wall, so it shifts the centroid by much less than delta.
  CHECK((moment / m.signedVolume).norm() < 1e-6);
}

TEST_CASE("mesh measures detect holes, flipped faces and inversion", "[unit][cavity]") {
  meshing::TriangleMesh mesh = makeEmmetropicCavity({}).mesh;
  REQUIRE(measureMesh(mesh).isWatertight());
  auto open = mesh;
  open.faces.pop_back();
  CHECK(measureMesh(open).boundaryEdges == 3);
  CHECK_FALSE(measureMesh(open).isWatertight());
  auto flipped = mesh;
  std::swap(flipped.faces[10][0], flipped.faces[10][1]);
  CHECK(measureMesh(flipped).misorientedEdges == 3);
  auto inverted = mesh;
  for (auto& f : inverted.faces) std::swap(f[0], f[1]);
  CHECK(measureMesh(inverted).isWatertight());
  CHECK(measureMesh(inverted).signedVolume == Approx(-measureMesh(mesh).signedVolume));
}

TEST_CASE("cavity parameters out of range are rejected with the parameter named",
          "[unit][cavity]") {
  MyopicCavityParameters myopic;
  myopic.axialLength = 40.0 * kMm;
  CHECK_THROWS_WITH(makeMyopicCavity(myopic),
                    Catch::Contains("myopic axial length") && Catch::Contains("out of range"));
  EmmetropicCavityParameters emmetropic;
  emmetropic.resolution = 3;
  CHECK_THROWS_WITH(makeEmmetropicCavity(emmetropic), Catch::Contains("resolution"));
  emmetropic.resolution = 64;
  emmetropic.anterior.capSag = -1.0 * kMm;
  CHECK_THROWS_AS(makeEmmetropicCavity(emmetropic), AnatomyError);
  StaphylomaCavityParameters staphyloma;
  staphyloma.staphylomaDepth = 5.0 * kMm;
  staphyloma.staphylomaWidth = 6.0 * kMm;
  CHECK_THROWS_WITH(makeStaphylomaCavity(staphyloma), Catch::Contains("folds its edge"));
  staphyloma.staphylomaDepth = 2.0 * kMm;
  staphyloma.staphylomaWidth = 30.0 * kMm;
  CHECK_THROWS_WITH(makeStaphylomaCavity(staphyloma), Catch::Contains("too wide"));
}

TEST_CASE("projection: cap, wall, and the rim settled by the normal", "[unit][cavity]") {
  const CavityShape shape(test::sphereGeometry(1.0e-3));
  CHECK(shape.project(shape.capPoint(0.5, 0.3)).part == CavityPart::kCap);
  CHECK(shape.project(shape.wallPoint({1.0, 0.3})).part == CavityPart::kWall);
  // 0.1 mm inside the cavity from a wall point: still the wall, at 0.1 mm.
  const WallCoordinate w{0.8, 2.0};
  const CavityProjection inside = shape.project(shape.wallPoint(w) - 1e-4 * shape.wallNormal(w));
  CHECK(inside.part == CavityPart::kWall);
  CHECK(inside.wallDistance == Approx(1e-4).epsilon(1e-6));
  CHECK(inside.wall.theta == Approx(w.theta).margin(1e-9));
  // A rim point belongs to both parts: the wall by default, the cap when its normal says so.
  const Vec3 rim = shape.capPoint(1.0, 0.7);
  CHECK(shape.project(rim).part == CavityPart::kWall);
  const Vec3 capNormal = shape.capNormal(1.0, 0.7);
  CHECK(shape.project(rim, &capNormal).part == CavityPart::kCap);
}
