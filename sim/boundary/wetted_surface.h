// Which elastic particles form a wetted surface, and of which wall tag (wall wetting on tissue).
//
// A contact angle is set per (fluid, wall tag) (MaterialTable::setContactAngle). Where an elastic
// tissue replaces the wall (the sclera under the retina), its fluid-facing layer carries that tag
// here, and the wall_adhesion stage wets it as it wets wall particles of the tag
// (sim/effects/wall_adhesion_young.h). Only one layer may carry a tag: the stage takes each tagged
// particle as a piece of surface area, so tagging the layers behind it would count the area twice.
//
// The tag is a registry field, so it follows the particles through the Z-order re-sorting and into
// checkpoints. It is created on first use: scenes without wetted tissue allocate nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/core/error.h"
#include "sim/core/particle_set.h"

namespace sim {

namespace field {
inline constexpr const char* kWettedSurfaceTag = "wetted_surface_tag";
}  // namespace field

// The field stores tag + 1, so that 0, the value of every particle added after the field was
// created, means "not a wetted surface".
inline std::vector<std::int32_t>& wettedSurfaceField(DynamicParticles& particles) {
  return particles.fields.addOrGet<std::int32_t>({field::kWettedSurfaceTag, "1", true, true});
}

inline void setWettedSurfaceTag(DynamicParticles& particles, Index i, std::int32_t wallTag) {
  require(i < particles.size(), "setWettedSurfaceTag: particle index out of range");
  require(wallTag >= 0, "setWettedSurfaceTag: wall tags are >= 0");
  wettedSurfaceField(particles)[i] = wallTag + 1;
}

// The wall tag of particle i's wetted surface, or -1 (also when no particle was ever tagged).
inline std::int32_t wettedSurfaceTag(const DynamicParticles& particles, Index i) {
  if (!particles.fields.has(field::kWettedSurfaceTag)) return -1;
  return particles.fields.get<std::int32_t>(field::kWettedSurfaceTag)[i] - 1;
}

// The stored field (tag + 1, 0 = none), or nullptr when no particle was ever tagged.
inline const std::vector<std::int32_t>* findWettedSurfaceField(const DynamicParticles& particles) {
  return particles.fields.has(field::kWettedSurfaceTag)
             ? &particles.fields.get<std::int32_t>(field::kWettedSurfaceTag)
             : nullptr;
}

}  // namespace sim
