#include "sim/fluid/density.h"

namespace sim {

void computeDensities(World& world, std::vector<Real>& density) {
  const auto& p = world.particles;
  const auto& walls = world.walls;
  const NeighborList& nf = world.fluidNeighbors();
  const NeighborList& nw = world.wallNeighbors();
  const Kernel& kernel = world.kernel;
  const Real w0 = kernel.W0();
  const Index n = static_cast<Index>(p.size());
  density.resize(n);
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Real rho = p.mass[i] * w0;
    for (const Index* j = nf.begin(i); j != nf.end(i); ++j) rho += p.mass[*j] * kernel.W(p.x[i] - p.x[*j]);
    Real wallSum = 0;
    for (const Index* b = nw.begin(i); b != nw.end(i); ++b)
      wallSum += walls.volume[*b] * kernel.W(p.x[i] - walls.x[*b]);
    density[i] = rho + world.restDensityOf(i) * wallSum;
  }
}

}  // namespace sim
