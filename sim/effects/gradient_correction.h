// Kernel-gradient correction of Bonet & Lok 1999 (Comput. Methods Appl. Mech. Engrg. 180:97,
// eq. 46): L_i = (sum_j V_j gradW_ij (x_j - x_i)^T)^-1, so that sum_j V_j (f_j - f_i) L_i gradW_ij
// is exact for any linear field f whatever the particle order. Used by the interfacial_tension
// stage's corrected surface stress (interfacial_tension_hu_adams2006.h). (The wall_adhesion stage
// keeps its symmetric pair sum: with this operator a 30 deg droplet over-spread to 25.8 deg and
// 150 deg stayed at 143.9, docs/interface.md validation 3.)
#pragma once

#include <cmath>

#include "sim/world/world.h"

namespace sim {

// Below this |det| (1 in a full support, ~0.5 in a half space, ~0.125 in a box corner) the
// particle has too few neighbours for a first-order gradient: L = I (the plain sum).
inline constexpr Real kMinCorrectionDeterminant = 0.05;

// L_i over the dynamic neighbours only (`withWalls` false: a one-sided gradient of the fluid's
// own field next to a wall) or over dynamic and wall neighbours (the wall completes the support,
// as a mirror does). Needs the densities of the current step (V_j = m_j / rho_j).
inline Mat3 gradientCorrection(const World& world, Index i, bool withWalls) {
  const auto& p = world.particles;
  const NeighborList& nf = world.fluidNeighbors();
  const auto& gradF = world.fluidGradients();
  Mat3 b = Mat3::Zero();
  for (Index k = nf.offsets[i]; k < nf.offsets[i + 1]; ++k) {
    const Index j = nf.indices[k];
    b += (p.mass[j] / p.density[j]) * gradF[k] * (p.x[j] - p.x[i]).transpose();
  }
  if (withWalls) {
    const NeighborList& nw = world.wallNeighbors();
    const auto& gradB = world.wallGradients();
    for (Index k = nw.offsets[i]; k < nw.offsets[i + 1]; ++k) {
      const Index w = nw.indices[k];
      b += world.walls.volume[w] * gradB[k] * (world.walls.x[w] - p.x[i]).transpose();
    }
  }
  return std::abs(b.determinant()) > kMinCorrectionDeterminant ? Mat3(b.inverse())
                                                               : Mat3::Identity();
}

}  // namespace sim
