// Gravity (or any uniform body acceleration): a_i += g, with g the World's current gravity, which
// the scenario runner turns as the posture changes (docs/developer-guide.md principle 2).
#pragma once

#include <vector>

#include "sim/effects/effect.h"

namespace sim {

class Gravity final : public Effect {
 public:
  std::string_view name() const override { return "gravity"; }
  void apply(World& world, const StepContext&) override {
    auto& a = world.particles.a;
    const Vec3 g = world.gravity;
    const std::size_t n = a.size();
    if (world.gravityReferenceDensity <= 0) {
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) a[i] += g;
      return;
    }
    // Per material: g (1 - rho_ref / rho_m) (World::gravityReferenceDensity).
    factor_.resize(static_cast<std::size_t>(world.materials.size()));
    for (int m = 0; m < world.materials.size(); ++m)
      factor_[static_cast<std::size_t>(m)] =
          1.0 - world.gravityReferenceDensity / world.materials[m].restDensity;
    const auto& material = world.particles.material;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) a[i] += factor_[static_cast<std::size_t>(material[i])] * g;
  }

 private:
  std::vector<Real> factor_;  // [1] per material, reused (no allocation once sized)
};

}  // namespace sim
