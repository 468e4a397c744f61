// `tamponade mesh generate`: writes a parametric vitreous cavity (anatomy/vitreous_cavity.h) as a
// mesh file and prints its axial length, volume, area and watertightness. Bad options or
// parameters: exit code 2; a file that cannot be written: exit code 1.
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <string_view>

#include "anatomy/anatomy_error.h"
#include "anatomy/mesh_properties.h"
#include "anatomy/vitreous_cavity.h"
#include "meshing/mesh_writer.h"
#include "tools/cli_args.h"
#include "tools/commands.h"

namespace tools {

namespace {

constexpr const char* kHelp =
    "usage: tamponade mesh generate --type emmetropic|myopic|staphyloma --out FILE.stl|.obj|.ply\n"
    "                               [--axial-length L] [--staphyloma-depth D]\n"
    "                               [--staphyloma-width W] [--lens-depth L] [--cap-sag S]\n"
    "                               [--resolution N] [--units mm|m]\n"
    "\n"
    "Generates a closed, outward-oriented vitreous cavity in the eye frame (origin at the "
    "cavity's\n"
    "centroid, +z anterior, +y superior, +x toward the patient's left) and prints its axial "
    "length,\n"
    "volume, area and watertightness. Lengths need a unit: 28mm, 0.028m.\n"
    "\n"
    "  --type              emmetropic (Atchison 2006 eye scaled to the axial length), myopic\n"
    "                      (Atchison 2005 radii vs refraction), staphyloma (myopic + posterior "
    "bulge)\n"
    "  --axial-length      corneal apex to retina; defaults 23.58mm / 28mm / 29mm by type\n"
    "                      (ranges 20-26mm / 24-34mm / 24-36mm)\n"
    "  --staphyloma-depth  depth of the bulge (staphyloma only, default 2mm, 0.2-6mm)\n"
    "  --staphyloma-width  base diameter of the bulge (staphyloma only, default 12mm)\n"
    "  --lens-depth        corneal apex to the lens/IOL posterior pole (default 7.6mm)\n"
    "  --cap-sag           dent of the lens/IOL cap into the cavity (default 1mm, 0 = flat)\n"
    "  --resolution        segments around the optical axis (default 96, 8-4096)\n"
    "  --units             units of the written file (default mm)\n"
    "  --out               output file; the extension picks STL (binary), OBJ or PLY\n";

double parseLength(std::string_view option, std::string_view text) {
  const std::string s(text);
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(s, &used);
  } catch (const std::exception&) {
    throw UsageError(std::string(option) + " '" + s + "' is not a length (e.g. 28mm)");
  }
  const std::string unit = s.substr(used);
  if (unit == "mm") return value * 1e-3;
  if (unit == "m") return value;
  if (unit.empty())
    throw UsageError(std::string(option) + " " + s + " needs a unit: write " + s + "mm or " + s +
                     "m");
  throw UsageError(std::string(option) + " '" + s + "': unknown unit '" + unit + "' (mm or m)");
}

int parseCount(std::string_view option, std::string_view text) {
  const std::string s(text);
  size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || s.empty())
    throw UsageError(std::string(option) + " '" + s + "' is not a whole number");
  return value;
}

}  // namespace

