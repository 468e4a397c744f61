// Start-up relaxation of the fluid fill (not part of the simulated time): particles of rest mass
// rho d^3 on a lattice cut 0.65 d from the wall (MassRule::kRelaxedFill, scenario.h) hold the
// fluid's volume at rest density, but the outermost of them sit where the single Akinci wall
// layer over-estimates the density (+55 % at d/2 from a face, +6 % at d, docs/methods/solvers.md),
// and the staircase of the lattice leaves holes along a curved wall. A few passes of particle
// shifting (Xu, Stansby & Laurence 2009, J. Comput. Phys. 228; Lind et al. 2012, J. Comput. Phys.
// 231, eq. 8: dx_i = -D grad C_i) move every fluid particle down the gradient of its kernel-summed
// volume fraction C_i = sum_j V0_j W_ij + sum_b V_b W_ib (fluid, fixed dynamic particles such as
// tissue, and walls): particles leave the over-dense wall layer for the holes, the fluid becomes
// nearly uniform at C ~ 1, and the implicit solvers (INDSPH, DFSPH) start from a state they can
// hold (instead of the ~30 % compression of MassRule::kFillCavity).
#pragma once

#include "sim/world/world.h"

namespace protocols {

struct FillRelaxation {
  int passes = 100;          // [1] shifting passes
  double shiftFactor = 0.1;  // [1] D / d^2: dx = -shiftFactor d^2 grad C
  double maxShift = 0.1;     // [1] per pass, in spacings (keeps the pass from tunnelling)
  // [1] total, in spacings, from the particle's lattice site. The holes the pass fills are less
  // than a lattice cell away (the staircase along a curved wall: up to sqrt(3)/2 d), but a
  // boundary of one layer (a 1 mm elastic sclera sampled at d = 1.2 mm, with nothing behind
  // it) never reads C ~ 1, so unbounded passes walked fluid out through it: mean C 0.94 before
  // the passes, 0.79 after 30, 0.75 after 100 on paper_sclera_10kpa.toml. A lattice cut 0.65 d
  // from the wall ends >= 0.15 d inside it with this cap.
  double maxTotalShift = 0.5;
  std::vector<int> movable;  // material indices that move (the fluids); the rest stay fixed
};

struct FillRelaxationResult {
  double meanBefore = 0.0;  // [1] mean C over the movable particles before the passes
  double maxBefore = 0.0;   // [1]
  double meanAfter = 0.0;   // [1] after
  double maxAfter = 0.0;    // [1]
};

// Kernel-summed volume fraction C_i (see above) of every dynamic particle, in particle order.
// Needs the wall volumes (World::initialize).
std::vector<double> volumeFractions(const sim::World& world);

// Shifts the movable particles of an initialized World (positions only; velocities are zeroed)
// and leaves the neighbour lists to the next step. Deterministic and independent of the thread
// count (Jacobi passes over a private grid; the World's particle order is not changed).
FillRelaxationResult relaxFill(sim::World& world, const FillRelaxation& options);

}  // namespace protocols
