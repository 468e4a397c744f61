// Anchoring of dynamic particles: a per-particle "fixed" flag. A fixed particle keeps its
// position: the elasticity solve treats it as a Dirichlet condition (velocity 0) and writes
// velocity 0 back. Used to pin the sclera's outer surface (meshing's sampleShell outer flags) or
// the orbital fat's back face, and the clamped end of a cantilever.
//
// The flag is a registry field, so it follows the particles through the Z-order re-sorting and
// into checkpoints. It is created on first use: scenes without anchors allocate nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/core/error.h"
#include "sim/core/particle_set.h"

namespace sim {

namespace field {
inline constexpr const char* kFixed = "fixed";
}  // namespace field

// The flags (1 = fixed), registered on first call.
inline std::vector<std::int32_t>& fixedFlags(DynamicParticles& particles) {
  return particles.fields.addOrGet<std::int32_t>({field::kFixed, "1", true, true});
}

inline void setFixed(DynamicParticles& particles, Index i, bool fixed = true) {
  require(i < particles.size(), "setFixed: particle index out of range");
  fixedFlags(particles)[i] = fixed ? 1 : 0;
}

// Sets v = 0 on every anchored particle (none when the field does not exist): the pipeline's
// constrain step, and INDSPH, which holds anchors still through its solves.
inline void zeroFixedVelocities(DynamicParticles& particles) {
  if (!particles.fields.has(field::kFixed)) return;
  const auto& fixed = particles.fields.get<std::int32_t>(field::kFixed);
  const Index n = static_cast<Index>(particles.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i)
    if (fixed[i] != 0) particles.v[i].setZero();
}

inline bool isFixed(const DynamicParticles& particles, Index i) {
  if (!particles.fields.has(field::kFixed)) return false;
  return particles.fields.get<std::int32_t>(field::kFixed)[i] != 0;
}

}  // namespace sim
