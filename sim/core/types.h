// Basic numeric types of the engine. SI units everywhere inside sim/ (DESIGN.md principle 5).
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace sim {

using Real = double;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
// Particle indices. 32 bits hold 4e9 particles, far beyond one 24 GiB machine.
using Index = std::uint32_t;
// Per-pair kernel gradients cached by the neighbour pass are stored in single precision: they are
// read once per pair in every solver iteration, so their memory traffic is most of an
// iteration's cost, and float halves it. Their relative rounding (6e-8) is far below the solvers'
// tolerances (1e-3 .. 1e-5); every sum that reads them accumulates in double, and the gradient of
// (j, i) is still exactly minus that of (i, j) (rounding is sign-symmetric), so pair forces stay
// equal and opposite. Kernel values stay double: they are read once per step (density sums), and
// the number density of a layered wall is exact to 1e-12 (tests/sim/test_layered_walls.cpp).
using CachedReal = float;
using CachedVec3 = Eigen::Vector3f;

}  // namespace sim
