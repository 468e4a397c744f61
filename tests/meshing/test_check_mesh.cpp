// The table of bad meshes built in memory: each is repaired with the right repair listed, or
// refused with the right problem and place.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <regex>

#include "meshing/cgal_checks.h"
#include "meshing/check_mesh.h"
#include "meshing/mesh_error.h"
#include "test_meshes.h"

using namespace meshing;

namespace {

constexpr double kR = 0.012;  // [m] sphere radius of the test cavity

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

TriangleMesh withoutFaces(TriangleMesh m, double zAbove) {
  std::vector<Triangle> kept;
  for (const Triangle& f : m.faces) {
    const double z =
        (m.vertices[static_cast<size_t>(f[0])].z() + m.vertices[static_cast<size_t>(f[1])].z() +
         m.vertices[static_cast<size_t>(f[2])].z()) /
        3;
    if (z <= zAbove) kept.push_back(f);
  }
  m.faces = kept;
  return m;
}

}  // namespace

TEST_CASE("a clean sphere passes unchanged with its measures", "[unit][check]") {
  const TriangleMesh sphere = meshing_test::eyeSphere(3);
  const MeshReport r = checkMesh(sphere);
  CHECK(r.isUsable());
  CHECK(r.repairs.empty());
  CHECK(r.mesh.faces.size() == sphere.faces.size());
  // The inscribed polyhedron is smaller than the sphere: 0.86 % in volume, 0.47 % in area at
  // 1280 faces (chordal error); 1.5 % bounds both.
  CHECK(r.measures.signedVolume == Approx(4.0 / 3.0 * M_PI * kR * kR * kR).epsilon(0.015));
  CHECK(r.measures.area == Approx(4 * M_PI * kR * kR).epsilon(0.015));
  CHECK(r.measures.size() ==
        Approx(2 * kR).epsilon(1e-9));  // icosahedron vertices on the axes' planes
}