int runMeshGenerate(Args args) {
  std::string type, out;
  std::optional<double> axialLength, depth, width, lensDepth, capSag;
  std::optional<int> resolution;
  double fileScale = 1e3;  // metres -> mm
  try {
    for (size_t i = 0; i < args.size(); ++i) {
      const std::string_view option = args[i];
      if (option == "--help" || option == "-h") {
        std::fputs(kHelp, stdout);
        return 0;
      }
      if (i + 1 >= args.size()) throw UsageError(std::string(option) + " needs a value");
      const std::string_view value = args[++i];
      if (option == "--type")
        type = value;
      else if (option == "--out")
        out = value;
      else if (option == "--axial-length")
        axialLength = parseLength(option, value);
      else if (option == "--staphyloma-depth")
        depth = parseLength(option, value);
      else if (option == "--staphyloma-width")
        width = parseLength(option, value);
      else if (option == "--lens-depth")
        lensDepth = parseLength(option, value);
      else if (option == "--cap-sag")
        capSag = parseLength(option, value);
      else if (option == "--resolution")
        resolution = parseCount(option, value);
      else if (option == "--units") {
        if (value == "mm")
          fileScale = 1e3;
        else if (value == "m")
          fileScale = 1.0;
        else
          throw UsageError("--units '" + std::string(value) + "' must be mm or m");
      } else {
        throw UsageError("unknown option '" + std::string(option) + "'");
      }
    }
    if (type.empty()) throw UsageError("--type is required (emmetropic, myopic or staphyloma)");
    if (out.empty()) throw UsageError("--out FILE is required");
    const std::string extension = out.size() >= 4 ? out.substr(out.size() - 4) : "";
    if (extension != ".stl" && extension != ".obj" && extension != ".ply")
      throw UsageError("--out '" + out + "' must end in .stl, .obj or .ply");
    if (type != "staphyloma" && (depth || width))
      throw UsageError("--staphyloma-depth/--staphyloma-width apply only to --type staphyloma");
  } catch (const UsageError& e) {
    std::fprintf(stderr, "tamponade mesh generate: %s\n\n%s", e.what(), kHelp);
    return 2;
  }

  anatomy::AnteriorBoundary anterior;
  if (lensDepth) anterior.lensPosteriorDepth = *lensDepth;
  if (capSag) anterior.capSag = *capSag;
  std::optional<anatomy::VitreousCavity> cavity;
  try {
    if (type == "emmetropic") {
      anatomy::EmmetropicCavityParameters p;
      if (axialLength) p.axialLength = *axialLength;
      if (resolution) p.resolution = *resolution;
      p.anterior = anterior;
      cavity = anatomy::makeEmmetropicCavity(p);
    } else if (type == "myopic") {
      anatomy::MyopicCavityParameters p;
      if (axialLength) p.axialLength = *axialLength;
      if (resolution) p.resolution = *resolution;
      p.anterior = anterior;
      cavity = anatomy::makeMyopicCavity(p);
    } else if (type == "staphyloma") {
      anatomy::StaphylomaCavityParameters p;
      if (axialLength) p.axialLength = *axialLength;
      if (depth) p.staphylomaDepth = *depth;
      if (width) p.staphylomaWidth = *width;
      if (resolution) p.resolution = *resolution;
      p.anterior = anterior;
      cavity = anatomy::makeStaphylomaCavity(p);
    } else {
      std::fprintf(stderr,
                   "tamponade mesh generate: unknown --type '%s' (emmetropic, myopic or "
                   "staphyloma)\n",
                   type.c_str());
      return 2;
    }
  } catch (const anatomy::AnatomyError& e) {
    std::fprintf(stderr, "tamponade mesh generate: %s\n", e.what());
    return 2;
  }

  const anatomy::MeshProperties measures = anatomy::measureMesh(cavity->mesh);
  try {
    meshing::writeMesh(cavity->mesh, out, fileScale);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tamponade mesh generate: %s\n", e.what());
    return 1;
  }
  const auto& g = cavity->shape.geometry();
  std::printf("type            %s\n", cavity->type.c_str());
  std::printf(
      "axial length    %.2f mm (corneal apex to posterior pole; cavity on the axis %.2f mm)\n",
      cavity->axialLength * 1e3, cavity->axialDepth * 1e3);
  std::printf("semi-axes       %.3f x %.3f x %.3f mm (horizontal, vertical, axial)\n",
              g.semiAxisHorizontal * 1e3, g.semiAxisVertical * 1e3, g.semiAxisAxial * 1e3);
  if (g.staphylomaDepth > 0.0)
    std::printf("staphyloma      depth %.2f mm, width %.2f mm\n", g.staphylomaDepth * 1e3,
                g.staphylomaWidth * 1e3);
  std::printf("volume          %.4f mL (mesh; closed form %.4f mL)\n", cavity->volume * 1e6,
              cavity->analyticVolume * 1e6);
  std::printf("area            %.1f mm^2\n", cavity->area * 1e6);
  std::printf("mesh            %zu vertices, %zu faces\n", cavity->mesh.vertices.size(),
              cavity->mesh.faces.size());
  std::printf("watertight      %s (%zu open, %zu non-manifold, %zu misoriented edges; %s)\n",
              measures.isWatertight() ? "yes" : "NO", measures.boundaryEdges,
              measures.nonManifoldEdges, measures.misorientedEdges,
              measures.signedVolume > 0 ? "outward" : "INWARD");
  std::printf("written         %s (%s)\n", out.c_str(), fileScale == 1.0 ? "m" : "mm");
  return measures.isWatertight() && measures.signedVolume > 0 ? 0 : 1;
}

}  // namespace tools
