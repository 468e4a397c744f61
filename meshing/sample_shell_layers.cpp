#include "meshing/sample_shell_layers.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "meshing/mesh_error.h"

namespace meshing {

ShellSamples sampleShellLayers(const std::vector<SurfaceSamples>& layers, const ShellLayerOptions& options) {
  const double d = options.spacing;  // [unit]
  if (!(d > 0) || !std::isfinite(d))
    throw MeshError("shell layer sampling", "spacing must be positive and finite", "give e.g. 0.4 mm");
  if (!options.thickness)
    throw MeshError("shell layer sampling", "no thickness given", "give a thickness function");
  ShellSamples out;
  for (size_t k = 0; k < layers.size(); ++k) {
    const SurfaceSamples& surface = layers[k];
    if (surface.normals.size() != surface.size() || surface.areas.size() != surface.size())
      throw MeshError("shell layer sampling", "surface samples need one normal and one area each",
                      "sample the surface with sampleSurface");
    const double depth = (static_cast<double>(k) + 0.5) * d;  // [unit]
    // Never below a quarter of the area: a surface curving away this sharply is not a shell.
    const double grow = std::max(1.0 + options.curvature * depth, 0.5);
    for (size_t s = 0; s < surface.size(); ++s) {
      const double t = options.thickness(surface.points[s]);  // [unit]
      if (!std::isfinite(t))
        throw MeshError("shell layer sampling", "thickness function gave " + std::to_string(t),
                        "return a finite thickness");
      if (t <= 0) continue;
      const auto n = static_cast<size_t>(std::max(options.minLayers, static_cast<int>(std::lround(t / d - 0.5))));
      if (n > layers.size())
        throw MeshError("shell layer sampling",
                        "the thickness needs " + std::to_string(n) + " layers, " +
                            std::to_string(layers.size()) + " given",
                        "give one surface sampling per layer");
      if (k >= n) continue;
      out.points.push_back(surface.points[s] + depth * surface.normals[s].normalized());
      out.depth.push_back(depth);
      out.isOuter.push_back(k + 1 == n);
      out.volumes.push_back(surface.areas[s] * d * grow * grow);
    }
  }
  return out;
}

}  // namespace meshing
