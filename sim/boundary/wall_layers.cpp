#include "sim/boundary/wall_layers.h"

#include <cmath>
#include <string>

namespace sim {

bool hasLayeredWalls(const WallParticles& walls) { return walls.fields.has(kWallLayerField); }

std::vector<std::int32_t>& wallLayerField(WallParticles& walls) {
  return walls.fields.addOrGet<std::int32_t>({kWallLayerField, "1", true, true});
}

bool isSurfaceWall(const WallParticles& walls, std::size_t b) {
  if (!hasLayeredWalls(walls)) return true;
  return walls.fields.get<std::int32_t>(kWallLayerField)[b] == 0;
}

void addLayeredWallParticle(WallParticles& walls, const Vec3& position, const Vec3& outwardNormal,
                            int tag, Real volume, int layer) {
  require(volume > 0 && std::isfinite(volume),
          "a layered wall particle needs its volume > 0 m^3 (got " + std::to_string(volume) + ")");
  require(layer >= 0, "wall layer index must be >= 0 (0 = surface layer)");
  auto& layerOf = wallLayerField(walls);
  walls.add(position, outwardNormal, tag, volume);
  layerOf.back() = layer;
}

std::size_t addWallLayersBehindSurface(WallParticles& walls, const std::vector<Vec3>& points,
                                       const std::vector<Vec3>& normals,
                                       const std::vector<Real>& areas,
                                       const std::vector<Real>& curvature,
                                       const std::vector<int>& tags, Real d,
                                       const WallLayers& layers) {
  require(d > 0, "wall layer spacing must be > 0 m");
  require(layers.count >= 1, "a layered wall needs at least one layer");
  require(normals.size() == points.size() && areas.size() == points.size(),
          "surface samples need one normal and one area per point (got " +
              std::to_string(points.size()) + " points, " + std::to_string(normals.size()) +
              " normals, " + std::to_string(areas.size()) + " areas)");
  require(curvature.empty() || curvature.size() == points.size(),
          "surface curvature must be empty (flat) or one value per sample");
  require(tags.empty() || tags.size() == points.size(),
          "surface tags must be empty or one per sample");
  std::size_t added = 0;
  for (std::size_t s = 0; s < points.size(); ++s) {
    const Real length = normals[s].norm();
    require(length > 0.5 && length < 1.5, "surface sample " + std::to_string(s) +
                                              " has no unit normal; layered walls need normals");
    const Vec3 n = normals[s] / length;
    for (int k = 0; k < layers.count; ++k) {
      const Real depth = (k + 0.5) * d;  // [m]
      // Area of the parallel surface at `depth` on the wall side: for a surface whose fluid side
      // is a ball of radius R (mean curvature 1/R), the offset sphere has (1 + depth/R)^2 the area.
      const Real grow = curvature.empty() ? 1.0 : 1.0 + curvature[s] * depth;
      const Real volume = areas[s] * d * std::max(grow * grow, Real(0.25));
      addLayeredWallParticle(walls, points[s] + depth * n, n, tags.empty() ? 0 : tags[s], volume,
                             k);
      ++added;
    }
  }
  return added;
}

}  // namespace sim
