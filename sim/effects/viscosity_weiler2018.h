// Implicit viscosity (Weiler, Koschier, Brand & Bender 2018, "A physically consistent implicit
// viscosity solver for SPH fluids", Computer Graphics Forum 37(2):145-155), for the viscous
// silicone oils (1000-5000 cSt) whose explicit viscous step limit (0.08 d^2/nu) is far below the
// CFL step.
//
// The viscous acceleration is the Laplacian of the velocity field (Weiler et al.'s velocity
// Laplacian, the vector form of the second-derivative approximation with the factor 2(d+2), d = 3
// dimensions):
//   a_i = 2(d+2) sum_j m_j mu_ij / (rho_i rho_j) (v_ij . x_ij) / (|x_ij|^2 + 0.01 h^2) gradW_ij
//       + 2(d+2) sum_b V_b mu_i / rho_i (v_ib . x_ib) / (|x_ib|^2 + 0.01 h^2) gradW_ib   (walls)
// and the step is backward Euler, v = v* + dt a(v). Multiplied by m_i every pair term has the
// symmetric coefficient c_ij = 2(d+2) m_i m_j mu_ij / (rho_i rho_j), so the system is
//   (M + dt K) v = M v* + dt f_wall,        K = sum over pairs of k_ij x_ij x_ij^T,
// with k_ij = -c_ij W'(r)/(r (r^2 + 0.01 h^2)) >= 0: M + dt K is symmetric positive definite and
// conjugate gradients apply (divided row by row by m_i it is v - dt a(v) = v*, symmetric only
// for equal masses; the m_i-weighted form stays symmetric with several phases). It is solved
// matrix-free with a block-Jacobi (3x3 per particle) preconditioner, warm-started from the last
// step's viscous acceleration. Walls are static no-slip particles with Akinci volumes V_b; a wall
// may carry a tangential surface velocity (a plate sliding in its own plane, a rotating cylinder)
// in an optional wall field "velocity" [m/s]: its particle positions stay valid, so the wall stays
// static in the sense of docs/developer-guide.md principle 2.
//
// Momentum: the velocity is finally set to v = v* + dt M^-1 f(v_cg), the pair forces evaluated at
// the CG solution. They are equal and opposite pair by pair, so without walls sum m v is conserved
// to round-off whatever the CG tolerance (v differs from v_cg by M^-1 times the CG residual).
//
// Two phases: mu_ij is the harmonic mean 2 mu_i mu_j / (mu_i + mu_j) of the dynamic viscosities.
// Across an interface parallel to the flow the shear stress mu du/dn is continuous, so the two
// layers act as resistances in series; the harmonic mean is the effective viscosity of that series
// (as for conductivities between cells of a finite-volume scheme; Hu & Adams 2006, J. Comput.
// Phys. 213, use it for SPH multiphase viscosity). The arithmetic mean would give aqueous
// particles next to 1000x more viscous oil half the oil's viscosity and drag the aqueous along.
//
// Unconditionally stable: no time-step limit of its own. Allocates in attach() only; per-pair
// coefficient buffers are reserved at twice the initial neighbour count and grow only if the
// neighbour count ever exceeds that.
#pragma once

#include <string>
#include <vector>

#include "sim/core/reduction.h"
#include "sim/effects/effect.h"

namespace sim {

struct ImplicitViscosityParameters {
  // [1] CG stops when |r_i / m_i| summed in quadrature falls below tolerance * |b_i / m_i|
  // summed the same way (a velocity-scale relative residual).
  Real tolerance = 1e-6;
  int maxIterations = 300;
  bool wallFriction = true;  // no-slip walls (false: walls exert no viscous force)
  // Start CG from v* + dt a_visc(previous step) instead of v* (docs/methods/viscosity.md:
  // iterations).
  bool warmStart = true;
};

// Optional wall field: tangential velocity of the wall surface [m/s] (see header comment).
inline constexpr const char* kWallVelocityField = "velocity";

class ViscosityWeiler2018 final : public Effect {
 public:
  explicit ViscosityWeiler2018(const ImplicitViscosityParameters& parameters = {});
  std::string_view name() const override { return "implicit_viscosity"; }
  Kind kind() const override { return Kind::kImplicit; }
  void attach(World& world) override;
  void apply(World& world, const StepContext& context) override;

  int lastIterations() const { return lastIterations_; }
  Real lastResidual() const { return lastResidual_; }  // [1] relative, as the tolerance
  long totalIterations() const { return totalIterations_; }
  long solves() const { return solves_; }

 private:
  // Per-step pair coefficients and the block-Jacobi preconditioner.
  void assemble(const World& world, Real dt);
  // out = (M + dt K) in; returns sum_i in_i . out_i (deterministic order).
  Real multiply(const World& world, Real dt, const std::vector<Vec3>& in, std::vector<Vec3>& out);
  // m_i a_i (the viscous force [N]) of the velocity field `v` including walls at their velocity.
  void computeForces(const World& world, const std::vector<Vec3>& v, std::vector<Vec3>& out) const;
  // The CG solve of apply() (allocates nothing).
  void solve(const World& world, Real dt);

  ImplicitViscosityParameters params_;
  std::vector<Real> viscosityOfMaterial_;   // [Pa s]
  std::vector<Vec3>* warmStart_ = nullptr;  // [m/s^2] last viscous acceleration (registry field)
  const std::vector<Vec3>* wallVelocity_ = nullptr;  // [m/s] optional
  // Per pair, aligned with the neighbour lists: s_ij such that the pair force on i is
  // s_ij (gradW_ij . v_ij) gradW_ij (s_ij <= 0, [kg s m^6]).
  std::vector<Real> fluidPair_, wallPair_;
  std::vector<Mat3> preconditioner_;  // [1/kg] inverse 3x3 diagonal blocks of M + dt K
  std::vector<Vec3> velocityStar_, rhs_, solution_, residual_, search_, product_, precond_;
  DeterministicReducer reducer_;
  int lastIterations_ = 0;
  Real lastResidual_ = 0;
  long totalIterations_ = 0;
  long solves_ = 0;
};

// Which viscosity stage a scene needs: none (every material inviscid), the explicit one
// (ViscosityMonaghan2005) when its limit 0.08 d^2 / nu_max is at least the step the rest of the
// pipeline would take, or this implicit one when the explicit limit is below that step (it would
// force tiny steps; the implicit solve lets the scene run at the CFL step).
struct ViscosityTreatment {
  bool viscous = false;
  bool implicit = false;
  Real explicitLimit = 0;  // [s] ViscosityMonaghan2005::kStableStepFactor d^2 / nu_max
  Real advectionStep = 0;  // [s] the step without a viscous limit (see advectionTimeStep)
  std::string reason;
};
// The step the pipeline would take without any viscous limit [s]: maxTimeStep, the body-force
// bound cfl sqrt(d/|g|), the advective CFL cfl d/v_max of the current velocities and the pressure
// solver's own limit `solverLimit` (acoustic for weakly compressible solvers).
Real advectionTimeStep(const World& world, Real solverLimit);
ViscosityTreatment chooseViscosityTreatment(const World& world, Real solverLimit);

}  // namespace sim
