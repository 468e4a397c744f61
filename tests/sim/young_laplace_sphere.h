// Independent references for the static equilibrium of two fluids in a sphere of radius R: the
// axisymmetric Young-Laplace meniscus under gravity (shooting on the meridian's ODE) and, without
// gravity, the closed form of two intersecting spheres. The equilibrium solver
// (sim/equilibrium/) is tested against both; neither shares code with it.
//
// The lower phase is the heavier one (or either, without gravity): gravity along -z, the
// interface's meridian from its apex on the axis, arc length s, tangent angle psi from the
// horizontal:
//   r' = cos psi,  z' = sin psi,  psi' = b + c (z - z0) - sin(psi) / r   (psi' = b / 2 at r = 0),
// b the apex's curvature sum, c = (rho_lower - rho_upper) g / sigma >= 0 (Young-Laplace with the
// hydrostatic pressure difference). The meridian ends where it meets the sphere, (r, z) with
// r^2 + z^2 = R^2; the contact angle through the lower phase there is
//   cos(theta_lower) = (r sin psi - z cos psi) / R,
// and the lower phase's volume is the sphere's cap below the contact height z_c plus
// int (z - z_c) d(pi r^2) along the meridian. Two nested root finds (b for the angle, z0 for the
// volume) solve it; the wall fraction wetted by the upper phase is (R - z_c) / (2R).
#pragma once

#include <utility>
#include <vector>

namespace testref {

struct SphereMeniscus {
  double contactHeight = 0.0;     // [m] z_c of the contact line
  double upperWetFraction = 0.0;  // [1] wall area above z_c over the sphere's area
  double apexHeight = 0.0;        // [m]
  double apexCurvature = 0.0;     // [1/m] b
  std::vector<std::pair<double, double>> meridian;  // [m] (r, z) from the apex to the wall
};

// `lowerAngle` [rad] contact angle through the lower phase; `lowerVolumeFraction` its share of
// the sphere; `capillaryConstant` c [1/m^2] (0 for no gravity, where the closed form below is
// the better reference). Throws std::runtime_error when no meniscus meets the conditions.
SphereMeniscus youngLaplaceSphere(double radius, double capillaryConstant, double lowerAngle,
                                  double lowerVolumeFraction);

// Zero gravity: the interface is a spherical cap on the contact circle. With phase P above the
// contact height z_c of the unit sphere, rim polar angle gamma = acos(z_c), rim radius a, the cap's
// tangent angle phi to the rim plane satisfies cos(alpha_P) = cos(phi + gamma) (alpha_P the
// contact angle through P), its height is delta = a tan(phi / 2), and P holds the sphere's cap
// above z_c plus the segment pi delta (3 a^2 + delta^2) / 6. Solved for z_c by bisection; returns
// the wall fraction (1 - z_c) / 2 that P wets, given P's angle [rad] and volume fraction.
double zeroGravityWetFraction(double angle, double volumeFraction);

}  // namespace testref
