// Share of one fluid material seen by each wall particle (docs/methods/interface.md validation 5:
// coverage of a cavity wall by oil). The same Shepard-normalised SPH interpolant of the phase
// indicator as protocols/coverage/wall_oil_fraction.h, here within the engine's own kernel support
// h:
//   phi_b = sum_j V_j W(x_b - x_j) [mat_j == material] / sum_j V_j W(x_b - x_j),  V_j = m_j /
//   rho0_j,
// 0 for a wall particle with no fluid neighbour ("dry"). The wall particle is covered when
// phi_b >= 0.5. The normalisation matters: a wall particle sees fluid on one side only, so the
// plain sum would read about half the true fraction.
#pragma once

#include <vector>

#include "sim/world/world.h"

namespace sim {

// One value per wall particle [1], from the current wall neighbour lists (call after the
// world's neighbours are up to date, e.g. after a pipeline step).
std::vector<Real> wallPhaseFraction(const World& world, int material);

}  // namespace sim
