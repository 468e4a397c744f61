// `tamponade mesh generate`: writes a parametric vitreous cavity (anatomy/vitreous_cavity.h) as a
// mesh file and prints its axial length, volume, area and watertightness. Bad options or
// parameters: exit code 2; a file that cannot be written: exit code 1.
#include <cstdio>
#include <exception>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "anatomy/anatomy_error.h"
#include "anatomy/mesh_properties.h"
#include "anatomy/vitreous_cavity.h"
#include "meshing/mesh_writer.h"
#include "tools/cli.h"
#include "tools/cli_values.h"

namespace tools {

namespace {

constexpr const char* kUsage =
    "usage: tamponade mesh generate --type emmetropic|myopic|staphyloma --out FILE.stl|.obj|.ply\n"
    "                               [--axial-length L] [--staphyloma-depth D]\n"
    "                               [--staphyloma-width W] [--lens-depth L] [--cap-sag S]\n"
    "                               [--resolution N] [--units mm|m]\n";

constexpr const char* kDescription =
    "Generates a closed, outward-oriented vitreous cavity in the eye frame (origin at the "
    "cavity's\n"
    "centroid, +z anterior, +y superior, +x toward the patient's left) and prints its axial "
    "length,\n"
    "volume, area and watertightness. Lengths need a unit: 28mm, 0.028m.\n";

// "<number>mm" or "<number>m" as a CLI11 transform: the text becomes the length in metres.
CLI::Validator length() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        size_t used = 0;
        double value = 0.0;
        try {
          value = std::stod(text, &used);
        } catch (const std::exception&) {
          return "'" + text + "' is not a length (e.g. 28mm)";
        }
        const std::string unit = text.substr(used);
        if (unit.empty()) return text + " needs a unit: write " + text + "mm or " + text + "m";
        if (unit != "mm" && unit != "m")
          return "'" + text + "': unknown unit '" + unit + "' (mm or m)";
        char exact[40];  // %.17g: the double itself, read back unchanged
        std::snprintf(exact, sizeof exact, "%.17g", unit == "mm" ? value * 1e-3 : value);
        text = exact;
        return {};
      },
      "");
}

struct GenerateOptions {
  std::string type, out, units = "mm";
  std::optional<double> axialLength, depth, width, lensDepth, capSag;  // [m]
  std::optional<int> resolution;
};

void defineGenerateOptions(CLI::App& app, GenerateOptions& o) {
  app.add_option("--type", o.type,
                 "emmetropic (Atchison 2006 eye scaled to the axial length),\n"
                 "myopic (Atchison 2005 radii vs refraction),\n"
                 "staphyloma (myopic + posterior bulge)")
      ->required()
      ->type_name("emmetropic|myopic|staphyloma")
      ->check(oneOf({"emmetropic", "myopic", "staphyloma"}));
  app.add_option("--out", o.out, "output file; the extension picks STL (binary), OBJ or PLY")
      ->required()
      ->type_name("FILE")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            const std::string extension = text.size() >= 4 ? text.substr(text.size() - 4) : "";
            if (extension == ".stl" || extension == ".obj" || extension == ".ply") return {};
            return "'" + text + "' must end in .stl, .obj or .ply";
          },
          ""));
  const std::pair<const char*, std::optional<double>*> lengths[] = {
      {"--axial-length", &o.axialLength},
      {"--staphyloma-depth", &o.depth},
      {"--staphyloma-width", &o.width},
      {"--lens-depth", &o.lensDepth},
      {"--cap-sag", &o.capSag}};
  const char* help[] = {
      "corneal apex to retina; defaults 23.58mm / 28mm / 29mm by type\n"
      "(ranges 20-26mm / 24-34mm / 24-36mm)",
      "depth of the bulge (staphyloma only, default 2mm, 0.2-6mm)",
      "base diameter of the bulge (staphyloma only, default 12mm)",
      "corneal apex to the lens/IOL posterior pole (default 7.6mm)",
      "dent of the lens/IOL cap into the cavity (default 1mm, 0 = flat)"};
  for (std::size_t k = 0; k < std::size(lengths); ++k)
    app.add_option(lengths[k].first, *lengths[k].second, help[k])
        ->type_name("LENGTH")
        ->transform(length());
  app.add_option("--resolution", o.resolution,
                 "segments around the optical axis (default 96, 8-4096)")
      ->type_name("N")
      ->check(wholeNumber(std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
  app.add_option("--units", o.units, "units of the written file")
      ->type_name("mm|m")
      ->check(oneOf({"mm", "m"}))
      ->capture_default_str();
}

int generate(const CLI::App& app, const GenerateOptions& o);

}  // namespace

