// Bad input never hangs, crashes or passes as a result: a table of hostile but realistic inputs
// to the `tamponade` binary (protocol syntax, types, units, ranges, missing keys, meshes, memory,
// command-line values, folders, checkpoints). Every case asserts the exit code, that the message
// names the file and the place (line:column of the key, or the mesh file) and the cause, and that
// nothing that looks like a result (report.html, summary.json, frames.h5) is left behind.
// Cases stop before any simulation step except the checkpoint ones, which run 16 steps of a
// coarse eye (d = 1.5 mm, ~1000 fluid particles).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "meshing/make_icosphere.h"
#include "meshing/mesh_writer.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"

namespace fs = std::filesystem;
using tamponade_test::readText;
using tamponade_test::runTamponade;

namespace {

// The protocol every case edits: lines are numbered so that cases can name the place.
std::string protocolWith(const std::string& eye, const std::string& schedule,
                         const std::string& rest = "") {
  return "format_version = 1\n"                          // 1
         "title = \"Bad input\"\n"                       // 2
         "[eye]\n" +                                     // 3
         eye +                                           // 4.. (two lines)
         "[tamponade]\nagent = \"silicone_oil_1000\"\n"  // 6, 7
         "fill = \"90 %\"\n"                             // 8
         "[schedule]\n[[schedule.postures]]\n" +
         schedule +  // 9, 10, 11..
         "[accuracy]\npreset = \"draft\"\nparticle_spacing = \"1.5 mm\"\n" + rest;
}

const std::string kEmmetropic = "kind = \"emmetropic\"\nside = \"OD\"\n";
const std::string kSupine = "name = \"supine\"\nduration = \"4 ms\"\n";

std::string meshEye(const std::string& file) {
  return "kind = \"mesh\"\nside = \"OD\"\nmesh = \"" + file + "\"\nmesh_units = \"mm\"\n";
}

// `text` with the first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Files that look like the output of a run.
std::vector<std::string> resultFilesIn(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry :
       fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied)) {
    const std::string name = entry.path().filename().string();
    if (name == "report.html" || name == "summary.json" || name == "coverage.csv" ||
        name == "frames.h5" || name == "frames.xmf")
      found.push_back(entry.path().string());
  }
  return found;
}

struct Case {
  std::string name;
  std::string protocol;  // written to p.toml ("" = none)
  std::string arguments;
  int exitCode;
  std::vector<std::string> mustSay;  // each must appear in the output
};

// Two overlapping spheres of equal size (each closed): no way to tell which is the cavity.
meshing::TriangleMesh twoSpheres() {
  meshing::TriangleMesh a = meshing::makeIcosphere(12.0, 2);
  const meshing::TriangleMesh b = meshing::makeIcosphere(12.0, 2, meshing::Vec3(6.0, 0, 0));
  const int base = static_cast<int>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (meshing::Triangle t : b.faces) {
    for (int& v : t) v += base;
    a.faces.push_back(t);
  }
  return a;
}

}  // namespace

