// Tissue particles in a shell around a closed surface (the sclera around the cavity): the solid
// between the surface and its outward offset by a thickness that may vary over the surface.
#pragma once

#include <functional>
#include <vector>

#include "meshing/triangle_mesh.h"

namespace meshing {

struct ShellSamplingOptions {
  double spacing = 0;  // [unit] d, the lattice spacing
  // [unit] thickness t at a surface point (the point of the surface nearest to the particle);
  // called from several OpenMP threads at once, so it must not modify shared state
  std::function<double(const Vec3& surfacePoint)> thickness;
  double innerGap = -1;  // [unit] minimum distance from the surface; negative means d/2
  Vec3 latticeOrigin = Vec3::Zero();  // [unit] one lattice point
};

struct ShellSamples {
  std::vector<Vec3> points;   // [unit] #N, column order as in sampleVolume()
  std::vector<char> isOuter;  // 1 for the outermost layer (within d of the outer surface): anchors
  std::vector<double> depth;  // [unit] distance from the inner surface, #N
};

// Lattice points p outside the closed, outward mesh with innerGap <= dist(p, S) <= t(q), q the
// point of S nearest to p (so the outer boundary is the offset surface for a slowly varying t).
// Expected count: N d^3 ~= shell volume - A * innerGap, as for sampleVolume(). The lattice spans
// the mesh box grown by the largest thickness found at the vertices and face centroids (plus d):
// a thickness function with sharp peaks between them is cut there.
ShellSamples sampleShell(const TriangleMesh& mesh, const ShellSamplingOptions& options);
ShellSamples sampleShell(const TriangleMesh& mesh, double thickness, double spacing);

}  // namespace meshing
