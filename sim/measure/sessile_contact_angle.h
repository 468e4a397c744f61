// Contact angle of a sessile droplet on a flat wall from a fitted spherical cap
// (docs/methods/interface.md, validation 3). The interface is sampled at the midpoints of
// neighbouring droplet/other-phase particle pairs closer than 1.5 d (the sharp interface lies
// between the two phases' particles); the cap of the droplet's volume that fits those points best
// gives the angle (fitSessileCap). Also here: the algebraic least-squares sphere (|x|^2 = 2 c.x +
// k, linear in c and k; Kasa 1976) and the orthogonal-distance sphere; with the sphere centre at
// signed height z_c above the wall plane, the angle measured through the droplet is theta =
// acos(-z_c / R).
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

// Orthogonal-distance sphere fit (minimises sum (|x - c| - R)^2), damped Gauss-Newton from `start`.
SphereFit fitSphereGeometric(const std::vector<Vec3>& points, const SphereFit& start);

struct WallPlane {
  Vec3 point = Vec3::Zero();    // [m] a point on the wall surface
  Vec3 normal = Vec3::UnitY();  // [1] unit normal pointing into the fluid
};

// Angle [deg] through the droplet of the spherical cap of the given volume [m^3] on the wall,
// its axis through axisPoint, that best fits the points (least squares of the orthogonal
// distances, a 1-D search over the angle).
Real capAngleOfVolume(const std::vector<Vec3>& points, const WallPlane& wall, const Vec3& axisPoint,
                      Real volume);

// Angle [deg] through the droplet of the spherical cap of the given volume [m^3] whose section at
// `height` [m] above the wall has radius `sectionRadius` [m]: the angle from the droplet's
// footprint, i.e. where its contact line sits. Non-wetting droplets' shape away from the wall
// hardly depends on the angle (the volume's caps of 165 and 180 deg differ in height by 3 % of
// their radius) but their footprint does (at R0 = 12 d the first layer's radius is 4.97 d at
// 155 deg, 3.88 d at 165, 3.15 d at 175); for wetting droplets the footprint is what a coverage
// reading sees. From the widest section's angle (a few degrees: flatter caps sink below `height`
// near their rim) to 180 deg the section shrinks monotonically; a radius wider than the widest
// section reads that angle, narrower than the touching sphere's reads 180.
Real capAngleOfFootprint(Real volume, Real sectionRadius, Real height);

// Angle [deg] through the droplet, in (0, 180), of the spherical cap of the given volume [m^3]
// whose centroid lies `centroidHeight` [m] above the wall: a measure that uses no interface
// points, only the droplet's volume and mass centre, so it checks the cap fit independently.
// A cap of height H cut from a sphere of radius R has its centroid H (4R - H) / (4 (3R - H)) above
// its base, which grows monotonically with the angle at fixed volume (3/8 R0 at 90 deg, R at 180);
// heights outside that range read 0 or 180. Its sensitivity falls with the angle: at 150 deg 1 deg
// is 0.005 R0 of height, at 165 deg 0.003 R0.
Real capAngleOfCentroid(Real volume, Real centroidHeight);

struct CapFit {
  SphereFit sphere;          // the algebraic fit (Kasa) of the interface points
  Real sphereAngle = 0.0;    // [deg] its angle acos(-z_c / R), through the droplet's material
  Real contactAngle = 0.0;   // [deg] the cap of the droplet's volume that fits the points best
  Real capRadius = 0.0;      // [m] that cap's sphere radius
  Real volume = 0.0;         // [m^3] the droplet's volume, sum of m_i / rho_i
  Real centroidAngle = 0.0;  // [deg] the cap of that volume with the droplet's centroid height
                             //       (capAngleOfCentroid), a check without interface points
  // What the fit was made of, for further fits of the same droplet (the Young-Laplace outline
  // fit under gravity, sessile_young_laplace.h): the interface points left after the exclusion
  // near the wall, and the droplet's volume-weighted centroid.
  std::vector<Vec3> points;      // [m]
  Vec3 centroid = Vec3::Zero();  // [m]
};

// The contact angle of a droplet of `dropletMaterial` sitting on the wall plane: the interface
// points (interfacePairMidpoints) closer than excludeNearWall to the wall are dropped (the wall
// layer distorts the colour field there), and the angle is that of the spherical cap of the
// droplet's own volume, on the vertical axis through the droplet's centroid, that fits the
// remaining points best (capAngleOfVolume). Why not the free sphere: for a flat cap the points
// span a short arc (a 30 deg cap at R0 = 6 d is 2.7 d tall, 1.7 d above the excluded layer), on
// which the algebraic fit is biased towards small radii (a known property of the Kasa fit, e.g.
// Chernov 2010, Circular and Linear Regression): it read static lattice caps of 30 / 45 deg at 33.6
// / 46.9 deg; the volume-constrained cap reads them at 30.5 / 44.3 (docs/methods/interface.md,
// validation 3). Near 180 deg neither helps: at 165 deg both read 168 (0.02 d of centre height is 1
// deg there). The droplet's volume V_i = m_i / rho_i uses the solver's density where it is set
// (> 0), else the rest density. sphere / sphereAngle keep the free fit for comparison.
CapFit fitSessileCap(const World& world, int dropletMaterial, const WallPlane& wall,
                     Real excludeNearWall);

}  // namespace sim
