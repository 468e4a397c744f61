// Divergence-free SPH (Bender & Koschier 2015, "Divergence-free smoothed particle hydrodynamics",
// SCA; extended in Bender & Koschier 2017, IEEE TVCG 23(3)): a constant-density solver and a
// divergence-free solver, both Jacobi-style local pressure updates on velocities, with warm start.
//
// Density is the ordinary mass-weighted one (fluid/density.h), so with several phases this is the
// "multiphase DFSPH" baseline of Wang et al. 2023. The stiffness factor is derived for unequal
// masses (docs/methods/solvers.md): alpha_i = rho_i / (|sum_j m_j gradW_ij + sum_b psi_b
// gradW_ib|^2
//                                              + m_i sum_j m_j |gradW_ij|^2),
// which reduces to Bender's factor when all masses are equal.
#pragma once

#include <vector>

#include "sim/core/reduction.h"
#include "sim/fluid/pressure_solver.h"

namespace sim {

struct DfsphParameters {
  Real densityTolerance = 1e-3;     // [1] stop when mean compression (rho*/rho0 - 1) falls below
  Real divergenceTolerance = 1e-3;  // [1] stop when mean dt * (Drho/Dt)/rho0 falls below
  Real maxErrorFactor = 10.0;       // [1] also iterate while max compression > factor * tolerance
  int minIterations = 2;
  int maxIterations = 100;
  int maxDivergenceIterations = 100;
  bool divergenceSolve = true;
  Real warmStartFactor = 0.5;           // [1] fraction of last step's pressure applied first
  bool warmStartOnlyCompressed = true;  // warm-start only particles predicted compressed
  // [1] Jacobi relaxation of each pressure update. The local update with the full factor
  // (omega = 1, Bender's choice) barely damps the checkerboard mode of the pressure field: the
  // residual left when the average-error criterion stops the iteration is particle-scale
  // velocity noise that makes a fluid at rest jitter near walls (docs/methods/solvers.md).
  Real relaxation = 1.0;
  Index minNeighborsForDivergence = 20;  // fewer: free-surface particle, skipped (Bender 2017)
};

class DfsphBender2017 final : public PressureSolver {
 public:
  explicit DfsphBender2017(const DfsphParameters& parameters = {});
  std::string_view name() const override { return "dfsph"; }
  void attach(World& world) override;
  void beginStep(World& world, const StepContext& context) override;
  void correctVelocities(World& world, const StepContext& context) override;

 private:
  // v_i -= dt * (sum_j m_j (k_i/rho_i + k_j/rho_j) gradW_ij + sum_b psi_b k_i/rho_i gradW_ib)
  void applyPressureVelocity(World& world, const std::vector<Real>& kappa, Real dt);
  // Predicted density rho* (densityOnly) or density rate Drho/Dt; returns the mean error measure.
  Real predictDensity(World& world, Real dt);
  Real computeDensityRate(World& world);
  // Drho_i/Dt = sum_j m_j (v_i - v_j).gradW_ij + v_i.wallGradient_i (cached gradients).
  Real densityRate(const World& world, Index i) const;
  Real maxCompression(const World& world) const;  // of the current prediction
  // beginStep() in steps (neither allocates).
  void stiffnessFactors(const World& world, bool divergence);
  void solveDivergence(World& world, Real dt);

  DfsphParameters params_;
  std::vector<Real>* factor_ = nullptr;        // alpha_i [kg s^2... see header] (not checkpointed)
  std::vector<Real>* pressure_ = nullptr;      // [Pa] last step's pressure, output
  std::vector<Real>* kappaDensity_ = nullptr;  // [m^2/s^2] accumulated stiffness p/rho, warm start
  std::vector<Real>* kappaDivergence_ = nullptr;  // [m^2/s^2] accumulated for warm start
  std::vector<Real> predicted_;                   // rho* or Drho/Dt per particle (scratch)
  std::vector<Real> kappa_;                       // this iteration's k_i (scratch)
  std::vector<Real> densityWarmStart_;            // [m^2/s^2] last accepted step's kappa (scratch)
  std::vector<Real> kappaOverRho_;                // [m^5/(kg s^2)] k_i / rho_i (scratch)
  // [kg/m^4] rho0_i sum_b V_b gradW_ib per particle, fixed for a step (walls are static and the
  // positions do not move during the solves): every wall term of both solves is this vector times
  // a per-particle scalar, so the iterations never loop over wall pairs (scratch).
  std::vector<Vec3> wallGradient_;
  Real divergenceDt_ = 0;  // [s] dt the divergence solve used this step
  DeterministicReducer reducer_;
};

}  // namespace sim
