// `tamponade mesh check|sample`: thin wrapper over meshing/. Prints lengths in mm (clinical units
// at the edge); exit codes: 0 ok or repaired, 1 run failure (e.g. cannot write the output),
// 2 bad input (unreadable or refused mesh, bad option).
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <regex>
#include <string>

#include "meshing/check_mesh.h"
#include "meshing/import_mesh.h"
#include "meshing/measure_spacing.h"
#include "meshing/mesh_error.h"
#include "meshing/sample_surface.h"
#include "meshing/sample_volume.h"
#include "meshing/write_point_cloud.h"
#include "tools/cli.h"
#include "tools/cli_values.h"

namespace tools {
Subcommand addMeshGenerateCommand(CLI::App& mesh);  // tools/cmd_mesh_generate.cpp
namespace {

constexpr const char* kMeshUsage =
    "usage: tamponade mesh check FILE [--units mm|m] [--max-hole-edges N]\n"
    "       tamponade mesh generate --type emmetropic|myopic|staphyloma --out FILE  (see --help)\n"
    "       tamponade mesh sample FILE --spacing LENGTH [--units mm|m] [--out points.ply]\n";

constexpr const char* kCheckDescription =
    "Reads a mesh (STL, OBJ, PLY, OFF, ...), reports what is wrong and what was repaired,\n"
    "area, volume, size and units. Exit 0 if usable (as is or repaired), 2 if refused.\n";

constexpr const char* kSampleDescription =
    "Checks the mesh, then samples wall particles on its surface and interior particles on a\n"
    "cubic lattice (gap spacing/2 from the wall); prints counts and nearest-neighbour spacing;\n"
    "--out writes both as a PLY point cloud in metres (label 0 wall, 1 interior).\n"
    "HDF5 output comes with protocols/.\n";

// Strict "<number><unit>" with unit m, mm or um; positive and finite. A CLI11 transform: the
// text becomes the length in metres.
CLI::Validator lengthWithUnit() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        static const std::regex pattern(
            R"(^\s*((?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)\s*(mm|um|m)\s*$)");
        std::smatch match;
        if (!std::regex_match(text, match, pattern))
          return "'" + text + "' is not a length with a unit (write e.g. 0.4mm, 400um or 0.0004m)";
        const std::string unit = match[2].str();
        const double metres = std::stod(match[1].str()) * (unit == "mm"   ? 1e-3
                                                           : unit == "um" ? 1e-6
                                                                          : 1.0);
        if (!(metres > 0) || !std::isfinite(metres))
          return "'" + text + "' must be a positive length";
        char exact[40];  // %.17g: the double itself, read back unchanged
        std::snprintf(exact, sizeof exact, "%.17g", metres);
        text = exact;
        return {};
      },
      "");
}

struct MeshOptions {
  std::string file;
  std::string units;
  double spacing = 0;  // [m]
  std::string out;
  int maxHoleEdges = meshing::MeshCheckOptions{}.maxHoleEdges;
  meshing::LengthUnit lengthUnit() const {
    return units.empty() ? meshing::LengthUnit::unknown : meshing::parseLengthUnit(units);
  }
};

// FILE and --units, the options check and sample share.
void defineMeshFile(CLI::App& app, MeshOptions& o) {
  app.add_option("FILE", o.file, "the mesh: STL, OBJ, PLY, OFF, ...")->required();
  app.add_option("--units", o.units,
                 "units of the file; without it they are guessed from the size\n(with a warning)")
      ->type_name("mm|m")
      ->check(oneOf({"mm", "m"}));
}

void printReport(const meshing::ImportResult& imported, const meshing::MeshReport& report,
                 const std::string& file) {
  std::printf("file:      %s\n", file.c_str());
  std::printf("units:     %s%s\n", meshing::toString(imported.unit),
              imported.unitGuessed ? " (guessed)" : "");
  for (const auto& w : imported.warnings) std::printf("warning:   %s\n", w.c_str());
  std::printf("input:     %d vertices, %d faces\n", report.inputVertices, report.inputFaces);
  for (const auto& r : report.repairs) std::printf("repaired:  %s\n", r.c_str());  // places in mm
  for (const auto& r : report.refusals) std::printf("REFUSED:   %s\n", r.c_str());
  const auto& m = report.measures;
  const meshing::Vec3 size = m.boundsMax - m.boundsMin;  // [mm]: checked in mm
  std::printf("status:    %s\n", !report.isUsable()     ? "refused"
                                 : report.wasRepaired() ? "repaired"
                                                        : "ok");
  std::printf("area:      %.4g mm^2\n", m.area);
  if (report.isUsable())
    std::printf("volume:    %.4g mm^3 (%.4g mL)\n", m.signedVolume, m.signedVolume * 1e-3);
  std::printf("size:      %.4g x %.4g x %.4g mm (bounding box)\n", size.x(), size.y(), size.z());
}

// checkMesh() on the mesh in mm, so that the places named in its messages read in mm.
meshing::MeshReport checkInMillimetres(const meshing::TriangleMesh& metres,
                                       const meshing::MeshCheckOptions& options) {
  meshing::TriangleMesh mm = metres;
  for (meshing::Vec3& v : mm.vertices) v *= 1e3;
  meshing::MeshReport report = meshing::checkMesh(mm, options);
  return report;
}

