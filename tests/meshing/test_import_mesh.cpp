// Import: round trips through every writable format, unit declaration and guessing, and the
// table of unreadable files.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "meshing/check_mesh.h"
#include "meshing/import_mesh.h"
#include "meshing/load_mesh.h"
#include "meshing/mesh_error.h"
#include "meshing/mesh_measures.h"
#include "meshing/mesh_writer.h"
#include "test_meshes.h"
#include "tests/support/scratch_directory.h"

using namespace meshing;
using tamponade_test::ScratchDirectory;

TEST_CASE("import round trip keeps topology, area and volume in STL, OBJ, PLY and OFF",
          "[unit][import]") {
  const ScratchDirectory dir("tamponade-meshing-roundtrip");
  const TriangleMesh sphere = meshing_test::eyeSphere(3);  // [m]
  const MeshMeasures expected = measureMesh(sphere);
  const std::string files[] = {dir.file("eye.stl"), dir.file("eye.obj"), dir.file("eye.ply"),
                               dir.file("eye.off"), dir.file("eye_ascii.stl")};
  writeMesh(sphere, files[0], 1000.0);  // binary STL in mm
  writeMesh(sphere, files[1], 1000.0);
  writeMesh(sphere, files[2], 1000.0);
  meshing_test::writeOff(sphere, files[3], 1000.0);
  meshing_test::writeAsciiStl(sphere, files[4], 1000.0);
  for (const std::string& file : files) {
    INFO(file);
    const ImportResult r = importMesh(file, LengthUnit::millimetre);
    CHECK(!r.unitGuessed);
    CHECK(r.warnings.empty());
    // Identical vertices joined: STL repeats every corner per face (STACK.md pitfall 8).
    CHECK(r.mesh.vertices.size() == sphere.vertices.size());
    CHECK(r.mesh.faces.size() == sphere.faces.size());
    const MeshMeasures got = measureMesh(r.mesh);
    // Binary STL stores float32 (relative rounding 6e-8 per coordinate), the text formats 9-12
    // digits: area and volume agree to 1e-6 relative, far below any geometric effect.
    CHECK(got.area == Approx(expected.area).epsilon(1e-6));
    CHECK(got.signedVolume == Approx(expected.signedVolume).epsilon(1e-6));
    const MeshReport report = checkMesh(r.mesh);
    CHECK(report.isUsable());
    CHECK(report.repairs.empty());
  }
}

TEST_CASE("units: declared, guessed from size with a warning", "[unit][import]") {
  const ScratchDirectory dir("tamponade-meshing-units");
  const TriangleMesh sphere = meshing_test::eyeSphere(2);
  writeMesh(sphere, dir.file("mm.stl"), 1000.0);  // diagonal ~41 units: mm
  writeMesh(sphere, dir.file("m.obj"), 1.0);      // diagonal ~0.041 units: m
  const ImportResult mm = importMesh(dir.file("mm.stl"));
  CHECK(mm.unit == LengthUnit::millimetre);
  CHECK(mm.unitGuessed);
  REQUIRE(mm.warnings.size() == 1);
  CHECK_THAT(mm.warnings[0], Catch::Contains("assumed mm") && Catch::Contains("--units"));
  CHECK(measureMesh(mm.mesh).size() == Approx(0.024).epsilon(1e-6));
  const ImportResult m = importMesh(dir.file("m.obj"));
  CHECK(m.unit == LengthUnit::metre);
  CHECK_THAT(m.warnings.at(0), Catch::Contains("assumed m "));
  CHECK(measureMesh(m.mesh).size() == Approx(0.024).epsilon(1e-6));
  // The protocol's mesh_units also take cm and um (they passed validate and failed at assembly).
  writeMesh(sphere, dir.file("cm.obj"), 100.0);
  CHECK(measureMesh(importMesh(dir.file("cm.obj"), parseLengthUnit("cm")).mesh).size() ==
        Approx(0.024).epsilon(1e-6));
  writeMesh(sphere, dir.file("um.obj"), 1e6);
  CHECK(measureMesh(importMesh(dir.file("um.obj"), parseLengthUnit("um")).mesh).size() ==
        Approx(0.024).epsilon(1e-6));
  CHECK(parseLengthUnit("mm") == LengthUnit::millimetre);
  CHECK_THROWS_WITH(parseLengthUnit("inch"), Catch::Contains("use 'mm' or 'm'"));
}

