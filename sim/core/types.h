// Basic numeric types of the engine. SI units everywhere inside sim/ (docs/developer-guide.md
// principle 5).
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace sim {

using Real = double;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
// Particle indices. 32 bits hold 4e9 particles, far beyond one 24 GiB machine.
using Index = std::uint32_t;

}  // namespace sim
