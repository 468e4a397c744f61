// Implicit corotated linear elasticity for SPH solids (Peer, Gissler, Band & Teschner 2018,
// "An implicit SPH formulation for incompressible linearly elastic solids", CGF 37(6)), in the
// total Lagrangian form with kernel-gradient correction (Bonet & Lok 1999) and an implicit
// zero-energy-mode penalty (Ganzenmueller 2015's pair error, treated implicitly as in Kugelstadt
// et al. 2021); the elastic part of INDSPH (Wang et al. 2023, section 4).
//
// Per elastic particle i (reference position X_i, reference volume V_i = m_i / rho0):
//   corrected reference gradient  g_ij = L_i gradW(X_i - X_j),
//                                 L_i = (sum_j V_j (X_j - X_i) gradW(X_i - X_j)^T)^-T
//   deformation gradient          F_i  = sum_j V_j (x_j - x_i) g_ij^T        (Peer 2018 eq. 7)
//   rotation                      R_i  = rotational part of F_i (Mueller et al. 2016, warm start)
//   corotated strain              eps_i = sym(R_i^T F_i) - I                  (Peer 2018 eq. 9)
//   stress                        sigma_i = 2 mu eps_i + lambda tr(eps_i) I, P_i = R_i sigma_i
//   force                         f_i = sum_j V_i V_j (P_i g_ij - P_j g_ji)   (Peer 2018 eq. 12)
// which is minus the gradient of E = sum_i V_i (mu eps:eps + lambda/2 tr(eps)^2) with R fixed.
// Zero-energy modes (particle-scale patterns F cannot see) are penalised by
//   E_hg = sum_i sum_j (alpha E_young / 2) V_i V_j W0_ij / |X_ij|^2 |(F_i + F_j)/2 X_ij - x_ij|^2,
// Ganzenmueller 2015's symmetrised pair error (his hourglass force projects the same two errors on
// x_ij) in a quadratic energy, so the implicit solve can include it (Kugelstadt 2021, section 4).
// With the mean of F_i and F_j the error vanishes for quadratic displacement fields (trapezoidal
// rule), so the penalty does not stiffen smooth bending.
//
// Implicit step (Peer 2018 section 4, solved here for the velocities rather than the stress; with
// R_i held at its start-of-step value both energies are quadratic in x, so this is exact
// backward Euler of the linearised system):  (M + dt^2 H) v = M v* - dt grad E(x),
// H the Hessian of E + E_hg, solved matrix-free by block-Jacobi preconditioned CG. Fixed
// particles (sim/solid/fixed_particles.h) are Dirichlet rows with v = 0.
//
// Reference data (neighbours, corrected gradients) are keyed by particle id, because the pipeline
// re-sorts the particle arrays every zSortInterval steps; per-particle state that must survive a
// restart (reference position, rotation, fixed flag) lives in the field registry.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "sim/core/reduction.h"
#include "sim/effects/effect.h"

