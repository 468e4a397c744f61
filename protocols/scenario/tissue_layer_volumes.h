// Rest volumes of tissue particles sampled as layers along a surface (meshing/sample_shell_layers.h),
// made consistent with the number-density discretisation the pressure solve uses.
//
// INDSPH (Wang et al. 2023, eq. 7-8) takes a particle's number density delta_i = sum_j W_ij over
// its dynamic neighbours, whatever their volumes, and its rest value 1 / V0_i. The layers' geometric
// volumes A d (1 + kappa z)^2 are not 1 / sum_j W_ij on an irregular (RSA) packing: for Poisson-disk
// wall layers behind an eye cavity the kernel sum of layer 1 was 1.20 x 1/V on average, up to 1.76
// (docs/solvers.md "Eye cavities"), so such particles start "compressed" and the solve pushes them
// apart. Here V0_i = 1 / (sum_{j in tissue} W_ij + Phi(z_i) / d^3): the tissue's own kernel sum at
// rest plus that of a fluid at rest density (d^3 per particle) filling the half-space in front of
// the surface, Phi(z) being the fraction of the kernel's integral beyond a plane at distance z
// (flat-surface approximation; the cavity's radius is ~10 d at the draft spacing). A particle so
// calibrated is at its rest number density when the fluid is at rest in front of it.
#pragma once

#include <vector>

#include "sim/core/types.h"
#include "sim/kernels/kernel.h"

namespace protocols {

// [1] integral of W over the half-space farther than z [m] from the particle (0.5 at z = 0).
double kernelHalfSpaceFraction(const sim::Kernel& kernel, double z);

// [m^3] V0_i for the tissue particles `points` (depths [m] from the fluid's surface, #N), with
// `others` the other tissue particles that share their kernel support (e.g. the orbital fat) and
// `walls` the static wall particles (e.g. the lens cap next to the sclera's rim). A wall adds
// sum_b V_b W_ib / V0_i to delta_i (INDSPH eq. 7 with Akinci volumes V_b = 1 / sum_b' W_bb', as
// sim::World gives them), so V0_i = (1 - sum_b V_b W_ib) / (dynamic sum), at least a quarter of
// the wall-free value. Brute force over pairs (N (N + M + W) distance checks, < 1 s at draft).
std::vector<double> calibratedLayerVolumes(const sim::Kernel& kernel, const std::vector<sim::Vec3>& points,
                                           const std::vector<double>& depths,
                                           const std::vector<sim::Vec3>& others,
                                           const std::vector<sim::Vec3>& walls, double spacing);

}  // namespace protocols
