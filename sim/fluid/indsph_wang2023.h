// Incompressible number-density SPH, INDSPH (Wang et al. 2023, "An incompressible number density
// SPH for high density ratio multiphase fluid", sections 4.1-4.2, Algorithm 1): a DFSPH-style local
// pressure solve on the NUMBER density delta_i = sum_j W_ij instead of the mass density, so a
// particle's neighbours count the same whatever their mass and a heavy/light interface does not
// read as compressed (the error of paper section 3.3). Derivation in docs/methods/solvers.md.
//
//   delta_i   = W_0 + sum_j W_ij + sum_b (V_b / V0_i) W_ib        (eq. 6, walls: Akinci 2012)
//   delta*_i  = delta_i + dt sum_j (v_i - v_j).gradW_ij + dt sum_b (V_b/V0_i) v_i.gradW_ib (eq. 15)
//   kappa_i   = omega delta_i (delta*_i - delta0_i) / (dt^2 (|G_i|^2/m_i + sum_j |gradW_ij|^2/m_j))
//                                                                     (eqs. 17-18, see docs)
//   dv_i      = -dt/m_i (kappa_i/delta_i G_i + sum_j kappa_j/delta_j gradW_ij)   (eqs. 19-20)
// with G_i = sum_j gradW_ij + sum_b (V_b/V0_i) gradW_ib and delta0_i = 1/V0_i = rho0_i/m_i
// (eq. 16). The output pressure is p_i = kappa_i delta_i.
//
// Walls, two models chosen by the scene:
// - single-layer Akinci 2012 surface particles (no "wall_layer" field): a wall neighbour only
//   enters the fluid particle's own constraint (its number density and G_i), i.e. p_b = 0 in the
//   symmetric pair force. Such a layer has no rest number density of its own (its wall-only sum
//   already equals the rest value), so it cannot be an unknown of the solve.
// - layered walls (sim/boundary/wall_layers.h, volumes V_b known): the paper's static particles
//   (section 4.3, eq. 21). Each wall particle b with dynamic neighbours is an unknown kappa_b:
//     delta_b   = (1/V_b) (V_b W_0 + sum_c V_c W_bc + sum_j V0_j W_bj)    (eq. 6 with volumes)
//     delta*_b  = delta_b + dt sum_j (V0_j/V_b) v_j.gradW_jb            (eq. 15 with v_b = 0)
//     kappa_b   = omega delta_b (delta*_b - 1/V_b) / (dt^2 sum_j (V0_j/V_b)^2 |gradW_bj|^2/m_j)
//                                                    (eq. 21: d_b^{p_b} = 0, static b cannot move)
//     dv_j      = -dt/m_j kappa_b/delta_b (V0_j/V_b) gradW_jb               (eqs. 12, 19)
//   A fluid particle that gets between wall particles compresses them and is pushed out by their
//   own pressure, which a lattice wall with mirrored or zero wall pressure cannot do.
// Optionally a divergence-free pass in the same number-density form precedes each step.
#pragma once

#include <vector>

#include "sim/core/reduction.h"
#include "sim/fluid/pressure_solver.h"

