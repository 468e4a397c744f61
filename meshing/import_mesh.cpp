#include "meshing/import_mesh.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "meshing/mesh_error.h"
#include "meshing/mesh_measures.h"

namespace meshing {

LengthUnit parseLengthUnit(std::string_view text) {
  if (text == "mm") return LengthUnit::millimetre;
  if (text == "m") return LengthUnit::metre;
  if (text == "cm") return LengthUnit::centimetre;
  if (text == "um") return LengthUnit::micrometre;
  throw MeshError("units", "unknown length unit '" + std::string(text) + "'",
                  "use 'mm' or 'm' (or 'cm', 'um')");
}

const char* toString(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::millimetre: return "mm";
    case LengthUnit::metre: return "m";
    case LengthUnit::centimetre: return "cm";
    case LengthUnit::micrometre: return "um";
    case LengthUnit::unknown: break;
  }
  return "unknown";
}

double metresPer(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::millimetre: return 1e-3;
    case LengthUnit::metre: return 1.0;
    case LengthUnit::centimetre: return 1e-2;
    case LengthUnit::micrometre: return 1e-6;
    case LengthUnit::unknown: break;
  }
  throw MeshError("units", "no length unit given", "declare mm or m");
}

namespace {

constexpr std::uintmax_t kLargestMeshFile = std::uintmax_t{1} << 30;  // [B] 1 GiB
constexpr std::size_t kLargestPlyHeader = 64 * 1024;                  // [B]

struct Vec3BitsHash {
  size_t operator()(const std::array<double, 3>& p) const {
    size_t h = 1469598103934665603ull;
    for (double c : p) {
      std::uint64_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return h;
  }
};

std::string formatLength(double metres) {
  std::ostringstream s;
  s.precision(3);
  if (metres >= 0.1)
    s << metres << " m";
  else if (metres >= 1e-3)
    s << metres * 1e3 << " mm";
  else
    s << metres * 1e6 << " um";
  return s.str();
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Walks the node hierarchy, applying each node's accumulated transform (identity for STL/OBJ/PLY,
// not for glTF/FBX/DAE). Polygons are split into fans (v0, vi, vi+1), exact for the convex faces
// exporters write; points and lines are skipped. This replaces assimp's Triangulate and
// SortByPType steps, which abort the process (an internal assertion) on a face list that
// contradicts its header, found by fuzzing (docs/fuzzing.md).
void collectNode(const std::string& path, const aiScene& scene, const aiNode& node,
                 const aiMatrix4x4& parent, TriangleMesh& out) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    if (node.mMeshes[k] >= scene.mNumMeshes || scene.mMeshes[node.mMeshes[k]] == nullptr)
      throw MeshError(path, "cannot read the file as a mesh: a node names a missing mesh",
                      "re-export the mesh");
    const aiMesh& m = *scene.mMeshes[node.mMeshes[k]];
    const int base = static_cast<int>(out.vertices.size());
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      const aiVector3D p = transform * m.mVertices[v];
      out.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      for (unsigned i = 0; i < face.mNumIndices; ++i)
        if (face.mIndices[i] >= m.mNumVertices)
          throw MeshError(path,
                          "face " + std::to_string(f) + " refers to vertex " +
                              std::to_string(face.mIndices[i]) + " of " +
                              std::to_string(m.mNumVertices),
                          "the file is damaged or its header contradicts its data: re-export it");
      for (unsigned i = 1; i + 1 < face.mNumIndices; ++i)
        out.faces.push_back({base + static_cast<int>(face.mIndices[0]),
                             base + static_cast<int>(face.mIndices[i]),
                             base + static_cast<int>(face.mIndices[i + 1])});
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    collectNode(path, scene, *node.mChildren[c], transform, out);
}

// A path assimp may open: an existing, non-empty regular file of bounded size (a directory, a
// device such as /dev/zero or a pipe would be read forever or fail with a misleading message).
void checkMeshFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found)
    throw MeshError(path, "file not found", "check the path and the working directory");
  if (ec)
    throw MeshError(path, "cannot open: " + ec.message(),
                    "check the path (a symbolic link that points to itself? permissions?)");
  if (fs::is_directory(status))
    throw MeshError(path, "is a directory, not a mesh file",
                    "give the path of a .stl/.obj/.ply/.off file");
  if (!fs::is_regular_file(status))
    throw MeshError(path, "is not a regular file (a device, pipe or socket)",
                    "give the path of a .stl/.obj/.ply/.off file saved on disk");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (ec) throw MeshError(path, "cannot read its size: " + ec.message(), "check the file");
  if (bytes == 0)
    throw MeshError(path, "file is empty (0 bytes)",
                    "re-export the mesh; the write probably failed");
  if (bytes > kLargestMeshFile)
    throw MeshError(path,
                    "file is " + std::to_string(bytes >> 20) + " MiB, more than the " +
                        std::to_string(kLargestMeshFile >> 20) + " MiB an eye mesh needs",
                    "decimate the mesh (an eye cavity needs some 1e4-1e5 triangles)");
}

