#include "sim/fluid/density.h"

namespace sim {

void computeDensities(World& world, std::vector<Real>& density) {
  const auto& mass = world.particles.mass;
  kernelSums(
      world, density, [&](Index j) { return mass[j]; },
      [&](Index i, Real fluid, Real wall) { return fluid + world.restDensityOf(i) * wall; });
}

}  // namespace sim
