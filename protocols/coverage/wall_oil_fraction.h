// Local oil fraction at each retinal wall particle, from the fluid particles around it.
//
// phi_w = sum_j V_j W(|x_w - x_j|, h) oil_j / sum_j V_j W(|x_w - x_j|, h)   over fluid j, r < h,
// the Shepard-normalised SPH interpolant of the phase indicator (oil_j = 1 for oil, 0 for
// aqueous; Shepard 1968, in SPH e.g. Monaghan 2005 Rep. Prog. Phys. 68:1703, sec. 2.4). The
// normalisation is what makes it usable at a wall: the wall particle has fluid on one side only,
// so the plain sum would be about half of the true fraction. A wall particle with no fluid
// particle within h is dry (phi undefined, stored as 0).
//
// The support radius h_c of this interpolant is not the dynamics' h = 2 d: fluid starts a gap g
// (1.2 d) from the wall on a lattice, so the nearest fluid particle of a wall particle can be
// g + sqrt(3)/2 d ~ 2.07 d away and a 2 d kernel would call it dry. Any ball of radius
// sqrt(3)/2 d contains a point of a cubic lattice of spacing d, so with h_c = g + sqrt(3) d every
// wall particle of a flat (or convex-inward) wall has a fluid neighbour when the cavity is full,
// and "dry" means what it says: no fluid next to the wall. The price is a wider smoothing: phi is
// read at the neighbours' weighted centroid, up to h_c inward of the wall (see the tolerance
// derivation in tests/protocols/test_coverage.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "sim/core/types.h"
#include "sim/kernels/kernel.h"

namespace protocols {

enum class WallWetting : std::uint8_t { kDry = 0, kAqueous = 1, kOil = 2 };

inline constexpr double kOilCoveredThreshold = 0.5;  // [1] phi >= this: oil-covered

// h_c = wallGap + sqrt(3) spacing [m] (see above).
inline double coverageSupportRadius(double spacing, double wallGap) {
  return wallGap + 1.7320508075688772 * spacing;
}

struct WallOilFractions {
  std::vector<double> oilFraction;   // [1] phi per wall particle, #W (0 where dry)
  std::vector<WallWetting> wetting;  // per wall particle, #W
};

struct FluidPhaseState {
  const std::vector<sim::Vec3>* positions = nullptr;  // [m] fluid particles, #F
  const std::vector<std::uint8_t>* isOil = nullptr;   // 1 = oil (tamponade), 0 = aqueous, #F
  const std::vector<double>* volumes = nullptr;       // [m^3] V_j = m_j / rho_j, #F; null = equal
};

// `walls`: retinal wall particle positions [m], #W. The kernel's support radius is h. Neighbours
// are found with a uniform grid of cell h (O(W + F)); the wall loop runs on OpenMP threads and
// the result does not depend on their number. Throws CoverageError on mismatched sizes.
WallOilFractions computeWallOilFractions(const std::vector<sim::Vec3>& walls,
                                         const FluidPhaseState& fluid, const sim::Kernel& kernel);

}  // namespace protocols