namespace sim {

namespace field {
inline constexpr const char* kReferencePosition = "reference_position";
inline constexpr const char* kElasticRotation = "elastic_rotation";
}  // namespace field

struct ElasticityParameters {
  // [1] alpha: zero-energy-mode penalty stiffness relative to Young's modulus (0 = off). The
  // penalty vanishes for quadratic displacement fields, so it does not stiffen smooth bending; it
  // sets how stiff the particle-scale modes the deformation gradient cannot see are. Measured on
  // the cantilever of tests/sim/solid_elasticity_test.cpp (4 particles thick): tip deflection
  // +14 % (alpha 1), +10 % (10), -5 % (100), -36 % (1000) against Euler-Bernoulli.
  Real hourglassStiffness = 10.0;
  Real solverTolerance = 1e-6;     // [1] CG stop: |r| <= tol |b| (preconditioned norm)
  int maxSolverIterations = 1000;  // [1]
  // [1] dt <= C d / c_p, c_p = sqrt((lambda + 2 mu) / rho) the pressure-wave speed. Backward Euler
  // is unconditionally stable for the linearised system; the limit keeps the lagged rotation
  // accurate (a wave crosses at most C spacings per step) and the CG iteration count moderate.
  Real waveCourantNumber = 10.0;
  // [1] epsilon of the coupling limit dt <= epsilon / omega_1 for a body in contact with walls or
  // with dynamic particles of another material; omega_1 = (pi/2) c_p / L the body's first
  // compression mode, L its thickness (0 = off). Why: the elastic stage solves backward Euler for
  // the body alone, before the pressure solve; what it hands to the other side in one step is an
  // impulse the body's own inertia carries, so a load is resisted with the stiffness
  // k / (1 + (omega_1 dt)^2) instead of k (measured: a 60000 kg/m^3 block on an anchored
  // 1000 kg/m^3 pad sags 0.172, 0.204, 0.344, 0.82 d at dt = 0.25, 0.5, 1, 2 ms against the
  // incompressible 1-D estimate 0.163 d; docs/methods/elasticity.md). 0.3 keeps that error below 9
  // % (the heavy-onto-light drop test uses it). Off by default: the limit uses the thickness mode,
  // which for a body whose load cannot squeeze it sideways (a wall lining under fluid)
  // over-restricts the step by up to ~100x, and the scenes that need it (a body carrying a heavier
  // one) are few; see docs/methods/elasticity.md.
  Real couplingStepFactor = 0.0;
  // [1] support radius of the solid's reference kernel in particle spacings (0 = the world's
  // kernel). The reference neighbourhoods are the solid's own, so it may be wider than the fluid's:
  // at 2 d a surface particle sees one layer inwards, too few for the quadratic gradient weights;
  // it falls back to the first-order correction and a cantilever bends ~30 % too far.
  Real supportRadiusFactor = 2.5;
  // Quadratic moving-least-squares gradient weights instead of the first-order correction where
  // the neighbourhood determines a quadratic (see docs/methods/elasticity.md for why).
  bool quadraticGradient = true;
};

// Statistics of the last apply().
struct ElasticityStats {
  int iterations = 0;         // CG iterations
  Real relativeResidual = 0;  // [1] at exit
  bool converged = true;
  Real elasticEnergy = 0;  // [J] E + E_hg at the start-of-step positions
};

class ElasticityPeer2018 final : public Effect {
 public:
  explicit ElasticityPeer2018(const ElasticityParameters& parameters = {});

  std::string_view name() const override { return "elasticity"; }
  Kind kind() const override { return Kind::kImplicit; }
  // Stores the current positions of all particles of elastic materials as their reference
  // configuration. Reference neighbours: elastic particles of the same material (body) within the
  // kernel support. Throws SimError if an elastic particle has no elastic neighbour.
  void attach(World& world) override;
  void apply(World& world, const StepContext& context) override;
  // [s] waveCourantNumber * d / max pressure-wave speed over the elastic materials, and
  // couplingStepFactor / omega_1 of every body touching walls or other materials' particles.
  Real maxTimeStep(const World& world) const override;

  const ElasticityStats& stats() const { return stats_; }
  const ElasticityParameters& parameters() const { return parameters_; }
  std::size_t elasticCount() const { return slotId_.size(); }
  // Pressure-wave speed sqrt((lambda + 2 mu) / rho) of an elastic material [m/s].
  static Real waveSpeed(const Material& material);  // [m/s]
  // Per body (elastic material, in ascending material index): thickness L [m] = 2 x the largest
  // distance of a particle from the body's surface particles (along reference neighbours) + d,
  // and the first compression-mode frequency (pi/2) c_p / L [rad/s] the coupling limit uses.
  const std::vector<Real>& bodyThickness() const { return bodyThickness_; }
  const std::vector<Real>& bodyModeFrequency() const { return bodyOmega_; }

