// Fill level of a cavity: the plane that leaves a given fraction of the enclosed volume on one
// side, and the lattice particles of each phase.
#pragma once

#include <vector>

#include "meshing/sample_volume.h"
#include "meshing/triangle_mesh.h"

namespace meshing {

// The half-space {x : direction . x >= offset} is "above" (the +u side).
struct FillPlane {
  Vec3 direction = Vec3::UnitZ();  // unit normal u, pointing into the filled phase
  double offset = 0;               // [unit] c in u . x = c
  double volumeAbove = 0;          // [unit^3] enclosed volume with u . x >= c
  double volumeBelow = 0;          // [unit^3] enclosed volume with u . x <  c
  bool isAbove(const Vec3& p) const { return direction.dot(p) >= offset; }
};

// Exact volume of the part of the closed, outward mesh with u . x >= c. By the divergence
// theorem V = (1/3) * closed integral of (x - o) . n dA over the clipped solid's boundary; with
// o on the plane the cap face contributes nothing ((x - o) . u = 0 there), so V is the sum of
// signed tetrahedra (o, triangle piece) over the triangles clipped to the half-space.
double clippedVolume(const TriangleMesh& mesh, const Vec3& direction, double offset);

// The plane u . x = c with `fraction` f of the enclosed volume on the +u side, by bisection on
// clippedVolume() (monotone in c) to |dc| < 1e-12 of the mesh extent. The caller picks u: oil
// lighter than aqueous floats, u = -gravity; a heavy oil sinks, u = +gravity.
// Throws MeshError for f outside [0, 1] or a zero direction.
FillPlane findFillPlane(const TriangleMesh& mesh, double fraction, const Vec3& direction);

struct PhaseSamples {
  std::vector<Vec3> above;  // lattice points on the +u side (the filled phase)
  std::vector<Vec3> below;  // the rest of the cavity
};

// sampleVolume() of the cavity split by the plane; both phases share one lattice, so the
// particles continue across the interface without a gap. options.keep, if set, applies too.
PhaseSamples sampleFillPhases(const TriangleMesh& mesh, const FillPlane& plane,
                              const VolumeSamplingOptions& options);

}  // namespace meshing
