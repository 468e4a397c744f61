// Contact angle of a sessile droplet on a flat wall from a fitted spherical cap (issue 6
// validation 3). The interface is sampled at the midpoints of neighbouring droplet/other-phase
// particle pairs closer than 1.5 d (the sharp interface lies between the two phases' particles);
// a sphere is fitted to those points by algebraic least squares (|x|^2 = 2 c.x + k, linear in
// c and k; Kasa 1976), and with the sphere centre at signed height z_c above the wall plane,
// the angle measured through the droplet is theta = acos(-z_c / R). Points closer than
// `excludeNearWall` to the wall are dropped: the wall layer distorts the colour field there.
#pragma once

#include <vector>

#include "sim/world/world.h"

namespace sim {

struct SphereFit {
  Vec3 centre = Vec3::Zero();  // [m]
  Real radius = 0.0;           // [m]
  Real rmsResidual = 0.0;      // [m] rms of |x - c| - R over the points
};

// Algebraic least-squares sphere through >= 4 points (throws SimError if degenerate).
SphereFit fitSphere(const std::vector<Vec3>& points);

// Midpoints of the neighbouring pairs (material, any other fluid material) closer than 1.5 d:
// samples of the sharp interface, which lies between the two phases' particles [m].
std::vector<Vec3> interfacePairMidpoints(const World& world, int material);

struct WallPlane {
  Vec3 point = Vec3::Zero();   // [m] a point on the wall surface
  Vec3 normal = Vec3::UnitY(); // [1] unit normal pointing into the fluid
};

struct CapFit {
  SphereFit sphere;
  Real contactAngle = 0.0;  // [deg] measured through the droplet's material
  int pointCount = 0;
};

CapFit fitSessileCap(const World& world, int dropletMaterial, const WallPlane& wall,
                     Real excludeNearWall);

}  // namespace sim
