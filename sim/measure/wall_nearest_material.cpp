#include "sim/measure/wall_nearest_material.h"

#include <limits>

namespace sim {

std::vector<int> wallNearestMaterial(const World& world) {
  const auto& p = world.particles;
  const auto& walls = world.walls;
  std::vector<int> out(walls.size(), -1);
  const auto wallCount = static_cast<std::ptrdiff_t>(walls.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t b = 0; b < wallCount; ++b) {
    Real best = std::numeric_limits<Real>::infinity();
    for (Index i = 0; i < p.size(); ++i) {
      const Real r2 = (p.x[i] - walls.x[b]).squaredNorm();
      if (r2 < best) {
        best = r2;
        out[b] = p.material[i];
      }
    }
  }
  return out;
}

}  // namespace sim
