// Global diagnostics of the dynamic particles, deterministic (fixed-order sums).
#pragma once

#include "sim/core/reduction.h"
#include "sim/world/world.h"

namespace sim {

inline Real kineticEnergy(const World& world) {  // [J]
  const auto& p = world.particles;
  DeterministicReducer r;
  return r.sum(p.size(), [&](std::size_t i) { return 0.5 * p.mass[i] * p.v[i].squaredNorm(); });
}

inline Vec3 linearMomentum(const World& world) {  // [kg m/s]
  const auto& p = world.particles;
  DeterministicReducer r;
  return r.sumVec(p.size(), [&](std::size_t i) { return Vec3(p.mass[i] * p.v[i]); });
}

inline Real maxSpeed(const World& world) {  // [m/s]
  const auto& v = world.particles.v;
  return std::sqrt(
      DeterministicReducer::max(v.size(), [&](std::size_t i) { return v[i].squaredNorm(); }));
}

inline bool allFinite(const World& world) {
  const auto& p = world.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!p.x[i].allFinite() || !p.v[i].allFinite()) return false;
  return true;
}

}  // namespace sim