 private:
  // Gradient of E + E_hg evaluated at field u (positions, subtractIdentity = true) or the Hessian
  // applied to u (velocities, subtractIdentity = false); writes out[s] for every slot.
  void energyGradient(const std::vector<Vec3>& u, bool subtractIdentity, std::vector<Vec3>& out);
  void applySystem(const std::vector<Vec3>& v, Real dt, std::vector<Vec3>& out);
  // attach() in steps: slots and their material constants (returns Young's modulus per slot),
  // the CSR offsets of the reference pairs (throws for a slot without neighbours), the pairs'
  // corrected gradients, and the bodies.
  std::vector<Real> assignSlots(const World& world, const std::vector<Index>& idToIndex);
  void countPairs(const std::vector<std::vector<std::int32_t>>& neighbours,
                  const std::vector<Vec3>& X, Real h);
  void buildPairs(const std::vector<std::vector<std::int32_t>>& neighbours,
                  const std::vector<Vec3>& X, const Kernel& kernel,
                  const std::vector<Real>& youngs);
  void buildBodies(const World& world, const std::vector<std::int32_t>& materialOf);
  void mapSlots(const World& world);
  // apply() in steps (none allocates): gather the slots' state, solve for the velocities,
  // restore each free body's momentum.
  void gatherSlots(const World& world, const std::vector<Mat3>& rotation);
  void solveVelocities(Real dt);
  void conserveBodyMomentum(const World& world);
  void computeRotations();
  void buildPreconditioner(Real dt);

  ElasticityParameters parameters_;
  ElasticityStats stats_;
  DeterministicReducer reducer_;

  // Fixed per elastic particle, in slot order (slot = rank of the id among elastic particles).
  std::vector<std::int32_t> slotId_;    // particle id of slot s
  std::vector<std::int32_t> idToSlot_;  // -1 for non-elastic ids
  std::vector<Real> volume_;            // [m^3] reference volume V_s
  std::vector<Real> mu_, lambda_;       // [Pa] Lame parameters of the slot's material
  std::vector<Vec3> gradSum_;           // [1/m] b_s = sum_j V_j g_sj (non-zero at surfaces)
  // Reference neighbour pairs, CSR over slots.
  std::vector<std::size_t> pairBegin_;    // size slots + 1
  std::vector<std::int32_t> pairSlot_;    // neighbour slot j
  std::vector<std::size_t> pairReverse_;  // position of (j, s) in j's list
  std::vector<Vec3> pairGrad_;            // [1/m^4] g_sj = L_s gradW, corrected gradient
  std::vector<Vec3> pairX_;               // [m] X_j - X_s
  std::vector<Real> pairHourglass_;       // [N/m] alpha E V_s V_j W0 / |X|^2

  // Bodies = elastic materials: slots of body b are bodySlots_[bodyBegin_[b] .. bodyBegin_[b+1]).
  std::size_t bodyCount_ = 0;
  std::vector<std::int32_t> bodyOf_;
  std::vector<std::size_t> bodyBegin_, bodySlots_;
  std::vector<std::int32_t> bodyFixed_;           // 1 if the body has a fixed particle this step
  std::vector<Real> bodyThickness_;               // [m]
  std::vector<Real> bodyOmega_;                   // [rad/s]
  mutable std::vector<std::int32_t> bodyLoaded_;  // scratch of maxTimeStep
  void computeBodyThickness(Real spacing, const std::vector<Real>& waveSpeeds);

  // Per-step state, in slot order.
  std::vector<Index> slotIndex_;  // current particle index of slot s
  std::vector<std::int32_t> fixed_;
  std::vector<Real> mass_;    // [kg]
  std::vector<Real> energy_;  // [J] per slot, elastic + zero-energy-mode penalty
  std::vector<Vec3> x_, v_, rhs_, r_, z_, p_, ap_, grad_;
  std::vector<Mat3> rotation_, defGrad_, stress_, precond_;  // stress_ holds T_s (see .cpp)
};

}  // namespace sim