TEST_CASE("bad meshes: repaired with the repair listed, or refused saying what and where",
          "[unit][check]") {
  const TriangleMesh sphere = meshing_test::eyeSphere(3);
  const double volume = checkMesh(sphere).measures.signedVolume;

  SECTION("inverted: all faces reversed back, volume positive") {
    TriangleMesh m = sphere;
    for (Triangle& f : m.faces) std::swap(f[1], f[2]);
    const MeshReport r = checkMesh(m);
    REQUIRE(r.isUsable());
    CHECK_THAT(joined(r.repairs), Catch::Contains("reversed all 1280 faces"));
    CHECK(r.measures.signedVolume == Approx(volume).epsilon(1e-12));
  }
  SECTION("a few faces flipped: re-oriented and listed") {
    TriangleMesh m = sphere;
    for (int f : {5, 77, 300})
      std::swap(m.faces[static_cast<size_t>(f)][1], m.faces[static_cast<size_t>(f)][2]);
    const MeshReport r = checkMesh(m);
    REQUIRE(r.isUsable());
    CHECK_THAT(joined(r.repairs),
               Catch::Contains("re-oriented 3 faces") && Catch::Contains("5, 77, 300"));
    CHECK(r.measures.signedVolume == Approx(volume).epsilon(1e-12));
  }
  SECTION("duplicate vertices (a triangle soup) are joined") {
    TriangleMesh m;
    for (const Triangle& f : sphere.faces) {
      const int base = static_cast<int>(m.vertices.size());
      for (int v : f) m.vertices.push_back(sphere.vertices[static_cast<size_t>(v)]);
      m.faces.push_back({base, base + 1, base + 2});
    }
    const MeshReport r = checkMesh(m);
    REQUIRE(r.isUsable());
    CHECK_THAT(joined(r.repairs),
               Catch::Contains("removed 3198 duplicate"));  // 3840 corners, 642 vertices
    CHECK(r.mesh.vertices.size() == 642);
  }
  SECTION("small hole: filled, volume nearly unchanged") {
    TriangleMesh m = sphere;
    m.faces.erase(m.faces.begin() + 100);
    const MeshReport r = checkMesh(m);
    REQUIRE(r.isUsable());
    CHECK_THAT(joined(r.repairs), Catch::Contains("filled a hole of 3 edges"));
    // The patch is a flat fan over the removed face: the volume differs by a sliver far below
    // one face's share of the volume (1/1280).
    CHECK(r.measures.signedVolume == Approx(volume).epsilon(1e-4));
  }
  SECTION("open (cap cut off): refused, naming the hole size and where it is") {
    const MeshReport r = checkMesh(withoutFaces(sphere, 0.8 * kR));
    REQUIRE_FALSE(r.isUsable());
    CHECK_THAT(joined(r.refusals), Catch::Contains("open surface: a hole with") &&
                                       Catch::Contains("boundary edges around (") &&
                                       Catch::Contains("bordering faces"));
  }
  SECTION("self-intersecting (a vertex pushed through the far side): refused with faces") {
    TriangleMesh m = sphere;
    m.vertices[0] *= -1.5;
    const MeshReport r = checkMesh(m);
    REQUIRE_FALSE(r.isUsable());
    const std::string refusal = joined(r.refusals);
    CHECK_THAT(refusal, Catch::Contains("self-intersecting surface") &&
                            Catch::Contains("pairs of faces cross, e.g. face "));
    // WHERE: one of the two faces named first is a spike face around the moved vertex 0.
    std::smatch match;
    REQUIRE(
        std::regex_search(refusal, match, std::regex("e\\.g\\. face ([0-9]+) and face ([0-9]+)")));
    const auto touchesVertex0 = [&](const std::string& index) {
      const Triangle& f = sphere.faces[std::stoul(index)];
      return f[0] == 0 || f[1] == 0 || f[2] == 0;
    };
    CHECK((touchesVertex0(match[1].str()) || touchesVertex0(match[2].str())));
  }
  SECTION("two components: the largest kept and the other named; refused on request") {
    TriangleMesh m = sphere;
    const TriangleMesh bubble = makeIcosphere(0.002, 2, Vec3(0.03, 0, 0));
    const int base = static_cast<int>(m.vertices.size());
    m.vertices.insert(m.vertices.end(), bubble.vertices.begin(), bubble.vertices.end());
    for (Triangle f : bubble.faces) m.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
    const MeshReport r = checkMesh(m);
    REQUIRE(r.isUsable());
    CHECK_THAT(joined(r.repairs),
               Catch::Contains("kept the largest of 2 connected components (1280 faces)") &&
                   Catch::Contains("320 faces near (0.03"));
    CHECK(r.measures.signedVolume == Approx(volume).epsilon(1e-12));
    MeshCheckOptions strict;
    strict.keepLargestComponent = false;
    const MeshReport refused = checkMesh(m, strict);
    CHECK_FALSE(refused.isUsable());
    CHECK_THAT(joined(refused.refusals), Catch::Contains("2 connected components"));
  }
  SECTION("degenerate faces: repeated-vertex face dropped, zero-area sliver collapsed") {
    // On a cube (exact coordinates, so the midpoint is exactly collinear): split edge (0, 2) of
    // face 0 = (0, 2, 1) at its midpoint p on one side only and close the T-junction with the
    // zero-area sliver (0, 2, p): closed, manifold, one degenerate face.
    const double L = 0.01;  // [m]
    TriangleMesh m = meshing_test::makeCube(L);
    const Triangle f0 = m.faces[0];
    const int p = static_cast<int>(m.vertices.size());
    m.vertices.emplace_back(0, 0.5 * L, 0);
    m.faces[0] = {f0[0], p, f0[2]};
    m.faces.push_back({p, f0[1], f0[2]});      // face 12
    m.faces.push_back({f0[0], f0[1], p});      // face 13: the sliver
    m.faces.push_back({f0[2], f0[2], f0[1]});  // face 14: repeats a vertex
    const MeshReport r = checkMesh(m);
    REQUIRE(r.isUsable());
    const std::string repairs = joined(r.repairs);
    CHECK_THAT(repairs, Catch::Contains("degenerate faces that repeat a vertex (faces 14)"));
    CHECK_THAT(repairs, Catch::Contains(
                            "removed 1 degenerate (zero-area) faces by edge collapses (faces 13)"));
    CHECK(detail::findDegenerateFaces(r.mesh).empty());
    CHECK(r.measures.signedVolume == Approx(L * L * L).epsilon(1e-12));
  }
  SECTION("non-manifold edge: refused with the faces and the edge's midpoint") {
    TriangleMesh m = sphere;
    m.vertices.emplace_back(0.05, 0.05, 0.05);
    m.faces.push_back({m.faces[10][0], m.faces[10][1], static_cast<int>(m.vertices.size() - 1)});
    const MeshReport r = checkMesh(m);
    REQUIRE_FALSE(r.isUsable());
    CHECK_THAT(joined(r.refusals), Catch::Contains("non-manifold edge shared by 3 faces") &&
                                       Catch::Contains("1280") && Catch::Contains(" at ("));
  }
  SECTION("NaN coordinates and broken indices throw MeshError") {
    TriangleMesh m = sphere;
    m.vertices[7].y() = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_MATCHES(
        checkMesh(m), MeshError,
        Catch::Matchers::Message(
            "mesh: vertex 7 has a NaN or infinite coordinate (repair or re-export the mesh)"));
    TriangleMesh broken = sphere;
    broken.faces[3][1] = 9999;
    CHECK_THROWS_WITH(checkMesh(broken), Catch::Contains("face 3 refers to vertex 9999"));
    CHECK_THROWS_WITH(checkMesh(TriangleMesh{}), Catch::Contains("has no faces"));
  }
  SECTION("requireUsableMesh throws with every refusal") {
    CHECK_THROWS_WITH(requireUsableMesh(withoutFaces(sphere, 0.8 * kR), "cut.stl"),
                      Catch::StartsWith("cut.stl: mesh refused: open surface"));
  }
}