// Headers assimp's readers do not bound: an ASCII PLY without `end_header` makes assimp 5.2's
// PLY reader loop forever, so a PLY must start with "ply" and end its header within the first
// kLargestPlyHeader bytes.
void checkFormatHeader(const std::string& path) {
  if (lowerExtension(path) != ".ply") return;
  std::ifstream in(path, std::ios::binary);
  std::string head(kLargestPlyHeader, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (!head.starts_with("ply"))
    throw MeshError(path, "cannot read the file as a mesh: it does not start with 'ply'",
                    "check that it is a PLY export, not another format renamed");
  std::istringstream lines(head);
  std::string line;
  std::size_t consumed = 0;
  while (std::getline(lines, line)) {
    consumed += line.size() + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line == "end_header" && consumed <= head.size()) return;
  }
  throw MeshError(path,
                  "cannot read the file as a mesh: its PLY header has no 'end_header' line "
                  "within the first " +
                      std::to_string(kLargestPlyHeader / 1024) + " KiB",
                  "the file is truncated or not a PLY file: re-export it");
}

}  // namespace

int joinIdenticalVertices(TriangleMesh& mesh) {
  std::unordered_map<std::array<double, 3>, int, Vec3BitsHash> index;
  index.reserve(mesh.vertices.size());
  std::vector<int> remap(mesh.vertices.size(), -1);
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const Triangle& f : mesh.faces)
    for (int v : f) used[static_cast<size_t>(v)] = 1;
  std::vector<Vec3> kept;
  kept.reserve(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!used[v]) continue;
    const Vec3& p = mesh.vertices[v];
    // +0.0 and -0.0 must join: normalise the sign of zero before hashing the bits.
    const std::array<double, 3> key{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};
    const auto [it, inserted] = index.emplace(key, static_cast<int>(kept.size()));
    if (inserted) kept.push_back(p);
    remap[v] = it->second;
  }
  const int removed = static_cast<int>(mesh.vertices.size() - kept.size());
  for (Triangle& f : mesh.faces)
    for (int& v : f) v = remap[static_cast<size_t>(v)];
  mesh.vertices = std::move(kept);
  return removed;
}

namespace {

// The file's triangles in file units, every vertex finite (throws a MeshError otherwise).
TriangleMesh readTriangles(const std::string& path) {
  checkMeshFile(path);
  checkFormatHeader(path);

  Assimp::Importer importer;
  const std::string ext = lowerExtension(path);
  if (ext.empty() || !importer.IsExtensionSupported(ext)) {
    std::string list;
    importer.GetExtensionList(list);
    throw MeshError(path, "unknown mesh format '" + ext + "'",
                    "export as .stl, .obj, .ply or .off (assimp also reads " + list + ")");
  }
  // Only the reader and its structure check: every post-processing step we need (polygons into
  // triangles, points and lines dropped, identical vertices joined across sub-meshes) is done
  // below, where a contradictory file becomes a MeshError instead of an assimp assertion.
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  const std::string assimpError = importer.GetErrorString();
  if (scene != nullptr && scene->mNumMeshes == 0)
    throw MeshError(path, "contains no triangles (only points, lines or nothing)",
                    "export the cavity as a closed triangle surface");
  if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) ||
      scene->mRootNode == nullptr)
    throw MeshError(path, "cannot read the file as a mesh: " + assimpError,
                    "check that it is a valid " + ext.substr(1) +
                        " file (not truncated, not another format renamed)");

  TriangleMesh mesh;
  collectNode(path, *scene, *scene->mRootNode, aiMatrix4x4(), mesh);
  if (mesh.faces.empty())
    throw MeshError(path, "contains no triangles (only points, lines or nothing)",
                    "export the cavity as a closed triangle surface");
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!mesh.vertices[v].allFinite()) {
      std::ostringstream s;
      s << "vertex " << v << " has a NaN or infinite coordinate (" << mesh.vertices[v].transpose()
        << ")";
      throw MeshError(path, s.str(), "repair or re-export the mesh in the modelling tool");
    }
  }
  return mesh;
}