TEST_CASE("bad input: refused with exit 2, file:line:column or file, the cause, no result",
          "[unit][cli][bad-input]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_bad_input_test");
  const std::filesystem::path& dir = scratch.path();
  fs::create_directories(dir / "meshdir");
  // Meshes: a directory, a device, a link loop, a PLY without end_header, a sphere 1 unit across
  // (1 mm, or 1 m), two overlapping spheres, a surface of zero-area faces.
  fs::create_symlink("loop_b.stl", dir / "loop_a.stl");
  fs::create_symlink("loop_a.stl", dir / "loop_b.stl");
  writeText(dir / "no_end_header.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  meshing::writeMesh(meshing::makeIcosphere(0.5, 2), (dir / "one_mm.stl").string());
  meshing::writeMesh(twoSpheres(), (dir / "two_spheres.stl").string());
  // A closed tetrahedron whose four corners lie on one line: every face has zero area.
  writeText(dir / "line.obj",
            "v 0 0 0\nv 10 0 0\nv 20 0 0\nv 30 0 0\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  writeText(dir / "a_file", "not a folder\n");

  const std::vector<Case> cases = {
      // Syntax, types, units, ranges, missing keys.
      {"unterminated string",
       protocolWith(kEmmetropic, "name = \"supine\nduration = \"4 ms\"\n"),
       "validate p.toml",
       2,
       {"p.toml:11:"}},
      {"string where a boolean is expected",
       protocolWith(kEmmetropic, kSupine, "[outputs]\nreport = \"yes\"\n"),
       "validate p.toml",
       2,
       {"p.toml:17:10:", "outputs.report", "must be"}},
      {"duration without a unit",
       protocolWith(kEmmetropic, "name = \"supine\"\nduration = 4\n"),
       "validate p.toml",
       2,
       {"p.toml:12:12:", "duration"}},
      {"a mass as a duration",
       protocolWith(kEmmetropic, "name = \"supine\"\nduration = \"4 kg\"\n"),
       "validate p.toml",
       2,
       {"p.toml:12:12:", "duration", "kg"}},
      {"missing tamponade",
       "format_version = 1\n[eye]\n" + kEmmetropic + "[schedule]\n[[schedule.postures]]\n" +
           kSupine,
       "validate p.toml",
       2,
       {"p.toml:", "missing required key", "tamponade"}},
      // Durations, intervals and windows: a floor and a ceiling (the run never ended below the
      // floor, and 1e308 s planned inf steps).
      {"frame interval 1e-20 s",
       protocolWith(kEmmetropic, kSupine, "[outputs]\nframe_interval = \"1e-20 s\"\n"),
       "validate p.toml",
       2,
       {"p.toml:17:18:", "outputs.frame_interval", "outside the allowed"}},
      {"steady window 1e-20 s",
       replaced(protocolWith(kEmmetropic, "name = \"supine\"\nduration = \"until steady\"\n"),
                "[schedule]\n", "[schedule]\nsteady_window = \"1e-20 s\"\n"),
       "validate p.toml",
       2,
       {"p.toml:10:17:", "schedule.steady_window", "outside the allowed"}},
      {"duration 1e308 s",
       protocolWith(kEmmetropic, "name = \"supine\"\nduration = \"1e308 s\"\n"),
       "validate p.toml",
       2,
       {"p.toml:12:12:", "duration", "outside the allowed"}},
      {"duration 1e-9 s",
       protocolWith(kEmmetropic, "name = \"supine\"\nduration = \"1e-9 s\"\n"),
       "validate p.toml",
       2,
       {"p.toml:12:12:", "duration", "outside the allowed"}},
      {"NaN gravity direction",
       protocolWith(kEmmetropic, "gravity_direction = [nan, 0, 1]\nduration = \"4 ms\"\n"),
       "validate p.toml",
       2,
       {"p.toml:11:21:", "gravity_direction", "NaN"}},
      // Mesh paths that are no mesh file.
      {"mesh path is a directory",
       protocolWith(meshEye("meshdir"), kSupine),
       "validate p.toml",
       2,
       {"p.toml:6:8:", "is a directory"}},
      {"mesh path is a device",
       protocolWith(meshEye("/dev/zero"), kSupine),
       "validate p.toml",
       2,
       {"p.toml:6:8:", "not a regular file"}},
      {"mesh path is a link loop",
       protocolWith(meshEye("loop_a.stl"), kSupine),
       "validate p.toml",
       2,
       {"p.toml:6:8:", "cannot be opened"}},
      // What a mesh eye cannot have, found by validate (they passed it and failed at assembly).
      {"mesh eye with a break",
       protocolWith(meshEye("one_mm.stl") + "[[eye.breaks]]\nname = \"tear\"\nclock_hour = 12\n"
                                            "posterior_to_ora = \"3 mm\"\ndiameter = \"2 mm\"\n",
                    kSupine),
       "validate p.toml",
       2,
       {"p.toml:8:1:", "retinal break 'tear' on an imported mesh"}},
      {"mesh eye with an elastic sclera",
       protocolWith(meshEye("one_mm.stl") + "[eye.sclera]\nmode = \"elastic\"\n", kSupine),
       "validate p.toml",
       2,
       {"p.toml:9:8:", "elastic", "imported mesh"}},
      // Meshes assimp would loop on, and meshes that would pass as a result.
      {"PLY without end_header (mesh check)",
       "",
       "mesh check no_end_header.ply --units mm",
       2,
       {"no_end_header.ply", "end_header"}},
      {"PLY without end_header (plan)",
       protocolWith(meshEye("no_end_header.ply"), kSupine),
       "plan p.toml",
       2,
       {"p.toml:6:8:", "no_end_header.ply", "end_header"}},
      {"1 mm cavity",
       protocolWith(meshEye("one_mm.stl"), kSupine),
       "plan p.toml",
       2,
       {"p.toml:6:8:", "one_mm.stl", "implausible size"}},
      {"1 m sphere in metres without units",
       "",
       "mesh check one_mm.stl",
       2,
       {"one_mm.stl", "implausible"}},
      {"two equal overlapping spheres",
       "",
       "mesh check two_spheres.stl --units mm",
       2,
       {"two_spheres.stl", "similar size"}},
      {"two equal overlapping spheres (plan)",
       protocolWith(meshEye("two_spheres.stl"), kSupine),
       "plan p.toml",
       2,
       {"p.toml:6:8:", "similar size"}},
      {"all-degenerate mesh (mesh sample)",
       "",
       "mesh sample line.obj --units mm --spacing 1mm",
       2,
       {"line.obj", "encloses no volume"}},
      // Memory: estimated before anything is allocated.
      {"spacing beyond the memory",
       replaced(protocolWith(kEmmetropic, kSupine), "\"1.5 mm\"", "\"0.05 mm\""),
       "plan p.toml --max-memory 1GiB",
       2,
       {"p.toml:15:20:", "particle spacing 0.05 mm needs about", "particle_spacing = \""}},
      // Command-line values and folders.
      {"--stop-after-steps abc",
       protocolWith(kEmmetropic, kSupine),
       "run p.toml --stop-after-steps abc",
       2,
       {"--stop-after-steps: 'abc'"}},
      {"--max-memory without a unit",
       protocolWith(kEmmetropic, kSupine),
       "plan p.toml --max-memory 4",
       2,
       {"--max-memory: '4'", "unit"}},
      {"output folder is a file",
       protocolWith(kEmmetropic, kSupine),
       "run p.toml --out a_file",
       2,
       {"a_file", "exists and is not a folder"}},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    fs::remove(dir / "p.toml");
    if (!c.protocol.empty()) writeText(dir / "p.toml", c.protocol);
    const tamponade_test::CommandResult r = runTamponade(c.arguments, dir);
    INFO(r.output);
    CHECK(r.exitCode == c.exitCode);
    for (const std::string& text : c.mustSay) CHECK(r.output.find(text) != std::string::npos);
    CHECK(resultFilesIn(dir).empty());
  }
}

TEST_CASE(
    "bad input: a checkpoint of another protocol is refused, and a stopped run's report says so",
    "[unit][cli][bad-input]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_bad_checkpoint_test");
  const std::filesystem::path& dir = scratch.path();
  // Two protocols of the same eye and particles, different schedules: their checkpoints have the
  // same particle counts and fields, so only the protocol's hash tells them apart.
  writeText(dir / "a.toml", protocolWith(kEmmetropic, "name = \"supine\"\nduration = \"1 s\"\n"));
  writeText(dir / "b.toml", protocolWith(kEmmetropic, "name = \"upright\"\nduration = \"2 s\"\n"));
  for (const std::string run : {"a", "b"}) {
    const auto r =
        runTamponade("run " + run + ".toml --out run_" + run + " --stop-after-steps 16", dir);
    INFO(r.output);
    REQUIRE(r.exitCode == 1);  // stopped as if interrupted, with a checkpoint
    REQUIRE(fs::exists(dir / ("run_" + run) / "checkpoint.h5"));
  }

  // Resume a copy of run a whose checkpoint came from run b.
  fs::copy(dir / "run_a", dir / "run_mixed");
  fs::copy_file(dir / "run_b" / "checkpoint.h5", dir / "run_mixed" / "checkpoint.h5",
                fs::copy_options::overwrite_existing);
  {
    const auto r = runTamponade("run --resume run_mixed", dir);
    INFO(r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("run_mixed/checkpoint.h5") != std::string::npos);
    CHECK(r.output.find("belongs to another protocol") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "run_mixed" / "report.html"));
    CHECK_FALSE(fs::exists(dir / "run_mixed" / "summary.json"));
  }
  // The report of the stopped run a says in its headline that the run is incomplete.
  {
    const auto r = runTamponade("report run_a", dir);
    INFO(r.output);
    CHECK(r.exitCode == 0);
    const std::string html = readText(dir / "run_a" / "report.html");
    const std::size_t headline = html.find("<h1>");
    REQUIRE(headline != std::string::npos);
    CHECK(html.substr(headline, html.find("</h1>") - headline).find("(incomplete run)") !=
          std::string::npos);
    CHECK(html.find("of the schedule's 1 s") != std::string::npos);
    CHECK_FALSE(
        nlohmann::json::parse(readText(dir / "run_a" / "summary.json")).at("complete").get<bool>());
  }
}