namespace {

// Writes a binary STL of one tetrahedron (4 facets) with the given corner coordinates.
void writeBinaryStl(const std::string& path, const float corner[4][3]) {
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string bytes(80, ' ');
  const std::uint32_t n = 4;
  bytes.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& f : faces) {
    float record[12] = {};
    for (int k = 0; k < 3; ++k) std::memcpy(record + 3 + 3 * k, corner[f[k]], sizeof(float) * 3);
    bytes.append(reinterpret_cast<const char*>(record), sizeof record);
    bytes.append(2, '\0');
  }
  meshing_test::writeText(path, bytes);
}

}  // namespace

TEST_CASE("unreadable files give MeshError naming the file, the problem and the fix",
          "[unit][import]") {
  const ScratchDirectory dir("tamponade-meshing-badfiles");
  const TriangleMesh sphere = meshing_test::eyeSphere(1);
  struct Case {
    std::string name;
    std::string file;
    LengthUnit unit;
    std::string message;  // must appear in what()
  };
  meshing_test::writeText(dir.file("empty.stl"), "");
  std::string garbage;
  for (int i = 0; i < 4000; ++i) garbage.push_back(static_cast<char>((i * 7919 + 13) % 251));
  meshing_test::writeText(dir.file("garbage.stl"), garbage);
  meshing_test::writeText(dir.file("garbage.ply"), garbage);
  meshing_test::writeText(dir.file("points.xyz"), "1 2 3\n");
  meshing_test::writeText(dir.file("lines.obj"), "v 0 0 0\nv 10 0 0\nv 0 10 0\nl 1 2\nl 2 3\n");
  meshing_test::writeText(dir.file("nan.obj"),
                          "v 0 0 0\nv 10 0 0\nv 0 nan 0\nv 0 0 10\n"
                          "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float nanCorners[4][3] = {{0, 0, 0}, {20, 0, 0}, {0, 20, nan}, {0, 0, 20}};
  writeBinaryStl(dir.file("nan.stl"), nanCorners);
  writeMesh(sphere, dir.file("eye_24m.stl"), 1e6);        // a 24 mm eye written in micrometres
  writeMesh(sphere, dir.file("eye_in_m.obj"), 1.0);       // 0.024 units: metres
  writeMesh(sphere, dir.file("eye_in_mm.obj"), 1e3);      // 24 units: mm
  writeMesh(sphere, dir.file("huge.obj"), 1e5);           // 2400 units: neither mm nor m
  writeMesh(sphere, dir.file("one_m.obj"), 1.0 / 0.024);  // 1 m across, written in m
  // An ASCII PLY whose header never ends: assimp's reader loops forever on it.
  meshing_test::writeText(dir.file("no_end_header.ply"),
                          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                          "property float y\nproperty float z\n0 0 0\n1 0 0\n0 1 0\n");
  std::filesystem::create_directories(dir.file("folder.stl"));
  std::filesystem::create_symlink("loop_b.stl", dir.file("loop_a.stl"));
  std::filesystem::create_symlink("loop_a.stl", dir.file("loop_b.stl"));

  const Case cases[] = {
      {"missing", dir.file("nothing_here.stl"), LengthUnit::millimetre, "file not found"},
      {"empty", dir.file("empty.stl"), LengthUnit::millimetre, "file is empty"},
      {"garbage stl", dir.file("garbage.stl"), LengthUnit::millimetre,
       "cannot read the file as a mesh"},
      {"garbage ply", dir.file("garbage.ply"), LengthUnit::millimetre,
       "cannot read the file as a mesh"},
      {"unknown format", dir.file("points.xyz"), LengthUnit::millimetre,
       "unknown mesh format '.xyz'"},
      {"no triangles", dir.file("lines.obj"), LengthUnit::millimetre, "no triangles"},
      {"NaN in OBJ", dir.file("nan.obj"), LengthUnit::millimetre, "NaN or infinite"},
      {"NaN in binary STL", dir.file("nan.stl"), LengthUnit::millimetre, "NaN or infinite"},
      {"24 m eye (um file declared mm)", dir.file("eye_24m.stl"), LengthUnit::millimetre,
       "implausible size 24 m"},
      {"0.024 mm eye (m file declared mm)", dir.file("eye_in_m.obj"), LengthUnit::millimetre,
       "probably in m:"},
      {"24 m eye (mm file declared m)", dir.file("eye_in_mm.obj"), LengthUnit::metre,
       "probably in mm:"},
      {"cannot guess", dir.file("huge.obj"), LengthUnit::unknown, "implausible for an eye in mm"},
      {"1 m sphere, no units", dir.file("one_m.obj"), LengthUnit::unknown,
       "implausible for an eye in mm"},
      {"PLY without end_header", dir.file("no_end_header.ply"), LengthUnit::millimetre,
       "no 'end_header' line"},
      {"directory", dir.file("folder.stl"), LengthUnit::millimetre, "is a directory"},
      {"device", "/dev/zero", LengthUnit::millimetre, "not a regular file"},
      {"symbolic link loop", dir.file("loop_a.stl"), LengthUnit::millimetre, "cannot open"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    try {
      importMesh(c.file, c.unit);
      FAIL("no exception");
    } catch (const MeshError& e) {
      const std::string what = e.what();
      CHECK_THAT(what, Catch::StartsWith(c.file + ": "));
      CHECK_THAT(what, Catch::Contains(c.message));
      CHECK_THAT(what, Catch::Contains("("));  // every message carries a fix in parentheses
    }
  }
}

TEST_CASE("loadMesh: shipped test meshes load, repair or refuse", "[unit][import]") {
  // data/meshes/test (tests run in the source root, see cmake/TamponadeTests.cmake).
  const LoadedMesh good = loadMesh("data/meshes/test/sphere_r12mm.stl", LengthUnit::millimetre);
  CHECK(good.report.repairs.empty());
  CHECK(good.mesh.faces.size() == 1280);
  // Icosphere of r = 12 mm at 1280 faces: 0.86 % below the sphere's volume (chordal error).
  CHECK(good.report.measures.signedVolume ==
        Approx(4.0 / 3.0 * M_PI * 1.728e-6 * (1 - 0.0086)).epsilon(0.001));
  const LoadedMesh inverted =
      loadMesh("data/meshes/test/sphere_r12mm_inverted.obj", LengthUnit::millimetre);
  CHECK_THAT(inverted.report.repairs.at(0), Catch::Contains("reversed all 1280 faces"));
  CHECK(loadMesh("data/meshes/test/sphere_r12mm_coarse.off").unit == LengthUnit::millimetre);
  CHECK_THROWS_WITH(
      loadMesh("data/meshes/test/sphere_r12mm_open.ply", LengthUnit::millimetre),
      Catch::StartsWith("data/meshes/test/sphere_r12mm_open.ply: mesh refused: open surface"));
}

TEST_CASE("import applies nested node transforms (COLLADA)", "[unit][import]") {
  const ScratchDirectory dir("tamponade-meshing-transforms");
  // A tetrahedron with 10-unit legs under two nodes: outer scales by 2 and moves +5 in x, inner
  // moves +1 in y (before the outer scale, so +2 in the end).
  meshing_test::writeText(dir.file("tet.dae"), R"DAE(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_geometries>
    <geometry id="tet" name="tet">
      <mesh>
        <source id="tet-pos">
          <float_array id="tet-pos-array" count="12">0 0 0 10 0 0 0 10 0 0 0 10</float_array>
          <technique_common><accessor source="#tet-pos-array" count="4" stride="3">
            <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
          </accessor></technique_common>
        </source>
        <vertices id="tet-vtx"><input semantic="POSITION" source="#tet-pos"/></vertices>
        <triangles count="4"><input semantic="VERTEX" source="#tet-vtx" offset="0"/>
          <p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene">
      <node id="outer"><matrix>2 0 0 5  0 2 0 0  0 0 2 0  0 0 0 1</matrix>
        <node id="inner"><matrix>1 0 0 0  0 1 0 1  0 0 1 0  0 0 0 1</matrix>
          <instance_geometry url="#tet"/></node></node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)DAE");
  const ImportResult r = importMesh(dir.file("tet.dae"), LengthUnit::millimetre);
  const MeshMeasures m = measureMesh(r.mesh);
  // float32 coordinates in the file: 1e-9 m absolute is far below their rounding at 25 mm.
  CHECK((m.boundsMin - Vec3(0.005, 0.002, 0.0)).norm() < 1e-9);
  CHECK((m.boundsMax - Vec3(0.025, 0.022, 0.020)).norm() < 1e-9);
  CHECK(m.signedVolume == Approx(std::pow(0.020, 3) / 6).epsilon(1e-6));  // scale^3 of 1000/6 mm^3
}
