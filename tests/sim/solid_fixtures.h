// Set-ups shared by the elastic-solid tests and the oscillating-plate benchmark.
#pragma once

#include <memory>
#include <vector>

#include "sim/effects/gravity.h"
#include "sim/fluid/pressure_solver.h"
#include "sim/solid/elasticity_peer2018.h"
#include "sim/solid/fixed_particles.h"
#include "sim/world/pipeline.h"

namespace sim::testing {

// A pressure solver that does nothing: solid-only scenes test the elastic stage alone, without
// a fluid incompressibility constraint acting on the solid's particles.
class NoPressureSolver final : public PressureSolver {
 public:
  std::string_view name() const override { return "none"; }
  void attach(World&) override {}
  void beginStep(World&, const StepContext&) override {}
  void correctVelocities(World&, const StepContext&) override {}
};

inline Material elasticMaterial(const char* name, Real density, Real youngsModulus,
                                Real poissonRatio) {
  Material m;
  m.name = name;
  m.kind = MaterialKind::kElastic;
  m.restDensity = density;          // [kg/m^3]
  m.youngsModulus = youngsModulus;  // [Pa]
  m.poissonRatio = poissonRatio;    // [1]
  return m;
}

// Cell-centred lattice of `counts` particles starting at `min` [m], spacing d [m], mass rho0 d^3.
inline void addLattice(World& world, const Vec3& min, const Eigen::Vector3i& counts, Real d,
                       int materialIndex, const Vec3& velocity = Vec3::Zero()) {
  const Real mass = world.materials[materialIndex].restDensity * d * d * d;
  for (int i = 0; i < counts.x(); ++i)
    for (int j = 0; j < counts.y(); ++j)
      for (int k = 0; k < counts.z(); ++k)
        world.particles.add(min + d * Vec3(i + 0.5, j + 0.5, k + 0.5), velocity, mass,
                            materialIndex);
}

inline WorldParameters solidWorldParameters(Real d, const Box& domain, const Vec3& gravity) {
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = domain;
  params.gravity = gravity;
  return params;
}

// Gravity + elasticity on a solver that does nothing, attached to `world`.
inline Pipeline solidPipeline(World& world, const ElasticityParameters& parameters = {}) {
  std::vector<std::unique_ptr<Effect>> effects;
  if (world.gravity.norm() > 0) effects.push_back(std::make_unique<Gravity>());
  effects.push_back(std::make_unique<ElasticityPeer2018>(parameters));
  Pipeline pipeline(std::make_unique<NoPressureSolver>(), std::move(effects), {});
  pipeline.attach(world);
  return pipeline;
}

inline const ElasticityPeer2018& elasticStage(const Pipeline& pipeline) {
  for (const auto& e : pipeline.effects())
    if (e->name() == "elasticity") return static_cast<const ElasticityPeer2018&>(*e);
  throw SimError("no elasticity stage");
}

}  // namespace sim::testing
