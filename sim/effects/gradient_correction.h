// Kernel-gradient correction of Bonet & Lok 1999 (Comput. Methods Appl. Mech. Engrg. 180:97,
// eq. 46): L_i = (sum_j V_j gradW_ij (x_j - x_i)^T)^-1, so that sum_j V_j (f_j - f_i) L_i gradW_ij
// is exact for any linear field f whatever the particle order. Used by the interfacial_tension
// stage's corrected surface stress (interfacial_tension_hu_adams2006.h). (The wall_adhesion stage
// keeps its symmetric pair sum: with this operator a 30 deg droplet over-spread to 25.8 deg and
// 150 deg stayed at 143.9, docs/methods/interface.md validation 3.)
#pragma once

#include <cmath>

#include "sim/world/pair_loop.h"

namespace sim {

// Below these |det B| the neighbourhood is too irregular for the correction and the plain sum is
// kept (L = I). A full support reads det ~ 1 (with walls completing it next to a wall); the
// fluid-only matrix ~ 0.5 next to a flat wall (a half space), ~ 0.25 in a box edge. Measured
// (docs/methods/interface.md, validation 1c): with 0.05 for both, the INDSPH l = 2 droplet with
// XSPH 0.05 (mu 1 mPa s) blew up at 0.09 s (speeds from 0.4 to 160 m/s in 30 steps); with 0.5 for
// the full matrix it runs stably. gradC's one-sided matrix keeps 0.05: at 0.25 the 150 deg sessile
// droplet fell from 142.6 to 139.2 deg (its contact-line particles lie in that range).
inline constexpr Real kMinCorrectionDeterminant = 0.5;        // fluid and walls (divergence)
inline constexpr Real kMinFluidCorrectionDeterminant = 0.05;  // fluid only (gradC)

// The moment matrix B_i = sum_j V_j gradW_ij (x_j - x_i)^T over the dynamic neighbours, and the
// wall neighbours' part of it (the wall completes the support, as a mirror does). Needs the
// densities of the current step (V_j = m_j / rho_j).
// `liquidsOnly`: only the neighbours of fluid materials (elastic ones left out, as walls are).
inline Mat3 fluidGradientMoment(const World& world, Index i, bool liquidsOnly = false) {
  const auto& p = world.particles;
  Mat3 b = Mat3::Zero();
  fluidPairs(world).forEach(i, [&](Index j, const Vec3& gradW) {
    if (liquidsOnly && !world.materials.isFluid(p.material[j])) return;
    b += (p.mass[j] / p.density[j]) * gradW * (p.x[j] - p.x[i]).transpose();
  });
  return b;
}

inline Mat3 wallGradientMoment(const World& world, Index i) {
  Mat3 b = Mat3::Zero();
  wallPairs(world).forEach(i, [&](Index w, const Vec3& gradW) {
    b += world.walls.volume[w] * gradW * (world.walls.x[w] - world.particles.x[i]).transpose();
  });
  return b;
}

// L = B^-1, or I where |det B| <= `minimum`.
inline Mat3 gradientCorrection(const Mat3& moment, Real minimum) {
  return std::abs(moment.determinant()) > minimum ? Mat3(moment.inverse()) : Mat3::Identity();
}

}  // namespace sim
