// Interfacial tension between two liquids from the physical sigma [N/m], in the surface-stress
// form of Hu & Adams 2006 ("A multi-phase SPH method for macroscopic and mesoscopic flows",
// J. Comput. Phys. 213:844, eqs. 14-16), which builds on the continuum surface stress of
// Lafaurie et al. 1994:
//   colour        C = 1 on material A, 0 on material B of each pair with sigma_AB > 0
//   gradient      gradC_i = L_i sum_j V_j (C_j - C_i) gradW_ij
//   stress        Pi_i = sigma (|gradC|/D I - gradC gradC^T / |gradC|),   D = 3
//   acceleration  a_i += 1/m_i sum_j V_i V_j (Pi_j - Pi_i) L_i gradW_ij      (corrected, default)
//                 a_i += 1/m_i sum_j V_i V_j (Pi_i + Pi_j) gradW_ij          (symmetric)
// with V = m / rho and L_i the kernel-gradient correction of Bonet & Lok 1999 (Comput. Methods
// Appl. Mech. Engrg. 180:97, eq. 46): L_i = (sum_j V_j gradW_ij (x_j - x_i)^T)^-1, which makes
// both sums exact for linear fields whatever the particle order.
//
// Why CSS rather than CSF (Brackbill 1992, Morris 2000): no curvature, i.e. no second derivative
// of a noisy colour field and no filtering of particles with small |gradC|. Across an interface
// the normal stress integrates to the Young-Laplace jump 2 sigma / R
// (tests/sim/interface_laplace.cpp); the isotropic part sigma|gradC|/D only changes pressure
// inside the diffuse layer, not the jump between the bulk phases.
//
// Why two forms. The symmetric pair sum of the paper conserves linear momentum exactly, but it
// is exact for a stress field only where sum_j V_j gradW_ij = 0, i.e. on an ordered lattice. The
// surface stress is tensile along the interface and rearranges the interface particles; there
// the symmetric form under-states the force: an INDSPH droplet held 0.84 of 2 sigma / R with the
// background pressure, the corrected form 0.97 (docs/methods/interface.md, validation 1c). The
// corrected (difference) form is first-order consistent on any particle order, at the price of a
// small momentum residual (measured 3-5e-4 of sum |f| on a relaxed jittered droplet; the droplet
// does not drift, tests/sim/interface_laplace.cpp). Cost: one more neighbour pass per interface
// particle (L_i is formed only where gradC or a neighbour's stress is not 0).
// The correction is used only in well-conditioned neighbourhoods (gradient_correction.h): with
// it applied wherever B was invertible, an INDSPH droplet at 1 mPa s blew up.
//
// Walls. The pair sum is mirrored onto wall particles b (stress Pi_b = R Pi_i R, the reflection
// of Pi_i about the local wall plane; volume the Akinci 2012 boundary volume), so a uniform
// stress near a wall exerts no spurious force, just as the Akinci pressure mirror does. In the
// corrected form the divergence's L_i includes the wall particles (the mirror completes the
// support), but gradC's does not: gradC next to a wall is the one-sided (fluid-only) corrected
// gradient of the fluid's own colour. The uncorrected sum instead reads the wall as carrying
// particle i's colour (a neutral, 90 deg, wall) and tilts the interface normal towards 90 deg
// there: sessile droplets requested at 30 / 150 deg settled at 35-39 / 138 deg, with the one-sided
// gradient at 31.6-33.4 / 142.6 (docs/methods/interface.md, validation 3). The wall_adhesion stage
// (wall_adhesion_young.h) adds the wall interface energies that set the contact angle.
//
// Time step: the capillary-wave limit dt <= sqrt(rho_avg d^3 / (2 pi sigma)) (Brackbill, Kothe
// & Zemach 1992, J. Comput. Phys. 100:335, eq. 61), with rho_avg the mean of the pair's rest
// densities.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "sim/effects/effect.h"

namespace sim {

namespace field {
// [1/m] colour gradient of the first tension pair (the diffuse interface normal times delta).
inline constexpr const char* kColourGradient = "colour_gradient";
}  // namespace field

enum class SurfaceStressForm {
  kAuto,       // chosen by the pressure solver: resolveSurfaceStressForm
  kCorrected,  // Bonet-Lok corrected gradient and difference-form divergence
  kSymmetric,  // Hu & Adams 2006 as published: momentum-exact pair sum, neutral-wall gradient
};

// Protocol / plan name of each form ("auto", "corrected", "symmetric").
std::string_view surfaceStressFormName(SurfaceStressForm form);
// The inverse: kAuto for "auto" and for any other name.
SurfaceStressForm surfaceStressFormFromName(std::string_view name);

// kAuto: symmetric under WCSPH, whose positive pressure at rest keeps the particles near a
// lattice, where the symmetric sum is exact (measured there: Laplace -5.5 % against -8.5 %
// corrected, l = 2 period -4 % against -9.5 %); corrected under the incompressible solvers, whose
// pressure is zero at rest and whose interface particles disorder (INDSPH Laplace -16 % symmetric,
// -3.4 % corrected). DFSPH, IISPH and number_density were not measured; they share INDSPH's zero
// pressure at rest.
SurfaceStressForm resolveSurfaceStressForm(SurfaceStressForm requested, std::string_view solver);

class InterfacialTensionHuAdams2006 final : public Effect {
 public:
  // `form` kAuto is taken as kCorrected; the pipeline resolves it by solver first.
  explicit InterfacialTensionHuAdams2006(SurfaceStressForm form = SurfaceStressForm::kCorrected)
      : form_(form == SurfaceStressForm::kAuto ? SurfaceStressForm::kCorrected : form) {}
  std::string_view name() const override { return "interfacial_tension"; }
  void attach(World& world) override;
  void apply(World& world, const StepContext& context) override;
  Real maxTimeStep(const World& world) const override;
  SurfaceStressForm form() const { return form_; }

 private:
  // apply() per pair of materials, in two passes over the particles (neither allocates).
  void surfaceStress(const World& world, const InterfacialTension& pair);
  void stressDivergence(World& world, const InterfacialTension& pair);
  // Per particle i of stressDivergence(): its pair sums and the walls' mirrored stress.
  bool addCorrectedPairForce(const World& world, Index i, Real vi, Mat3& correction, Vec3& f) const;
  void addSymmetricPairForce(const World& world, Index i, Real vi, Vec3& f) const;
  void addMirroredStressForce(const World& world, Index i, Real vi, const Mat3& correction,
                              bool elastic, Vec3& f) const;

  SurfaceStressForm form_;
  std::vector<Vec3>* colourGradient_ = nullptr;  // [1/m] output field of the first pair
  std::vector<Mat3> stress_;                     // [Pa] scratch: Pi of each particle
  std::vector<Vec3> gradient_;                   // [1/m] scratch gradC for the current pair
  std::vector<std::uint8_t> stressed_;           // scratch: 1 where Pi is set (else Pi = 0)
};

}  // namespace sim
