// Tissue particles in a shell around a closed surface, sampled as layers along the surface
// (issue 7): each surface sample gets particles at depths (k + 1/2) d along its outward normal.
// Unlike sampleShell's lattice, whose inner face on a curved surface is a staircase with openings
// about a spacing wide (fluid entered them 0.5-0.8 d deep, docs/elasticity.md), the inner layer
// lies at d/2 from the surface everywhere and is as dense as the surface samples; and where the
// shell ends on the surface (the sclera at the lens cap) it ends on the same surface samples as
// the walls there, so no seam opens between them.
#pragma once

#include <functional>
#include <vector>

#include "meshing/sample_shell.h"
#include "meshing/sample_surface.h"

namespace meshing {

struct ShellLayerOptions {
  double spacing = 0;  // [unit] d, the layer spacing along the normal
  // [unit] thickness t at a surface sample; <= 0: no shell there (e.g. the lens/IOL cap)
  std::function<double(const Vec3& surfacePoint)> thickness;
  // [1/unit] curvature of the surface, positive when it curves around the inside (a sphere of
  // radius R: 1/R); sets the layers' volumes (the offset surface at depth z has (1 + kappa z)^2
  // the area). 0 = flat.
  double curvature = 0;
  int minLayers = 2;  // [1] at least this many layers wherever t > 0 (the elasticity needs two)
};

// Layer k lies on `layers[k]` (samples of the surface with outward normals and areas, e.g.
// sampleSurface at spacing d, each layer with its own seed so that the holes of one random
// packing do not line up with the next layer's into a channel through the shell): a sample whose
// surface point has t > 0 and n = max(minLayers, round(t / d - 1/2)) > k (the same count per area
// as sampleShell's lattice between d/2 and t, which holds (t - d/2) / d particles per d^2) gets a
// particle at depth (k + 1/2) d along its normal, with volume A d (1 + kappa (k + 1/2) d)^2,
// marked isOuter when k = n - 1. Throws MeshError when a location needs more layers than given.
// Points layer by layer, innermost first, in sample order.
ShellSamples sampleShellLayers(const std::vector<SurfaceSamples>& layers, const ShellLayerOptions& options);

}  // namespace meshing
