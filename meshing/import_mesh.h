// Reads a triangle mesh file (STL ascii/binary, OBJ, PLY, OFF and whatever else assimp reads
// cleanly) into a TriangleMesh in metres: triangulated, node transforms applied, identical
// vertices joined. Geometry is not validated here beyond finite coordinates and a plausible
// size; checkMesh() does the topology.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "meshing/triangle_mesh.h"

namespace meshing {

// The units a mesh may be declared in: those of the protocol's eye.mesh_units (m, cm, mm, um).
enum class LengthUnit { unknown, millimetre, metre, centimetre, micrometre };

// "m", "cm", "mm", "um" -> the unit; anything else throws MeshError saying which spellings are
// accepted.
LengthUnit parseLengthUnit(std::string_view text);
const char* toString(LengthUnit unit);  // "mm", "m", "cm", "um" or "unknown"
double metresPer(LengthUnit unit);      // 1e-3, 1, 1e-2, 1e-6, or throws for unknown

struct ImportResult {
  TriangleMesh mesh;                      // [m]
  LengthUnit unit = LengthUnit::unknown;  // the unit used: declared, or guessed from the size
  bool unitGuessed = false;
  std::vector<std::string> warnings;  // e.g. the guessed unit and how to declare it
  int joinedVertices = 0;             // vertices merged because their coordinates were identical
};

// Plausible size of an eye cavity after unit conversion: the largest bounding-box extent must lie
// in [kMinEyeSize, kMaxEyeSize] or the import fails (a mm-vs-m mistake gives 1000x off). Eyes
// are 20-30 mm long, 15 mm in nanophthalmos and up to 36 mm in high myopia (the protocol's
// eye.axial_length range): 10-50 mm leaves a margin both ways and refuses a 1 mm "cavity" (a few
// particles) and a mesh in m read as mm.
inline constexpr double kMinEyeSize = 10e-3;  // [m]
inline constexpr double kMaxEyeSize = 50e-3;  // [m]

// Throws MeshError (file name, what is wrong, how to fix) for: missing or empty file, unknown
// format, unreadable content, no triangles, NaN/infinite coordinates, implausible size.
// With unit == unknown the unit is guessed from the bounding-box diagonal (an eye is 20-30 mm
// across: 10-60 units means mm, 0.01-0.06 means m) and a warning says so.
ImportResult importMesh(const std::string& path, LengthUnit unit = LengthUnit::unknown);

// Joins vertices with bit-identical coordinates and drops unreferenced ones; face order kept.
// Returns the number of vertices removed.
int joinIdenticalVertices(TriangleMesh& mesh);

}  // namespace meshing
