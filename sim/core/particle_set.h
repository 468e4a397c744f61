// Dynamic particles (fluid phases now, elastic tissue later) and static wall particles.
//
// Both are structure-of-arrays FieldRegistry instances with a few always-present fields that
// have typed accessors; effects and solvers register further fields only when they are active.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/core/field_registry.h"
#include "sim/core/types.h"

namespace sim {

// Names of the always-present fields (also the names in output files).
namespace field {
inline constexpr const char* kPosition = "position";
inline constexpr const char* kVelocity = "velocity";
inline constexpr const char* kAcceleration = "acceleration";
inline constexpr const char* kMass = "mass";
inline constexpr const char* kMaterial = "material";
inline constexpr const char* kId = "id";
inline constexpr const char* kDensity = "density";
inline constexpr const char* kNormal = "normal";
inline constexpr const char* kVolume = "volume";
inline constexpr const char* kTag = "tag";
}  // namespace field

class DynamicParticles {
 public:
  DynamicParticles()
      : x(fields.add<Vec3>({field::kPosition, "m", true, true})),
        v(fields.add<Vec3>({field::kVelocity, "m/s", true, true})),
        a(fields.add<Vec3>({field::kAcceleration, "m/s^2", false, false})),
        mass(fields.add<Real>({field::kMass, "kg", true, false})),
        material(fields.add<std::int32_t>({field::kMaterial, "1", true, true})),
        id(fields.add<std::int32_t>({field::kId, "1", true, true})),
        density(fields.add<Real>({field::kDensity, "kg/m^3", false, true})) {}
  DynamicParticles(const DynamicParticles&) = delete;
  DynamicParticles& operator=(const DynamicParticles&) = delete;

  std::size_t size() const { return fields.size(); }
  // Appends one particle; its id is its creation index (stable across re-sorting).
  void add(const Vec3& position, const Vec3& velocity, Real particleMass, int materialIndex) {
    const std::size_t i = size();
    fields.resize(i + 1);
    x[i] = position;
    v[i] = velocity;
    mass[i] = particleMass;
    material[i] = materialIndex;
    id[i] = static_cast<std::int32_t>(i);
  }

  FieldRegistry fields;
  std::vector<Vec3>& x;     // [m]
  std::vector<Vec3>& v;     // [m/s]
  std::vector<Vec3>& a;     // [m/s^2] non-pressure acceleration of the current step
  std::vector<Real>& mass;  // [kg]
  std::vector<std::int32_t>& material;
  std::vector<std::int32_t>& id;  // creation index, survives sorting
  std::vector<Real>& density;     // [kg/m^3] as the active pressure solver defines it
};

// Static wall particles: never moved by forces (docs/developer-guide.md principle 2: the wall is
// fixed in the eye frame). `volume` is the Akinci et al. 2012 boundary volume 1/sum_k W_bk.
class WallParticles {
 public:
  WallParticles()
      : x(fields.add<Vec3>({field::kPosition, "m", true, true})),
        normal(fields.add<Vec3>({field::kNormal, "1", true, false})),
        volume(fields.add<Real>({field::kVolume, "m^3", true, false})),
        tag(fields.add<std::int32_t>({field::kTag, "1", true, true})) {}
  WallParticles(const WallParticles&) = delete;
  WallParticles& operator=(const WallParticles&) = delete;

  std::size_t size() const { return fields.size(); }
  // `outwardNormal` points from the fluid into the wall material (zero if unknown); `tag` is a
  // caller-defined group (e.g. which wall or region), carried but never interpreted by sim/.
  // `particleVolume` [m^3] 0 means "unknown": World::initialize() then computes the Akinci volume.
  void add(const Vec3& position, const Vec3& outwardNormal = Vec3::Zero(), int groupTag = 0,
           Real particleVolume = 0.0) {
    const std::size_t i = size();
    fields.resize(i + 1);
    x[i] = position;
    normal[i] = outwardNormal;
    tag[i] = groupTag;
    volume[i] = particleVolume;
  }

  FieldRegistry fields;
  std::vector<Vec3>& x;       // [m]
  std::vector<Vec3>& normal;  // [1]
  std::vector<Real>& volume;  // [m^3]
  std::vector<std::int32_t>& tag;
};

}  // namespace sim
