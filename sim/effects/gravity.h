// Gravity (or any uniform body acceleration): a_i += g, with g the World's current gravity, which
// the scenario runner turns as the posture changes (DESIGN.md principle 2).
#pragma once

#include "sim/effects/effect.h"

namespace sim {

class Gravity final : public Effect {
 public:
  std::string_view name() const override { return "gravity"; }
  void apply(World& world, const StepContext&) override {
    auto& a = world.particles.a;
    const Vec3 g = world.gravity;
    const std::size_t n = a.size();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) a[i] += g;
  }
};

}  // namespace sim
