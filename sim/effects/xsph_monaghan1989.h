// XSPH velocity smoothing (Monaghan 1989, J. Comput. Phys. 82:1-15): every particle is pulled
// towards the kernel-weighted mean velocity of its neighbours,
//   a_i = (eps/dt) sum_j 2 m_j / (rho_i + rho_j) (v_j - v_i) W_ij,
// the form SPlisHSPlasH applies as a non-pressure force. Each pair term is equal and opposite, so
// linear momentum is conserved. It is numerical dissipation, not physics: it removes the
// particle-scale velocity noise that an incompressible solver leaves near walls when the physical
// viscosity is too small at the resolution to damp it (a water tank at d = 5 mm has a particle
// Reynolds number far above 1). eps = 0 switches it off.
// Fluid particles only, among fluid neighbours only: an elastic particle is not smoothed (it would
// damp the solid's rigid rotation and vibration), and a fluid particle ignores elastic neighbours
// as it ignores wall particles — a pull towards the solid's velocity without the equal and
// opposite one on the solid would leak momentum (docs/elasticity.md).
#pragma once

#include "sim/effects/effect.h"

namespace sim {

class XsphMonaghan1989 final : public Effect {
 public:
  explicit XsphMonaghan1989(Real strength) : strength_(strength) {
    require(strength >= 0 && strength <= 0.5, "XSPH strength must be in [0, 0.5]");
  }
  std::string_view name() const override { return "velocity_smoothing"; }
  void apply(World& world, const StepContext& context) override {
    auto& p = world.particles;
    const NeighborList& nf = world.fluidNeighbors();
    const Kernel& kernel = world.kernel;
    const Real scale = strength_ / context.dt;
    const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
      if (!world.materials.isFluid(p.material[i])) continue;
      Vec3 a = Vec3::Zero();
      for (const Index* j = nf.begin(i); j != nf.end(i); ++j)
        if (world.materials.isFluid(p.material[*j]))
          a += (2.0 * p.mass[*j] / (p.density[i] + p.density[*j]) * kernel.W(p.x[i] - p.x[*j])) *
             (p.v[*j] - p.v[i]);
      p.a[i] += scale * a;
    }
  }

 private:
  Real strength_;  // [1] eps
};

}  // namespace sim
