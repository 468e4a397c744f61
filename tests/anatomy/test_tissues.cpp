// Sclera shell thickness and the orbital fat volume.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "anatomy/anatomy_error.h"
#include "anatomy/material_library.h"
#include "anatomy/mesh_properties.h"
#include "anatomy/orbital_fat.h"
#include "anatomy/sclera_shell.h"
#include "anatomy/vitreous_cavity.h"
#include "sphere_eye.h"

using namespace anatomy;

namespace {
constexpr double kMm = 1e-3;
constexpr double R = test::kSphereRadius;
}  // namespace

TEST_CASE("sclera thickness follows Vurgese 2012 at the landmarks", "[unit][tissue]") {
  const CavityShape sphere(test::sphereGeometry());
  const Eye eye(Laterality::kRight, sphere);
  const ScleraShell sclera(eye);
  const double rim = sphere.rimTheta();
  const double ora = eye.landmarks().oraFromLimbus, toRim = eye.landmarks().limbusToRim;
  const double meridian = 0.4;
  // Wall distance on the sphere: limbusToRim + R (rimTheta - theta).
  const auto thetaAt = [&](double distance) { return rim - (distance - toRim) / R; };
  CHECK(sclera.thicknessAt(WallCoordinate{0.0, meridian}) == Approx(0.94 * kMm).margin(1e-9));
  CHECK(sclera.thicknessAt(WallCoordinate{std::numbers::pi / 2, meridian}) ==
        Approx(0.42 * kMm).margin(1e-9));
  CHECK(sclera.thicknessAt(WallCoordinate{std::numbers::pi / 4, meridian}) ==
        Approx(0.65 * kMm).margin(1e-9));  // midway equator-pole on a sphere
  // Tolerance 1e-9 m on thickness: the distance table is good to < 1e-7 m on a sphere and the
  // profile's slope is < 0.03 mm/mm.
  CHECK(sclera.thicknessAt(WallCoordinate{thetaAt(ora), meridian}) ==
        Approx(0.43 * kMm).margin(1e-9));
  // At the rim (4.5 mm behind the limbus): linear between limbus 0.50 and ora 0.43 mm.
  CHECK(sclera.thicknessAt(WallCoordinate{rim, meridian}) ==
        Approx((0.50 - 0.07 * 4.5 / 6.2) * kMm).margin(1e-9));
  // The cap (lens/IOL) has no sclera.
  CHECK(sclera.thicknessAt(sphere.capPoint(0.3, 1.0)) == 0.0);
  const auto mesh = sphere.triangulate(32);
  const auto thickness = sclera.vertexThickness(mesh);
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const bool cap = sphere.closestPart(mesh.vertices[i]) == CavityPart::kCap;
    CHECK((cap ? thickness[i] == 0.0 : (thickness[i] >= 0.42 * kMm && thickness[i] <= 0.94 * kMm)));
  }
  CHECK(sclera.materialName() == "sclera");
  ScleraThicknessProfile bad;
  bad.equator = 3.0 * kMm;
  CHECK_THROWS_WITH(ScleraShell(eye, bad), Catch::Contains("sclera thickness"));
}

TEST_CASE("orbital fat on a sphere: closed cup with the spherical-sector volume",
          "[unit][tissue]") {
  const CavityShape sphere(test::sphereGeometry());
  const Eye eye(Laterality::kRight, sphere);
  ScleraThicknessProfile uniform;  // constant 0.5 mm: the cup is a sector of a spherical shell
  uniform.limbus = uniform.oraSerrata = uniform.equator = uniform.midEquatorPole =
      uniform.posteriorPole = 0.5 * kMm;
  const ScleraShell sclera(eye, uniform);
  OrbitalFatParameters p;
  p.thickness = 6.0 * kMm;
  p.polarExtent = std::numbers::pi / 3.0;
  p.resolution = 128;
  const OrbitalFat fat = makeOrbitalFat(sclera, p);
  const MeshProperties m = measureMesh(fat.mesh);
  CHECK(m.isWatertight());
  CHECK(m.signedVolume > 0.0);
  CHECK(fat.materialName == "orbital_fat");
  // V = (2 pi / 3)(R2^3 - R1^3)(1 - cos alpha), R1 = R + 0.5 mm, R2 = R1 + 6 mm.
  const double r1 = R + 0.5 * kMm, r2 = r1 + 6.0 * kMm;
  const double exact = 2.0 * std::numbers::pi / 3.0 * (r2 * r2 * r2 - r1 * r1 * r1) * 0.5;
  // Inscribed tessellation: deviation <= h^2 / (2 r1) over the mesh area (h the longest edge,
  // ~ 2 pi r2 / 128 = 0.9 mm here, bounded by 1.2 mm): 0.06 mm x area.
  const double h = 1.2 * kMm;
  CHECK(std::abs(m.signedVolume - exact) <= h * h / (2.0 * r1) * m.area);
  CHECK(std::abs(m.signedVolume - exact) < 0.02 * exact);
  // The fat touches the sclera's outer surface and never enters the globe.
  const Vec3 centre = sphere.posteriorPole() + Vec3(0, 0, R);
  for (const auto& v : fat.mesh.vertices) CHECK((v - centre).norm() >= r1 - 1e-12);
}

TEST_CASE("orbital fat behind a staphyloma is closed and outside the sclera", "[unit][tissue]") {
  const CavityShape shape(staphylomaGeometry({}));
  const Eye eye(Laterality::kLeft, shape);
  const ScleraShell sclera(eye);
  const OrbitalFat fat = makeOrbitalFat(sclera, {});
  const MeshProperties m = measureMesh(fat.mesh);
  CHECK(m.isWatertight());
  CHECK(m.signedVolume > 0.0);
  // Every fat vertex lies outside the cavity by at least the local sclera thickness (1 nm slack
  // for rounding): the vertex is wall + t n and the wall's nearest point is its own base point.
  for (const auto& v : fat.mesh.vertices) {
    const WallCoordinate w = shape.closestWallCoordinate(v);
    CHECK((v - shape.wallPoint(w)).norm() >= sclera.thicknessAt(w) - 1e-9);
  }
  OrbitalFatParameters bad;
  bad.thickness = 0.0;
  CHECK_THROWS_WITH(makeOrbitalFat(sclera, bad), Catch::Contains("orbital fat thickness"));
}

TEST_CASE("tissue geometries name materials of the library", "[unit][tissue]") {
  const CavityShape sphere(test::sphereGeometry());
  const Eye eye(Laterality::kRight, sphere);
  const ScleraShell sclera(eye);
  const MaterialLibrary& library = MaterialLibrary::builtin();
  const MaterialRecord& scleraMaterial = library.find(sclera.materialName());
  CHECK(scleraMaterial.kind == MaterialKind::kTissue);
  CHECK(scleraMaterial.youngsModulus.has_value());
  OrbitalFatParameters p;
  p.resolution = 16;
  const MaterialRecord& fatMaterial = library.find(makeOrbitalFat(sclera, p).materialName);
  CHECK(fatMaterial.kind == MaterialKind::kTissue);
  CHECK(fatMaterial.poissonRatio.has_value());
}
