// Explicit laminar viscosity (Monaghan 2005, Rep. Prog. Phys. 68:1703, eq. 6.13 form as used by
// Morris et al. 1997 for Poiseuille flow), for water-like fluids:
//   a_i += 2(d+2) sum_j m_j mu_ij / (rho_i rho_j) (v_ij . x_ij) / (|x_ij|^2 + 0.01 h^2) gradW_ij
// with d = 3 and mu_ij the mean dynamic viscosity of the pair. Every pair force is equal and
// opposite (m_i a_i = -m_j a_j term by term), so linear momentum is conserved to round-off.
// Walls act as no-slip particles at rest with volume V_b (Akinci 2012). Elastic particles act as
// walls moving with the solid (the pair term with the fluid's viscosity) and take the equal and
// opposite force; elastic-elastic pairs are left to the elastic stage. Explicit: stable only for
// dt <= kStableStepFactor d^2 / nu (viscous diffusion limit); viscous oils need the implicit
// solver.
#pragma once

#include "sim/effects/effect.h"
#include "sim/effects/xsph_monaghan1989.h"

namespace sim {

class ViscosityMonaghan2005 final : public Effect {
 public:
  // dt <= kStableStepFactor d^2/nu. The classic 0.125 (Morris et al. 1997) is NOT stable for this
  // operator at h = 2d: power iteration on it (1500-particle oil block, d = 2 mm) gives a largest
  // stable step of 0.97 x 0.125 d^2/nu with tank walls and 0.80 x without
  // (docs/methods/viscosity.md). 0.08 keeps a margin below the measured 0.1.
  static constexpr Real kStableStepFactor = 0.08;

  explicit ViscosityMonaghan2005(bool wallFriction = true) : wallFriction_(wallFriction) {}
  std::string_view name() const override { return "viscosity"; }
  void attach(World& world) override;
  void apply(World& world, const StepContext& context) override;
  Real maxTimeStep(const World& world) const override;
  // Computes XSPH velocity smoothing (Monaghan 1989) in this stage's neighbour loop, one pass
  // over the pairs instead of two, and switches the separate stage off. Only valid when `xsph`
  // is the next explicit stage (Pipeline::attach checks): the two accelerations are then added
  // in the same order as by the two stages, so the result is bit-identical.
  void absorbSmoothing(XsphMonaghan1989& xsph) {
    smoothing_ = xsph.strength();
    xsph.setFused(true);
  }

 private:
  template <bool kSmoothing>
  void applyImpl(World& world, const StepContext& context);
  Vec3 elasticReaction(const World& world, Index i, Real h2) const;  // per particle, no allocation

  bool wallFriction_;
  Real smoothing_ = 0;                     // [1] XSPH eps computed here (0: none)
  std::vector<Real> viscosityOfMaterial_;  // [Pa s]
  // [Pa s] per particle, refreshed each apply (-1: elastic); resized only when the count grows.
  std::vector<Real> viscosity_;
};

}  // namespace sim
