// `tamponade mesh check|sample` end to end: the bad-mesh table through the real executable, for
// its exit codes (0 ok/repaired, 2 refused or bad input) and messages.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "meshing/mesh_writer.h"
#include "test_meshes.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"

using namespace meshing;

using tamponade_test::runTamponade;

TEST_CASE("mesh check: exit codes and messages for the bad-mesh table", "[unit][cli]") {
  const tamponade_test::ScratchDirectory dir("tamponade-meshing-cli");
  const TriangleMesh sphere = meshing_test::eyeSphere(3);  // [m]
  writeMesh(sphere, dir.file("good.stl"), 1000.0);
  TriangleMesh inverted = sphere;
  for (Triangle& f : inverted.faces) std::swap(f[1], f[2]);
  writeMesh(inverted, dir.file("inverted.obj"), 1000.0);
  TriangleMesh open = sphere;
  open.faces.resize(open.faces.size() - 40);
  writeMesh(open, dir.file("open.ply"), 1000.0);
  TriangleMesh crossing = sphere;
  crossing.vertices[0] *= -1.5;
  writeMesh(crossing, dir.file("crossing.stl"), 1000.0);
  TriangleMesh two = sphere;
  const TriangleMesh bubble = makeIcosphere(0.002, 2, Vec3(0.03, 0, 0));
  const int base = static_cast<int>(two.vertices.size());
  two.vertices.insert(two.vertices.end(), bubble.vertices.begin(), bubble.vertices.end());
  for (Triangle f : bubble.faces) two.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  writeMesh(two, dir.file("two.obj"), 1000.0);
  meshing_test::writeText(dir.file("empty.stl"), "");
  meshing_test::writeText(dir.file("garbage.stl"), std::string(300, '\x7f') + "not an stl");
  meshing_test::writeText(
      dir.file("nan.obj"),
      "v 0 0 0\nv 10 0 0\nv 0 nan 0\nv 0 0 10\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  writeMesh(sphere, dir.file("eye_in_m.stl"), 1.0);

  struct Case {
    std::string arguments;
    int code;
    std::string message;
  };
  const Case cases[] = {
      {"good.stl --units mm", 0, "status:    ok"},
      {"good.stl", 0, "assumed mm"},
      {"inverted.obj --units mm", 0, "reversed all 1280 faces"},
      {"two.obj --units mm", 0, "kept the largest of 2 connected components"},
      {"open.ply --units mm", 2, "open surface: a hole with"},
      {"crossing.stl --units mm", 2, "self-intersecting surface"},
      {"empty.stl", 2, "file is empty"},
      {"garbage.stl", 2, "cannot read the file as a mesh"},
      {"nan.obj --units mm", 2, "NaN or infinite"},
      {"eye_in_m.stl --units mm", 2, "probably in m: declare --units m"},
      {"good.stl --units inch", 2, "--units: 'inch' must be mm or m"},
      {"", 2, "FILE is required"},
  };
  for (const Case& c : cases) {
    std::string arguments = c.arguments;
    if (!arguments.empty()) arguments = dir.file("") + arguments;
    const auto r = runTamponade("mesh check " + arguments);
    INFO("mesh check " << arguments << "\n" << r.output);
    CHECK(r.exitCode == c.code);
    CHECK_THAT(r.output, Catch::Contains(c.message));
  }
  const auto report = runTamponade("mesh check " + dir.file("good.stl") + " --units mm");
  CHECK_THAT(report.output, Catch::Contains("area:") && Catch::Contains("volume:") &&
                                Catch::Contains("size:      24 x") &&
                                Catch::Contains("units:     mm"));
}

TEST_CASE("mesh sample: counts, spacing statistics, PLY output and strict lengths", "[unit][cli]") {
  const tamponade_test::ScratchDirectory dir("tamponade-meshing-cli-sample");
  writeMesh(meshing_test::eyeSphere(3), dir.file("eye.stl"), 1000.0);
  const std::string eye = dir.file("eye.stl");
  const auto ok =
      runTamponade("mesh sample " + eye + " --units mm --spacing 1mm --out " + dir.file("p.ply"));
  INFO(ok.output);
  CHECK(ok.exitCode == 0);
  CHECK_THAT(ok.output, Catch::Contains("wall:") && Catch::Contains("interior:") &&
                            Catch::Contains("nearest neighbour min") && Catch::Contains("wrote:"));
  std::ifstream ply(dir.file("p.ply"));
  std::string magic;
  ply >> magic;
  CHECK(magic == "ply");
  const struct {
    std::string spacing;
    std::string message;
  } bad[] = {{"0.4", "is not a length with a unit"},  {"0.4 inch", "is not a length with a unit"},
             {"-1mm", "is not a length with a unit"}, {"0mm", "must be a positive length"},
             {"1mmm", "is not a length with a unit"}, {"abc", "is not a length with a unit"}};
  for (const auto& b : bad) {
    const auto r = runTamponade("mesh sample " + eye + " --spacing '" + b.spacing + "'");
    INFO(b.spacing << "\n" << r.output);
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.output, Catch::Contains(b.message));
  }
  CHECK(runTamponade("mesh sample " + eye).exitCode == 2);  // --spacing required
  CHECK(runTamponade("mesh sample " + eye + " --spacing 1mm --out " + dir.file("nodir/p.ply"))
            .exitCode == 1);
  CHECK(runTamponade("mesh sample --help").exitCode == 0);
  CHECK(runTamponade("mesh check --help").exitCode == 0);
  CHECK(runTamponade("mesh frobnicate x").exitCode == 2);
}
