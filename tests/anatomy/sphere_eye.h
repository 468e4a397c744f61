// A spherical cavity for tests with closed-form answers: on a sphere of radius R the wall
// distance along a meridian is R times the polar angle.
#pragma once

#include "anatomy/cavity_shape.h"

namespace anatomy::test {

constexpr double kSphereRadius = 11.0e-3;  // [m]

// Sphere of radius 11 mm, cut by a flat cap (no sag) 6 mm in front of its centre.
inline CavityGeometry sphereGeometry(double capSag = 0.0) {
  CavityGeometry g;
  g.semiAxisHorizontal = g.semiAxisVertical = g.semiAxisAxial = kSphereRadius;
  g.apexDepth = 3.0e-3;
  g.capPlaneDepth = 3.0e-3 + kSphereRadius - 6.0e-3;  // rim plane at local z = +6 mm
  g.capSag = capSag;
  return g;
}

}  // namespace anatomy::test
