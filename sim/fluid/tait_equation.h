// Tait equation of state (Becker & Teschner 2007, eq. 3 with gamma = 7), free surface clamped:
//   p = max(B ((rho/rho0)^7 - 1), 0),  B = rho0 c^2 / 7.
// Shared by WCSPH (mass-weighted rho) and the number-density baseline (adapted rho~ = m delta).
#pragma once

#include <algorithm>

#include "sim/core/types.h"

namespace sim {

// [Pa] from density rho and rest density rho0 [kg/m^3] and squared speed of sound c2 [m^2/s^2].
inline Real taitPressure(Real rho, Real rho0, Real c2) {
  const Real ratio = rho / rho0;
  const Real r2 = ratio * ratio, r3 = r2 * ratio;
  return std::max(rho0 * c2 / 7.0 * (r3 * r3 * ratio - 1.0), Real(0));
}

}  // namespace sim
