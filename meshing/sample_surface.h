// Evenly spaced static wall particles on a triangle surface, each with the area it stands for.
#pragma once

#include <cstdint>
#include <vector>

#include "meshing/triangle_mesh.h"

namespace meshing {

struct SurfaceSamples {
  std::vector<Vec3> points;    // [unit] on the surface, #N
  std::vector<Vec3> normals;   // unit outward normal of the face each point lies on, #N
  std::vector<double> areas;   // [unit^2] surface area each point stands for; sums to the mesh area
  std::vector<int> faceIndex;  // face of the input mesh each point lies on, #N
  size_t size() const { return points.size(); }
};

struct SurfaceSamplingOptions {
  double spacing = 0;  // [unit] d, the nominal particle spacing
  // No two samples closer than exclusion * d (Euclidean). 0.9 makes the mean nearest-neighbour
  // distance come out close to d (RSA packings leave gaps, see below).
  double exclusion = 0.9;
  double candidatesPerArea = 24;    // candidates per d^2 of area (more: fuller, slower)
  std::uint64_t seed = 0x7a3b0c1d;  // fixed: same mesh and options give the same samples
};

// Poisson-disk sampling by dart throwing over a dense, area-stratified candidate set
// (random sequential adsorption, e.g. Bridson 2007 in spirit, Cline et al. 2009 for surfaces):
// candidates in random order are accepted when no accepted sample lies within r = exclusion*d.
// Accepted samples end up at least r apart and, the candidate set being dense, every surface
// point lies within about r of one; the density approaches the RSA jamming limit, ~0.547 disk
// coverage, i.e. about 0.70 samples per r^2 (Feder 1980), 0.86 per d^2 at r = 0.9 d. Each candidate
// carries area (face area / its face's candidate count) and gives it to its nearest sample, so the
// areas are a Monte-Carlo Voronoi partition that sums exactly to the mesh area. `mesh` must be
// outward oriented (normals are face normals). Throws MeshError on d <= 0 or a spacing too small
// for the mesh (more than ~50 million candidates).
SurfaceSamples sampleSurface(const TriangleMesh& mesh, const SurfaceSamplingOptions& options);
inline SurfaceSamples sampleSurface(const TriangleMesh& mesh, double spacing) {
  SurfaceSamplingOptions o;
  o.spacing = spacing;
  return sampleSurface(mesh, o);
}

}  // namespace meshing