// The unit guessed from the bounding-box diagonal `raw` (file units), with its warning.
LengthUnit guessUnit(const std::string& path, const MeshMeasures& raw,
                     std::vector<std::string>& warnings) {
  const double diagonal = raw.diagonal();  // [file units]
  std::ostringstream diag;
  diag.precision(4);
  diag << diagonal;
  const auto plausible = [&](LengthUnit u) {
    const double s = raw.size() * metresPer(u);
    return s >= kMinEyeSize && s <= kMaxEyeSize;
  };
  LengthUnit unit;
  if (diagonal >= 10 && diagonal <= 60)
    unit = LengthUnit::millimetre;
  else if (diagonal >= 0.01 && diagonal <= 0.06)
    unit = LengthUnit::metre;
  else if (plausible(LengthUnit::millimetre))
    unit = LengthUnit::millimetre;
  else if (plausible(LengthUnit::metre))
    unit = LengthUnit::metre;
  else
    throw MeshError(path,
                    "size " + diag.str() +
                        " (bounding-box diagonal, file units) is implausible for "
                        "an eye in mm (" +
                        formatLength(raw.size() * 1e-3) + " across) and in m (" +
                        formatLength(raw.size()) + " across)",
                    "an eye cavity is 20-30 mm across; rescale the mesh to mm or m");
  warnings.push_back(std::string("no units declared: assumed ") + toString(unit) +
                     " because the bounding-box diagonal is " + diag.str() +
                     " file units (an eye is 20-30 mm across); declare the units "
                     "(--units mm|m, or units in the protocol) to silence this");
  return unit;
}

// Throws when `size` [m] across is no eye cavity, naming the likely unit mistake.
void requireEyeSize(const std::string& path, double size, LengthUnit unit) {
  if (size > kMaxEyeSize || size < kMinEyeSize) {
    const bool big = size > kMaxEyeSize;
    std::string fix;
    if (unit == LengthUnit::metre && big)
      fix = "the file is probably in mm: declare --units mm";
    else if (unit == LengthUnit::millimetre && !big)
      fix = "the file is probably in m: declare --units m";
    else
      fix = "an eye cavity is 20-30 mm across; check the units the file was exported in";
    throw MeshError(
        path,
        "implausible size " + formatLength(size) + " across with units " + toString(unit) +
            (big ? " (an eye cavity is smaller than " : " (an eye cavity is larger than ") +
            formatLength(big ? kMaxEyeSize : kMinEyeSize) + ")",
        fix);
  }
}

}  // namespace

ImportResult importMesh(const std::string& path, LengthUnit unit) {
  ImportResult result;
  result.mesh = readTriangles(path);
  result.joinedVertices = joinIdenticalVertices(result.mesh);

  // Units: declared, or guessed from the bounding-box diagonal.
  const MeshMeasures raw = measureMesh(result.mesh);
  if (unit == LengthUnit::unknown) {
    result.unitGuessed = true;
    unit = guessUnit(path, raw, result.warnings);
  }
  result.unit = unit;
  const double scale = metresPer(unit);  // [m per file unit]
  for (Vec3& p : result.mesh.vertices) p *= scale;
  requireEyeSize(path, raw.size() * scale, unit);  // [m]
  return result;
}

}  // namespace meshing
