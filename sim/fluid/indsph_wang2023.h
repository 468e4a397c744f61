// Incompressible number-density SPH, INDSPH (Wang et al. 2023, "An incompressible number density
// SPH for high density ratio multiphase fluid", sections 4.1-4.2, Algorithm 1): a DFSPH-style local
// pressure solve on the NUMBER density delta_i = sum_j W_ij instead of the mass density, so a
// particle's neighbours count the same whatever their mass and a heavy/light interface does not
// read as compressed (the error of paper section 3.3). Derivation in docs/solvers.md.
//
//   delta_i   = W_0 + sum_j W_ij + sum_b (V_b / V0_i) W_ib        (eq. 6, walls: Akinci 2012)
//   delta*_i  = delta_i + dt sum_j (v_i - v_j).gradW_ij + dt sum_b (V_b/V0_i) v_i.gradW_ib (eq. 15)
//   kappa_i   = omega delta_i (delta*_i - delta0_i) / (dt^2 (|G_i|^2/m_i + sum_j |gradW_ij|^2/m_j))
//                                                                     (eqs. 17-18, see docs)
//   dv_i      = -dt/m_i (kappa_i/delta_i G_i + sum_j kappa_j/delta_j gradW_ij)   (eqs. 19-20)
// with G_i = sum_j gradW_ij + sum_b (V_b/V0_i) gradW_ib and delta0_i = 1/V0_i = rho0_i/m_i
// (eq. 16). The output pressure is p_i = kappa_i delta_i.
//
// Walls are Akinci 2012 surface particles acting with the fluid particle's own stiffness
// (pressure mirroring), not the paper's static particles with their own kappa (eq. 21): eq. 21
// needs a wall sampled as a volume at the fluid's spacing, with a rest number density; a single
// surface layer with Akinci volumes has none (its wall-only sum already equals the rest value).
// Optionally a divergence-free pass in the same number-density form precedes each step.
#pragma once

#include <vector>

#include "sim/core/reduction.h"
#include "sim/fluid/pressure_solver.h"

namespace sim {

struct IndsphParameters {
  Real tolerance = 1e-4;        // [1] eta: stop when mean (delta*/delta0 - 1) < eta (paper: 1e-4)
  int minIterations = 2;
  int maxIterations = 100;
  // [1] omega of each Jacobi update. With mixed masses a light particle is pushed by all its
  // heavy neighbours' stiffnesses at once, each computed as if it acted alone; full steps
  // (omega = 1) overshoot and at 1:75 threw particles through the floor after 0.3 s of the
  // two-phase dam break (cfl 0.15). 0.5, IISPH's relaxation, ran 1 s at 1:2...1:75 (2026-11-22).
  Real relaxation = 0.5;
  Real warmStartFactor = 0.5;   // [1] fraction of last accepted step's kappa applied first
  // Divergence-free pass (not in the paper; DFSPH's second solve in number-density form). On the
  // 4 x 8 cm tank at rest (omega 0.5) it lowers the final kinetic energy 3x (1.6e-6 vs 4.8e-6 J)
  // and the hydrostatic error (1.0 % vs 1.9 %); on the dam break it converges in one iteration
  // and changes nothing measurable (docs/solvers.md).
  bool divergenceSolve = true;
  Real divergenceTolerance = 1e-3;  // [1] stop when mean dt (D delta/Dt)/delta0 falls below
  int minNeighborsForDivergence = 20;  // particles with fewer (free surface) are left alone
};

class IndsphWang2023 final : public PressureSolver {
 public:
  explicit IndsphWang2023(const IndsphParameters& parameters = {});
  std::string_view name() const override { return "indsph"; }
  void attach(World& world) override;
  void beginStep(World& world, const StepContext& context) override;
  void correctVelocities(World& world, const StepContext& context) override;

 private:
  Real predictNumberDensity(World& world, Real dt);  // fills predicted_, returns mean compression
  Real numberDensityRate(const World& world, Index i) const;  // D delta_i / Dt, eq. 14 [1/(m^3 s)]
  void solveDivergence(World& world, Real dt);
  void applyPressureVelocity(World& world, const std::vector<Real>& kappa, Real dt);

  IndsphParameters params_;
  std::vector<Real>* numberDensity_ = nullptr;  // [1/m^3] delta_i (output)
  std::vector<Real>* pressure_ = nullptr;       // [Pa] p = kappa delta (output)
  std::vector<Real>* kappa_ = nullptr;          // [Pa m^3] accumulated kappa, warm start
  std::vector<Real> diagonal_;                  // [m^-8 kg^-1] |G|^2/m_i + sum |gradW|^2/m_j
  std::vector<Real> predicted_;                 // [1/m^3] delta* (scratch)
  std::vector<Real> increment_;                 // [Pa m^3] this iteration's kappa (scratch)
  std::vector<Real> warmStart_;                 // [Pa m^3] last accepted step's kappa (scratch)
  DeterministicReducer reducer_;
};

// Number density with Akinci wall terms (eq. 6), shared with the explicit number-density solver.
void computeNumberDensities(const World& world, std::vector<Real>& delta);

}  // namespace sim
