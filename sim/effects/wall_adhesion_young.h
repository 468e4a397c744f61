// Wall wetting with a contact angle theta per (fluid, wall tag), the model parameter derived from
// Young's relation, no per-scene tuning.
//
// The wall takes part in the diffuse interface of interfacial_tension
// (interfacial_tension_hu_adams2006.h) with a fixed colour c_w. In that model the energy of an
// interface across which the colour changes by |dC| is sigma |dC| per unit area, so a wall of
// colour c_w has the interface energies gamma_wA = sigma (1 - c_w) against phase A (C = 1) and
// gamma_wB = sigma c_w against phase B (C = 0). Young's relation measured through A,
//   sigma cos(theta_A) = gamma_wB - gamma_wA = sigma (2 c_w - 1),
// gives the wall colour
//   c_w = (1 + cos theta_A) / 2,
// which depends on theta only (sigma cancels). Each step this stage writes the wall part of the
// colour gradient, sum_b V_b (c_w - C_i) gradW_ib over the walls with a contact angle, into the
// field "wall_colour_gradient"; interfacial_tension adds it to the fluid part before forming the
// stress, so the interface normal near the wall turns toward the angle Young's relation asks
// for (the discrete counterpart of the wall boundary condition on the normal in Brackbill,
// Kothe & Zemach 1992, section 2.3, without choosing a contact-line region by hand). Walls of
// tags without a contact angle contribute nothing: they act as a neutral (90 deg) mirror.
//
// The angle given is measured through the fluid named in ContactAngle; the toolkit's clinical
// convention (DESIGN.md) names the aqueous phase. Only one tension pair may have contact angles
// (the scene's oil-aqueous pair); it must be the first pair of the MaterialTable.
#pragma once

#include <vector>

#include "sim/effects/effect.h"

namespace sim {

class WallAdhesionYoung final : public Effect {
 public:
  std::string_view name() const override { return "wall_adhesion"; }
  void attach(World& world) override;
  void apply(World& world, const StepContext& context) override;

  // c_w for a contact angle theta [deg] measured through the phase of colour 1.
  static Real wallColour(Real thetaThroughColourOne);

 private:
  std::vector<Real> wallColour_;  // [1] per wall particle; NaN where the wall has no angle
  int materialA_ = -1, materialB_ = -1;  // the pair; A has colour 1
  std::vector<Vec3>* wallGradient_ = nullptr;  // [1/m]
};

}  // namespace sim
