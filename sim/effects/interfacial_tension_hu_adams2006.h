// Interfacial tension between two liquids from the physical sigma [N/m], in the surface-stress
// form of Hu & Adams 2006 ("A multi-phase SPH method for macroscopic and mesoscopic flows",
// J. Comput. Phys. 213:844, eqs. 14-16), which builds on the continuum surface stress of
// Lafaurie et al. 1994:
//   colour        C = 1 on material A, 0 on material B of each pair with sigma_AB > 0
//   gradient      gradC_i = sum_j V_j (C_j - C_i) gradW_ij   (+ the wall part, see below)
//   stress        Pi_i = sigma (|gradC|/D I - gradC gradC^T / |gradC|),   D = 3
//   acceleration  a_i += 1/m_i sum_j V_i V_j (Pi_i + Pi_j) gradW_ij,   V = m / rho
// Why this form rather than CSF (Brackbill 1992, Morris 2000): the pair term is antisymmetric,
// so the tension conserves linear momentum exactly (a droplet cannot propel itself) and it needs
// no curvature, i.e. no second derivative of a noisy colour field and no filtering of particles
// with small |gradC|. Across an interface the normal stress integrates to the Young-Laplace jump
// 2 sigma / R (tests/sim/interface_laplace.cpp checks it); the isotropic part sigma|gradC|/D
// only changes pressure inside the diffuse layer, not the jump between the bulk phases.
//
// Walls: the pair sum is mirrored onto wall particles b (stress Pi_b = R Pi_i R, the reflection of
// Pi_i about the local wall plane; volume the Akinci 2012 boundary volume), so a uniform stress
// near a wall exerts no spurious force, just as the Akinci pressure mirror does. Walls do not
// enter gradC: a wall is a neutral (90 deg) mirror; the wall_adhesion stage
// (wall_adhesion_young.h) adds the wall interface energies that set another contact angle.
//
// Time step: the capillary-wave limit dt <= sqrt(rho_avg d^3 / (2 pi sigma)) (Brackbill, Kothe
// & Zemach 1992, J. Comput. Phys. 100:335, eq. 61), with rho_avg the mean of the pair's rest
// densities.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/effects/effect.h"

namespace sim {

namespace field {
// [1/m] colour gradient of the first tension pair (the diffuse interface normal times delta).
inline constexpr const char* kColourGradient = "colour_gradient";
}  // namespace field

class InterfacialTensionHuAdams2006 final : public Effect {
 public:
  std::string_view name() const override { return "interfacial_tension"; }
  void attach(World& world) override;
  void apply(World& world, const StepContext& context) override;
  Real maxTimeStep(const World& world) const override;

 private:
  std::vector<Vec3>* colourGradient_ = nullptr;  // [1/m] output field of the first pair
  std::vector<Mat3> stress_;                      // [Pa] scratch: Pi of each particle
  std::vector<Vec3> gradient_;                    // [1/m] scratch gradC for the current pair
  std::vector<std::uint8_t> stressed_;            // scratch: 1 where Pi is set (else Pi = 0)
};

}  // namespace sim
