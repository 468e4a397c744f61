// Orbital fat as a closed volume behind the posterior pole: a cup whose inner face is the outer
// surface of the sclera (so fat and sclera touch without gap or overlap) and whose outer face
// lies `thickness` further out along the base ellipsoid's normal, over the wall within
// `polarExtent` of the posterior pole, closed by a ring face at that edge. The optic nerve and
// the muscles are not modelled. Material "orbital_fat" (material_library.h).
// Thickness and extent are [U] model choices: the fat fills the muscle cone behind the globe,
// several mm deep.
#pragma once

#include <numbers>
#include <string>

#include "anatomy/sclera_shell.h"
#include "meshing/triangle_mesh.h"

namespace anatomy {

struct OrbitalFatParameters {
  double thickness = 6.0e-3;                    // [m] 0.5..30 mm [U]
  double polarExtent = std::numbers::pi / 3.0;  // [rad] from the posterior pole, 10..90 deg [U]
  int resolution = 64;                          // segments around the axis
};

struct OrbitalFat {
  meshing::TriangleMesh mesh;  // closed, outward, eye frame [m]
  std::string materialName = "orbital_fat";
  double volume = 0.0;  // [m^3] of the mesh
};

// Throws AnatomyError for parameters out of range.
OrbitalFat makeOrbitalFat(const ScleraShell& sclera, const OrbitalFatParameters& parameters = {});

}  // namespace anatomy
