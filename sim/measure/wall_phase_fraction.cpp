#include "sim/measure/wall_phase_fraction.h"

namespace sim {

std::vector<Real> wallPhaseFraction(const World& world, int material) {
  const auto& p = world.particles;
  const auto& walls = world.walls;
  const NeighborList& nw = world.wallNeighbors();
  // Scatter over the fluid particles' wall lists (serial: several fluid particles write to one
  // wall particle; this is a measurement, called a few times per run).
  std::vector<Real> weighted(walls.size(), 0.0), total(walls.size(), 0.0);
  for (Index i = 0; i < p.size(); ++i) {
    const Real v = world.restVolumeOf(i);  // [m^3]
    const bool match = p.material[i] == material;
    for (const Index* b = nw.begin(i); b != nw.end(i); ++b) {
      const Real vw = v * world.kernel.W(Vec3(p.x[i] - walls.x[*b]));
      total[*b] += vw;
      if (match) weighted[*b] += vw;
    }
  }
  for (std::size_t b = 0; b < walls.size(); ++b)
    weighted[b] = total[b] > 0 ? weighted[b] / total[b] : 0.0;
  return weighted;
}

}  // namespace sim
