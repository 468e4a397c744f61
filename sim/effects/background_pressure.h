// Background pressure for the surface stress in a closed incompressible scene.
//
// Why: the surface stress of the interfacial_tension stage (Hu & Adams 2006) is a tension along
// the interface, sigma |gradC| / 3 per unit area, i.e. a negative pressure tangentially. A
// particle method under a net tension clumps (the tensile instability): the interface particles
// rearrange so that the colour gradient collapses. Measured on the Laplace droplet under INDSPH
// (d = R/6, no background): sum V |gradC| fell from 1.04 to 0.51 of the sphere's area within a
// capillary time and the pressure jump with it, from 1.0 to 0.3 of 2 sigma / R, while the
// solver's projection itself is exact (an analytic radial gradient force gave 0.95 of its jump).
// Hu & Adams keep the total pressure positive with a background pressure in their equation of
// state (WCSPH here gets one from the test's 5 % mass excess, ~200 Pa, and reads 0.95). An
// incompressible solver has no such offset: its pressure is the Lagrange multiplier of the
// density constraint, zero at rest.
//
// What: the background pressure of the transport-velocity formulation (Adami, Hu & Adams 2013,
// J. Comput. Phys. 241:292, eq. 14): particles are advected with v + dv instead of v,
//   dv_i = -(dt p_bg / (rho_ref V_i)) [ sum_j (V_i^2 + V_j^2) gradW_ij
//                                       + 2 V_i^2 sum_b (V_b / V0_i) gradW_ib ],
// V = m / rho (= 1 / delta under INDSPH), walls mirrored at p_bg as the Akinci pressure mirror
// does, rho_ref the mean rest density of the tension pair. Adami et al. divide by m_i, i.e. by
// the particle's own density (they had one phase): then the shift of a phase scales with 1 /
// rho, which is no physics (the shift is not a force) and made the contact angle depend on the
// droplet's density. A 150 deg droplet at zero gravity (R0/8, from its cap, 0.6 s, mean of the
// last fifth) read 146.9 at 970 kg/m^3 and 164.0 at 1760 (swinging 158-167) with m_i; with
// rho_ref V_i, 147.2 and 148.9 (docs/methods/interface.md, validation 3). rho_ref is also
// the density of the time-step limit below, which therefore now holds for every phase (with m_i
// a phase lighter than the mean was shifted faster than the limit assumed). The bracket is the
// kernel's consistency error, zero on a complete regular neighbourhood, so dv only moves particles
// towards a uniform arrangement, against the clumping; the momentum equation does not see it (the
// formulation's extra stress rho v (v~ - v) is of second order in dv and left out). Why not in the
// momentum equation: tried first, the same bracket as a force. It held the jump as well, but it
// resists every rearrangement of the particles like an elastic lattice: the l = 2 droplet ran 22 %
// fast and damped at 45 1/s (physical 4), and in the eye (default_eye.toml, upright) the oil rose
// to the superior quadrant 4x slower (coverage 0.66 -> 0.675 instead of -> 0.805 in 0.6 s): the
// pinning of slow buoyant motion that the gravity reference removed (docs/methods/interface.md,
// validation 1b). Contact-line particles (a wall neighbour and a colour gradient of the first
// tension pair) are not shifted: there the shift moved the contact line itself (the cavity's 120
// deg lens covered 0.208 of the wall instead of 0.225; unshifted 0.228-0.234;
// docs/methods/interface.md, validation 3). At a free surface the shift would pull the surface in,
// so the stage runs only in closed scenes (rule in stage_registry.cpp). Fluid particles only:
// elastic particles carry their own stress, and a fluid particle next to tissue counts the tissue
// particles as neighbours, so its bracket stays complete.
//
// How large: p_bg = kBackgroundPressurePerTension sigma / d (the tension's scale: |gradC| ~ 1/d).
// Time step: dt <= kBackgroundCourant h / c_bg, c_bg = sqrt(p_bg / rho), h the kernel support
// radius (2 d). Measured with the force form on the same droplet (R = 3 mm, sigma 0.04 N/m,
// d = 0.5 mm): c_bg dt / h = 0.20 calm (max speed 4-6 mm/s) for p_bg = 1, 2 and 3 sigma / d; 0.28
// agitated (0.1-0.2 m/s); 0.44 unstable (docs/methods/interface.md). The transport form was run at
// this limit only; its own stability bound was not measured.
#pragma once

#include <vector>

#include "sim/effects/effect.h"

namespace sim {

namespace field {
// [m/s] transport-velocity correction dv: Pipeline::step integrates x += dt (v + dv) when the
// field exists (written by background_pressure each step).
inline constexpr const char* kTransportShift = "transport_shift";
}  // namespace field

// [1] p_bg in units of sigma / d. Laplace droplet under INDSPH (d = R/6) at the step limit, jump
// over 2 sigma / R after the first 10 ms: 1 -> 0.72, 1.5 -> 0.82, 2 -> 0.86, 4 -> 0.83, 8 -> 0.70
// (2 at R/8: 0.88-0.90; docs/methods/interface.md, validation 1b).
inline constexpr Real kBackgroundPressurePerTension = 2.0;
// [1] c_bg dt / h at the stage's time-step limit (measured, see above).
inline constexpr Real kBackgroundCourant = 0.2;

class BackgroundPressure final : public Effect {
 public:
  // pressure [Pa] > 0; referenceDensity [kg/m^3] > 0: rho_ref of the shift and the time-step limit.
  BackgroundPressure(Real pressure, Real referenceDensity);
  std::string_view name() const override { return "background_pressure"; }
  void attach(World& world) override;
  // Writes dv into the transport_shift field (does not touch the accelerations).
  void apply(World& world, const StepContext& context) override;
  Real maxTimeStep(const World& world) const override;
  Real pressure() const { return pressure_; }

 private:
  Real pressure_;                       // [Pa]
  Real referenceDensity_;               // [kg/m^3]
  std::vector<Vec3>* shift_ = nullptr;  // [m/s] the transport_shift field
};

// The background pressure an interfacial tension calls for [Pa]:
// kBackgroundPressurePerTension sigma / d.
Real backgroundPressureFor(const World& world, const InterfacialTension& tension);

// Fluid particles away from walls whose kernel support is not filled at the current state
// (number density below `fraction` of the rest value): a free surface. 0 in a closed scene.
// 0.9: the top layer of a lattice under a free surface has 0.85 of the rest number density
// (cubic spline, support 2 d), the bulk of a closed fill 0.95-1. Particles with wall neighbours
// are not counted: an Akinci wall leaves the corners of a closed box below 0.9 (8 particles in
// the droplet box of the tests), and a free surface lies mostly away from walls.
std::size_t countFreeSurfaceParticles(const World& world, Real fraction = 0.9);

}  // namespace sim
