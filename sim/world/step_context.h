// What one time step knows besides the World: its length and where to put statistics.
#pragma once

#include "sim/core/types.h"

namespace sim {

// Per-step diagnostics every pressure solver reports (compression, iterations).
struct SolverStats {
  int densityIterations = 0;      // iterations of the main (density / number-density) solve
  int divergenceIterations = 0;   // iterations of the divergence-free solve, if any
  Real averageCompression = 0.0;  // [1] mean of max(rho/rho0 - 1, 0) (or delta/delta0) at step end
  Real maxCompression = 0.0;      // [1] maximum of the same
  int densityIterationLimit = 0;  // the main solve's iteration cap (0: explicit solver, no solve)
};

struct StepContext {
  Real dt = 0.0;  // [s]
};

}  // namespace sim