namespace sim {

struct IndsphParameters {
  Real tolerance = 1e-4;  // [1] eta: stop when mean (delta*/delta0 - 1) < eta (paper: 1e-4)
  int minIterations = 2;
  int maxIterations = 100;
  // [1] omega of each Jacobi update. With mixed masses a light particle is pushed by all its
  // heavy neighbours' stiffnesses at once, each computed as if it acted alone; full steps
  // (omega = 1) overshoot and at 1:75 threw particles through the floor after 0.3 s of the
  // two-phase dam break (cfl 0.15). 0.5, IISPH's relaxation, ran 1 s at 1:2...1:75.
  Real relaxation = 0.5;
  Real warmStartFactor = 0.5;  // [1] fraction of last accepted step's kappa applied first
  // Divergence-free pass (not in the paper; DFSPH's second solve in number-density form). On the
  // 4 x 8 cm tank at rest (omega 0.5) it lowers the final kinetic energy 3x (1.6e-6 vs 4.8e-6 J)
  // and the hydrostatic error (1.0 % vs 1.9 %); on the dam break it converges in one iteration
  // and changes nothing measurable (docs/methods/solvers.md).
  bool divergenceSolve = true;
  Real divergenceTolerance = 1e-3;     // [1] stop when mean dt (D delta/Dt)/delta0 falls below
  int minNeighborsForDivergence = 20;  // particles with fewer (free surface) are left alone
  // [1] Layered walls: a wall particle is an unknown of the solve only when its dynamic
  // neighbours make up at least this fraction of its number density (small-diagonal guard, as in
  // IISPH). A wall particle whose only dynamic neighbour sits at the edge of the support
  // (r > 1.5 d for the cubic spline at h = 2d) has a near-zero diagonal: a 3e-5 lattice-sum
  // excess then read as kappa_b of up to 5e5 Pa (for a negligible force) on the 1:75 dam break.
  // A particle intruding past the surface layer contributes W(d) d^3 = 8 % and stays covered;
  // the fluid particle's own constraint still sees every wall particle.
  Real minWallDynamicFraction = 0.01;
  // Closed domains filled with fluid (no free surface): also correct EXPANSION of fluid particles
  // that have no wall neighbour, i.e. let kappa and p go negative there. The one-sided clamp
  // (max(delta*, delta0), which lets a free surface expand) pins a closed fluid at rest to p = 0,
  // so wherever the flow needs a pressure below its mean (-rho dphi/dt < 0 around an oscillating
  // droplet) the fluid is not pulled but left to rarefy: the l = 2 droplet oscillated at half
  // Lamb's frequency with the clamp (docs/methods/interface.md, validation 2). Particles next to
  // walls keep the clamp (a single-layer wall under-fills their number density at rest). The
  // convergence measures then use |delta* V0 - 1| (two-sided errors must not cancel in the mean).
  // Default off.
  bool correctBulkExpansion = false;
};

// Layered-wall (eq. 21) state: wall particles with dynamic neighbours and their pairs, the
// transpose of World::wallNeighbors() (rebuilt each step: the lists change with the fluid).
struct StaticWallPairs {
  std::vector<Index> walls;    // wall indices with at least one dynamic neighbour (ascending)
  std::vector<Index> offsets;  // CSR into dynamic/pair, one row per wall particle (size walls+1)
  std::vector<Index> dynamic;  // dynamic neighbour j
  std::vector<Index> pair;  // index k of the pair (j, b) in World::wallNeighbors()/wallGradients()
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
  // Whether particle i's expansion is corrected too (IndsphParameters::correctBulkExpansion).
  bool twoSided(const World& world, Index i) const {
    return params_.correctBulkExpansion &&
           world.wallNeighbors().begin(i) == world.wallNeighbors().end(i);
  }
  void solveDivergence(World& world, Real dt);
  // Applies the velocity change of the fluid stiffnesses `kappa` and, when given, of the wall
  // stiffnesses `wallKappa` (layered walls, indexed like world.walls).
  void applyPressureVelocity(World& world, const std::vector<Real>& kappa, Real dt,
                             const std::vector<Real>* wallKappa = nullptr);
  void prepareStaticWalls(const World& world);  // eq. 21 set-up: pairs, delta_b, diagonal
  Real predictWallNumberDensity(const World& world, Real dt);  // returns summed compression
  // correctVelocities() in steps (none allocates).
  void warmStartStiffness(World& world, Real dt);
  void relaxStiffness(const World& world, Real dt);
  void storePressure(const World& world);

  IndsphParameters params_;
  std::vector<Real>* numberDensity_ = nullptr;  // [1/m^3] delta_i (output)
  std::vector<Real>* pressure_ = nullptr;       // [Pa] p = kappa delta (output)
  std::vector<Real>* kappa_ = nullptr;          // [Pa m^3] accumulated kappa, warm start
  std::vector<Real> diagonal_;                  // [m^-8 kg^-1] |G|^2/m_i + sum |gradW|^2/m_j
  // [1/m^7] sum_b V_b gradW_ib / V0_i per particle, fixed for a step (static walls, positions
  // unchanged during the solves): the fluid particle's own wall terms in eqs. 14 and 19 are this
  // vector times a per-particle scalar, so the iterations loop over wall pairs only for the wall
  // particles' own stiffnesses (layered walls).
  std::vector<Vec3> wallGradient_;
  std::vector<Real> predicted_;  // [1/m^3] delta* (scratch)
  std::vector<Real> increment_;  // [Pa m^3] this iteration's kappa (scratch)
  std::vector<Real> warmStart_;  // [Pa m^3] last accepted step's kappa (scratch)
  DeterministicReducer reducer_;

  // Layered walls only (allocated by attach() when the scene has them; DESIGN principle 1).
  bool staticWalls_ = false;
  std::vector<Real>* wallKappa_ = nullptr;     // [Pa m^3] kappa_b, warm start (wall field)
  std::vector<Real>* wallPressure_ = nullptr;  // [Pa] p_b = kappa_b delta_b (wall field, output)
  StaticWallPairs wallPairs_;
  std::vector<Real> wallStaticDensity_;  // [1/m^3] W_0 + sum_c (V_c/V_b) W_bc, fixed
  std::vector<Real> wallDensity_;        // [1/m^3] delta_b (per wall)
  std::vector<Real> wallDiagonal_;       // [m^-8 kg^-1] sum_j (V0_j/V_b)^2 |gradW|^2/m_j
  std::vector<Real> wallPredicted_;      // [1/m^3] delta*_b (scratch)
  std::vector<Real> wallIncrement_;      // [Pa m^3] (scratch, per wall)
  std::vector<Real> wallWarmStart_;      // [Pa m^3] (scratch)
};

// Number density with Akinci wall terms (eq. 6), shared with the explicit number-density solver.
void computeNumberDensities(const World& world, std::vector<Real>& delta);

}  // namespace sim