int runCheck(const MeshOptions& o) {
  const meshing::ImportResult imported = meshing::importMesh(o.file, o.lengthUnit());
  meshing::MeshCheckOptions checkOptions;
  checkOptions.maxHoleEdges = o.maxHoleEdges;
  const meshing::MeshReport report = checkInMillimetres(imported.mesh, checkOptions);
  printReport(imported, report, o.file);
  if (!report.isUsable()) {
    std::fprintf(stderr, "tamponade mesh: %s: mesh refused: %s\n", o.file.c_str(),
                 report.refusals.front().c_str());
    return 2;
  }
  return 0;
}

int runSample(const MeshOptions& o) {
  const meshing::ImportResult imported = meshing::importMesh(o.file, o.lengthUnit());
  const meshing::MeshReport report = checkInMillimetres(imported.mesh, {});
  printReport(imported, report, o.file);
  if (!report.isUsable()) {
    std::fprintf(stderr, "tamponade mesh: %s: mesh refused: %s\n", o.file.c_str(),
                 report.refusals.front().c_str());
    return 2;
  }
  const double d = o.spacing;                  // [m]
  meshing::TriangleMesh cavity = report.mesh;  // [m] back from mm
  for (meshing::Vec3& v : cavity.vertices) v *= 1e-3;
  const double volume = report.measures.signedVolume * 1e-9;  // [m^3]
  const auto wall = meshing::sampleSurface(cavity, d);
  meshing::VolumeSamplingOptions volumeOptions;
  volumeOptions.spacing = d;
  const auto interior = meshing::sampleVolume(cavity, volumeOptions);
  // 2 d finds every nearest neighbour: lattice neighbours are d apart, and a maximal wall packing
  // (exclusion 0.9 d) leaves no point farther than 1.8 d from its nearest sample.
  const auto wallSpacing = meshing::measureSpacing(wall.points, 2 * d);
  const auto interiorSpacing = meshing::measureSpacing(interior, 2 * d);
  std::printf("spacing:   %.4g mm (interior gap %.4g mm from the wall)\n", d * 1e3, 0.5 * d * 1e3);
  std::printf("wall:      %zu particles, nearest neighbour min %.4g / mean %.4g mm\n", wall.size(),
              wallSpacing.minimum * 1e3, wallSpacing.mean * 1e3);
  std::printf(
      "interior:  %zu particles, nearest neighbour min %.4g / mean %.4g mm, N d^3 = %.4g mm^3 "
      "(%.1f %% of the volume; the d/2 wall gap holds the rest)\n",
      interior.size(), interiorSpacing.minimum * 1e3, interiorSpacing.mean * 1e3,
      static_cast<double>(interior.size()) * d * d * d * 1e9,
      100.0 * static_cast<double>(interior.size()) * d * d * d / volume);
  if (!o.out.empty()) {
    std::vector<meshing::Vec3> points = wall.points;
    points.insert(points.end(), interior.begin(), interior.end());
    std::vector<int> labels(wall.size(), 0);
    labels.resize(points.size(), 1);
    try {
      meshing::writePointCloud(o.out, points, labels);
    } catch (const meshing::MeshError& e) {
      std::fprintf(stderr, "tamponade mesh: error: %s\n", e.what());
      return o.out.ends_with(".ply") ? 1 : 2;
    }
    std::printf("wrote:     %s (%zu points, coordinates in m)\n", o.out.c_str(), points.size());
  }
  return 0;
}

// `check` and `sample`, sub-commands of `tamponade mesh`.
Subcommand addCheckCommand(CLI::App& mesh) {
  auto o = std::make_shared<MeshOptions>();
  CLI::App* check = addSubcommand(mesh, "check", "check and repair a mesh",
                                  "usage: tamponade mesh check FILE [--units mm|m] "
                                  "[--max-hole-edges N]\n",
                                  kCheckDescription);
  defineMeshFile(*check, *o);
  check->add_option("--max-hole-edges", o->maxHoleEdges, "largest hole the repair closes, in edges")
      ->type_name("N")
      ->check(wholeNumber(0, 9999))
      ->capture_default_str();
  return {check, [o] { return runCheck(*o); }};
}

Subcommand addSampleCommand(CLI::App& mesh) {
  auto o = std::make_shared<MeshOptions>();
  CLI::App* sample = addSubcommand(mesh, "sample", "sample wall and interior particles",
                                   "usage: tamponade mesh sample FILE --spacing LENGTH "
                                   "[--units mm|m] [--out points.ply]\n",
                                   kSampleDescription);
  defineMeshFile(*sample, *o);
  sample->add_option("--spacing", o->spacing, "particle spacing with a unit: 0.4mm, 400um, 0.0004m")
      ->required()
      ->type_name("LENGTH")
      ->transform(lengthWithUnit());
  sample->add_option("--out", o->out, "PLY point cloud of the samples, in metres")
      ->type_name("FILE");
  return {sample, [o] { return runSample(*o); }};
}

}  // namespace

int runMesh(Args args) {
  CLI::App app("", "tamponade mesh");
  describeCommand(app, kMeshUsage, "Checks, repairs, samples and generates eye meshes.\n");
  const Subcommand commands[] = {addCheckCommand(app), addSampleCommand(app),
                                 addMeshGenerateCommand(app)};
  if (const std::optional<int> exit = parseCommandLine(app, args)) return *exit;
  try {
    for (const Subcommand& c : commands)
      if (c.app->parsed()) return c.run();
    return usageError(app, "give a mesh command: check, sample or generate");
  } catch (const meshing::MeshError& e) {  // the input mesh or a mesh parameter is bad
    std::fprintf(stderr, "tamponade mesh: error: %s\n", e.what());
    return 2;
  }
}

}  // namespace tools
