// XSPH velocity smoothing (Monaghan 1989, J. Comput. Phys. 82:1-15): every particle is pulled
// towards the kernel-weighted mean velocity of its neighbours,
//   a_i = (eps/dt) sum_j 2 m_j / (rho_i + rho_j) (v_j - v_i) W_ij,
// the form SPlisHSPlasH applies as a non-pressure force. Each pair term is equal and opposite, so
// linear momentum is conserved. It is numerical dissipation, not physics: it removes the
// particle-scale velocity noise that an incompressible solver leaves near walls when the physical
// viscosity is too small at the resolution to damp it (a water tank at d = 5 mm has a particle
// Reynolds number far above 1). eps = 0 switches it off.
// Fluid particles only, among neighbours of the same material only (pairs stay equal and opposite):
// - an elastic particle is not smoothed (it would damp the solid's rigid rotation and vibration),
//   and a fluid particle ignores elastic neighbours as it ignores wall particles
//   (docs/methods/elasticity.md);
// - across a fluid-fluid interface the smoothing is an artificial drag between the phases: with it,
//   a 970 kg/m^3 blob in water rose 0.33 mm instead of 1.14 mm in 0.3 s, and finer spacing did not
//   help (docs/methods/interface.md, validation 6), so each phase is smoothed on its own.
#pragma once

#include "sim/effects/effect.h"

namespace sim {

class XsphMonaghan1989 final : public Effect {
 public:
  explicit XsphMonaghan1989(Real strength) : strength_(strength) {
    require(strength >= 0 && strength <= 0.5, "XSPH strength must be in [0, 0.5]");
  }
  std::string_view name() const override { return "velocity_smoothing"; }
  Real strength() const { return strength_; }
  // Set by Pipeline::attach when the explicit viscosity stage directly before this one computes
  // the smoothing in its own neighbour loop (ViscosityMonaghan2005::absorbSmoothing); apply() then
  // does nothing.
  void setFused(bool fused) { fused_ = fused; }
  bool fused() const { return fused_; }
  void apply(World& world, const StepContext& context) override {
    if (fused_) return;
    auto& p = world.particles;
    const NeighborList& nf = world.fluidNeighbors();
    const Kernel& kernel = world.kernel;
    const Real scale = strength_ / context.dt;
    const Index n = static_cast<Index>(p.size());
    const std::vector<PairValue>& cachedW = world.fluidKernelValues();
    const PairValue* cache = cachedW.size() == nf.indices.size() ? cachedW.data() : nullptr;
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
      if (!world.materials.isFluid(p.material[i])) continue;
      Vec3 a = Vec3::Zero();
      for (Index k = nf.offsets[i]; k < nf.offsets[i + 1]; ++k) {
        const Index j = nf.indices[k];
        if (p.material[j] != p.material[i]) continue;
        a += pairTerm(p, i, j, pairValue(cache, k, [&] { return kernel.W(p.x[i] - p.x[j]); }));
      }
      p.a[i] += scale * a;
    }
  }
  // One pair's term of the sum (before the factor eps/dt); w = W(x_i - x_j) as the pair cache holds
  // it (sim/neighbors/pair_precision.h), cached or evaluated, so the result is the same to the bit.
  static Vec3 pairTerm(const DynamicParticles& p, Index i, Index j, Real w) {
    return (2.0 * p.mass[j] / (p.density[i] + p.density[j]) * w) * (p.v[j] - p.v[i]);
  }

 private:
  Real strength_;  // [1] eps
  bool fused_ = false;
};

}  // namespace sim