Subcommand addMeshGenerateCommand(CLI::App& mesh) {
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* app = addSubcommand(mesh, "generate", "generate a parametric vitreous cavity", kUsage,
                                kDescription);
  defineGenerateOptions(*app, *o);
  return {app, [app, o] { return generate(*app, *o); }};
}

namespace {

// The cavity the options describe (the type is one of the three, checked by the parser).
anatomy::VitreousCavity makeCavity(const GenerateOptions& o) {
  anatomy::AnteriorBoundary anterior;
  if (o.lensDepth) anterior.lensPosteriorDepth = *o.lensDepth;
  if (o.capSag) anterior.capSag = *o.capSag;
  auto common = [&](auto& p) {
    if (o.axialLength) p.axialLength = *o.axialLength;
    if (o.resolution) p.resolution = *o.resolution;
    p.anterior = anterior;
  };
  if (o.type == "emmetropic") {
    anatomy::EmmetropicCavityParameters p;
    common(p);
    return anatomy::makeEmmetropicCavity(p);
  }
  if (o.type == "myopic") {
    anatomy::MyopicCavityParameters p;
    common(p);
    return anatomy::makeMyopicCavity(p);
  }
  anatomy::StaphylomaCavityParameters p;
  common(p);
  if (o.depth) p.staphylomaDepth = *o.depth;
  if (o.width) p.staphylomaWidth = *o.width;
  return anatomy::makeStaphylomaCavity(p);
}

void printCavity(const anatomy::VitreousCavity& cavity, const anatomy::MeshProperties& measures,
                 const std::string& out, double fileScale) {
  const auto& g = cavity.shape.geometry();
  std::printf("type            %s\n", cavity.type.c_str());
  std::printf(
      "axial length    %.2f mm (corneal apex to posterior pole; cavity on the axis %.2f mm)\n",
      cavity.axialLength * 1e3, cavity.axialDepth * 1e3);
  std::printf("semi-axes       %.3f x %.3f x %.3f mm (horizontal, vertical, axial)\n",
              g.semiAxisHorizontal * 1e3, g.semiAxisVertical * 1e3, g.semiAxisAxial * 1e3);
  if (g.staphylomaDepth > 0.0)
    std::printf("staphyloma      depth %.2f mm, width %.2f mm\n", g.staphylomaDepth * 1e3,
                g.staphylomaWidth * 1e3);
  std::printf("volume          %.4f mL (mesh; closed form %.4f mL)\n", cavity.volume * 1e6,
              cavity.analyticVolume * 1e6);
  std::printf("area            %.1f mm^2\n", cavity.area * 1e6);
  std::printf("mesh            %zu vertices, %zu faces\n", cavity.mesh.vertices.size(),
              cavity.mesh.faces.size());
  std::printf("watertight      %s (%zu open, %zu non-manifold, %zu misoriented edges; %s)\n",
              measures.isWatertight() ? "yes" : "NO", measures.boundaryEdges,
              measures.nonManifoldEdges, measures.misorientedEdges,
              measures.signedVolume > 0 ? "outward" : "INWARD");
  std::printf("written         %s (%s)\n", out.c_str(), fileScale == 1.0 ? "m" : "mm");
}

int generate(const CLI::App& app, const GenerateOptions& o) {
  if (o.type != "staphyloma" && (o.depth || o.width))
    return usageError(app, "--staphyloma-depth/--staphyloma-width apply only to --type staphyloma");
  const double fileScale = o.units == "m" ? 1.0 : 1e3;  // metres -> file units
  std::optional<anatomy::VitreousCavity> cavity;
  try {
    cavity = makeCavity(o);
  } catch (const anatomy::AnatomyError& e) {
    std::fprintf(stderr, "tamponade mesh generate: %s\n", e.what());
    return 2;
  }
  const anatomy::MeshProperties measures = anatomy::measureMesh(cavity->mesh);
  try {
    meshing::writeMesh(cavity->mesh, o.out, fileScale);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tamponade mesh generate: %s\n", e.what());
    return 1;
  }
  printCavity(*cavity, measures, o.out, fileScale);
  return measures.isWatertight() && measures.signedVolume > 0 ? 0 : 1;
}

}  // namespace

}  // namespace tools
