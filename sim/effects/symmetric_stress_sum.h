// The symmetric pair sum of a per-particle stress Pi (the surface stress of Hu & Adams 2006):
//
//   f_i = V_i sum_j V_j (Pi_i + Pi_j) gradW_ij        [N],  V = m / rho,
//
// over i's fluid-list neighbours, a particle without a stress counting as Pi = 0 (pairs where
// neither carries one are skipped). Antisymmetric in i and j, so the pairs conserve momentum.
// Shared by the interfacial tension's symmetric form and the wall-adhesion stress, so that both
// add their pairs in the same order with the same arithmetic. `include(j)` may leave neighbours
// out (the wall adhesion leaves out tissue).
#pragma once

#include <cstdint>
#include <vector>

#include "sim/world/pair_loop.h"

namespace sim {

template <class Include>
Vec3 symmetricStressSum(const World& world, Index i, Real vi, const std::vector<Mat3>& stress,
                        const std::vector<std::uint8_t>& stressed, Include include) {
  const auto& p = world.particles;
  Vec3 f = Vec3::Zero();
  fluidPairs(world).forEach(i, [&](Index j, const Vec3& gradW) {
    if (!stressed[i] && !stressed[j]) return;  // both zero (includes non-members)
    if (!include(j)) return;
    const Mat3 sum =
        stressed[i] ? (stressed[j] ? Mat3(stress[i] + stress[j]) : stress[i]) : stress[j];
    f += vi * (p.mass[j] / p.density[j]) * (sum * gradW);
  });
  return f;
}

}  // namespace sim
