// Variable smoothing length SPH, VSLSPH (Li, Li, Meng, Zhu & Zhang 2023, "An efficient
// non-iterative smoothed particle hydrodynamics fluid simulation method with variable smoothing
// length", Vis. Comput. Ind. Biomed. Art 6:1): an explicit pressure solver whose particles each
// carry a support radius h_i (the paper's "smoothing length", the kernel's support), updated once
// per step from the density without iteration so that the mass in every particle's support stays
// that of the rest state (eq. 8, sigma h^D rho = m_sum). Derivation and validation:
// docs/methods/solvers.md, "VSLSPH".
//
//   rho_i  = m_i delta_i,  delta_i = W_ii + sum_j Wbar_ij + sum_b (V_b / V0_i) Wbar_ib    (eq. 2)
//   Wbar_ij = (W(x_ij, h_i) + W(x_ij, h_j)) / 2                      (eq. 17, kernel average)
//   p_i    = max(k_i (rho_i / rho0_i - 1), 0),  k_i = rho0_i c^2      (eq. 18's state equation)
//   a_i    = -1/rho_i [ sum_j (p_i + p_j)/delta_j gradWbar_ij + p_i sum_b V_b gradWbar_ib ]
//            + Monaghan artificial viscosity                          (eq. 17 divided by m_i)
//   h_i'   = clamp([1 - (rho_i / rho0_i - 1) / D] h, f_min h, f_max h),  D = 3      (eq. 16)
//   dt    <= C d / c                                  (acoustic CFL; the paper states no rule)
//
// Departures from the paper, each for a stated reason:
// - density is the number-density form m_i sum_j W (Solenthaler & Pajarola 2008, Wang et al. 2023
//   eq. 6) rather than sum_j m_j W: identical for equal masses (the paper's single fluid), and a
//   light phase next to a heavy one does not read as compressed (the engine's two-phase rule);
//   V_i = 1/delta_i in eq. 17;
// - negative pressures are clamped to zero (free surface), as the engine's WCSPH does;
// - wall particles (Akinci 2012) carry the fixed support h and no pressure of their own (p_b = 0),
//   Akinci's wall force as in WCSPH;
// - eq. 16's reference state: rho0 goes with the rest support h (eq. 8 linearised about the rest
//   state, Fig. 1's "default value h"), so h_i' = [1 - (rho_i/rho0 - 1)/D] h. Read with the
//   previous step's h_i instead, the correction compounds every step (a free-surface particle,
//   whose density stays below rest, grows its h geometrically): the settling column blew up in
//   0.02 s that way (docs/methods/solvers.md);
// - h_i is clamped to [f_min, f_max] h; by default f_min = 1: letting h shrink below the kernel's
//   support where the fluid is compressed (f_min = 0.9) left the settling column 100x more kinetic
//   energy after 0.37 s (2.7e-4 vs 3.1e-6 J);
// - a Monaghan artificial viscosity (as in WCSPH) instead of eq. 18's Laplacian viscosity: the
//   engine's viscosity stages add the physical viscosity with the fixed support.
#pragma once

#include <vector>

#include "sim/core/reduction.h"
#include "sim/fluid/pressure_solver.h"

namespace sim {

struct VslsphParameters {
  // [m/s] numerical speed of sound c of the state equation (k = rho0 c^2); 0: the scene's WCSPH
  // speed of sound (PipelineOptions::wcsph), about 10x the flow speed (Becker & Teschner 2007).
  Real speedOfSound = 0.0;
  Real artificialViscosity = 0.05;  // [1] alpha of the Monaghan term, as WCSPH (0 disables)
  Real courantNumber = 0.4;         // [1] dt <= courant * d / c, as WCSPH
  // [1] range of h_i in units of the kernel's support h. The largest sets the neighbour grid's
  // cell width (search cost ~ f_max^3). Eq. 16 itself stays below 1 + 1/3: even an isolated
  // particle reads rho = m W(0) = 0.32 rho0 (cubic spline, h = 2d), i.e. h_i = 1.23 h, so 1.25
  // clips only the rare particle whose averaged kernel reads less than its own.
  // The smallest: 1 (see the file comment).
  Real minSupportFactor = 1.0;
  Real maxSupportFactor = 1.25;
};

class VslsphLi2023 final : public PressureSolver {
 public:
  explicit VslsphLi2023(const VslsphParameters& parameters);
  std::string_view name() const override { return "vslsph"; }
  void attach(World& world) override;
  void beginStep(World& world, const StepContext& context) override;
  void correctVelocities(World& world, const StepContext& context) override;
  Real maxTimeStep(const World& world) const override;

 private:
  void computeDensities(World& world);                           // eq. 2 with the kernel average
  void computePressuresAndSupports(World& world);                // state equation, eq. 16
  Vec3 pressureAcceleration(const World& world, Index i) const;  // eq. 17 / m_i, viscosity

  VslsphParameters params_;
  std::vector<Real>* support_ = nullptr;    // [m] h_i for the next neighbour update (checkpointed)
  std::vector<Real>* pressure_ = nullptr;   // [Pa]
  std::vector<Real> scale_;                 // [1] h / h_i this step (the lists were built with it)
  std::vector<Real> numberDensity_;         // [1/m^3] delta_i this step
  std::vector<Vec3> pressureAcceleration_;  // [m/s^2] scratch
  DeterministicReducer reducer_;
};

}  // namespace sim
