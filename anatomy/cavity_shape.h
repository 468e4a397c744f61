// The analytic surface of a vitreous cavity: a base ellipsoid (posterior wall), an optional
// posterior staphyloma (an axisymmetric outpouching at the posterior pole) and an anterior cap
// (the lens/IOL side) that closes the cavity. Every parametric cavity (vitreous_cavity.h) is one
// of these; the mesh is a tessellation with all vertices on the surface.
//
// Local construction frame: base ellipsoid centred at the origin, semi-axes a (x, horizontal),
// b (y, vertical), c (z, axial). The eye frame (docs/conventions.md) is this frame shifted along z
// so that the origin is the centroid of the enclosed volume; every public point is in the eye frame
// [m].
//
// Wall parametrisation (theta, meridian):
//   x = a sin(theta) cos(meridian),  y = b sin(theta) sin(meridian),
//   z = -c cos(theta) - depth * g(rho),  rho = hypot(x, y),
//   g(rho) = (1 + cos(pi rho / R)) / 2 for rho < R (R = width / 2), 0 beyond.
// theta = 0 is the posterior pole, theta = rimTheta() the rim where the wall meets the cap. One
// meridian (fixed `meridian`) lies in one plane through the optical axis; its true azimuth is
// atan2(b sin m, a cos m). The bump g is C1 at rho = R, and z grows monotonically with theta.
// Cap: x = A u cos m, y = B u sin m, z = zRim - sag (1 - u^2), u in [0, 1], (A, B) the rim
// semi-axes: a paraboloid dent of depth `sag` toward the cavity (the lens bulging back).
//
// Closed forms used for the volume (checked against the mesh in tests/anatomy):
//   ellipsoid below z = h:        pi a b [(h + c) - (h^3 + c^3) / (3 c^2)]
//   paraboloid dent removed:      pi A B sag / 2
//   staphyloma added:             pi depth R^2 (1/2 - 2/pi^2)
#pragma once

#include "meshing/triangle_mesh.h"

namespace anatomy {

using Vec3 = meshing::Vec3;

struct CavityGeometry {
  double semiAxisHorizontal = 0.0;  // [m] a, along x
  double semiAxisVertical = 0.0;    // [m] b, along y
  double semiAxisAxial = 0.0;       // [m] c, along z
  double apexDepth = 0.0;           // [m] corneal apex to the anterior apex of the base ellipsoid
  double capPlaneDepth = 0.0;       // [m] corneal apex to the plane of the cap rim
  double capSag = 0.0;              // [m] >= 0, how far the cap centre dents into the cavity
  double staphylomaDepth = 0.0;     // [m] >= 0, 0 = no staphyloma
  double staphylomaWidth = 0.0;     // [m] base diameter of the staphyloma
};

// A point of the wall in surface parameters.
struct WallCoordinate {
  double theta = 0.0;     // [rad] 0 at the posterior pole, rimTheta() at the rim
  double meridian = 0.0;  // [rad] parametric azimuth (see the header comment)
};

enum class CavityPart { kWall, kCap };

// Where a point (on or near the boundary) projects: the part it is nearest to, and its nearest
// wall point within its meridian plane (also computed for cap points).
struct CavityProjection {
  CavityPart part = CavityPart::kWall;
  WallCoordinate wall;
  double wallDistance = 0.0;  // [m] from the point to that wall point
};

class CavityShape {
 public:
  // Validates the geometry (positive axes, rim plane inside the ellipsoid, staphyloma inside the
  // posterior half and not folding a 1.5 mm shell); throws AnatomyError naming the parameter.
  explicit CavityShape(const CavityGeometry& geometry);

  const CavityGeometry& geometry() const { return geometry_; }

  Vec3 wallPoint(const WallCoordinate& w) const;   // eye frame [m]
  Vec3 wallNormal(const WallCoordinate& w) const;  // outward unit normal
  Vec3 capPoint(double u, double meridian) const;  // u in [0, 1], 1 = rim
  Vec3 capNormal(double u, double meridian) const;
  // Normal of the base ellipsoid (no staphyloma) at the same parameters: smooth everywhere.
  Vec3 ellipsoidNormal(const WallCoordinate& w) const;

  double rimTheta() const { return rimTheta_; }  // [rad]
  // Parametric meridian of the plane through the axis at true azimuth atan2(y, x) [rad].
  double meridianOfAzimuth(double azimuth) const;
  // Length along the wall between theta0 and theta1 on one meridian [m].
  double arcLength(double theta0, double theta1, double meridian) const;
  // Wall parameters of the wall point nearest to `p` within p's meridian plane.
  WallCoordinate closestWallCoordinate(const Vec3& p) const;
  // Which part of the boundary `p` is nearest to, and its nearest wall coordinate. Ties (< 1 um,
  // i.e. the rim) go to the part whose normal matches `normal` better, or to the wall without
  // one. ~90 surface evaluations (~7 us).
  CavityProjection project(const Vec3& p, const Vec3* normal = nullptr) const;
  CavityPart closestPart(const Vec3& p, const Vec3* normal = nullptr) const {
    return project(p, normal).part;
  }

  double volume() const { return volume_; }  // [m^3] closed form (header comment)
  Vec3 cornealApex() const;                  // on the axis, anterior of the cavity
  Vec3 posteriorPole() const { return wallPoint({0.0, 0.0}); }
  double axialLength() const;  // [m] corneal apex to posterior pole
  double axialDepth() const;   // [m] cap centre to posterior pole (cavity length on the axis)
  double minimumCurvatureRadius() const;  // [m] smallest radius of curvature of the smooth parts

  // Closed, outward-oriented tessellation with `segments` edges around the axis (>= 8); rings
  // along the meridians are spaced alike, with at least 6 rings across a staphyloma.
  meshing::TriangleMesh triangulate(int segments) const;

 private:
  // Constructor steps, after the rim: the staphyloma's radius and checks, then volume_ and
  // centroidZ_.
  void setStaphyloma();
  void computeVolumeAndCentroid();
  Vec3 localWall(double theta, double meridian) const;
  double bump(double rho) const;                              // depth * g(rho) [m]
  double bumpSlopeOverRho(double rho) const;                  // depth * g'(rho) / rho [1/m]
  double meridianSpeed(double theta, double meridian) const;  // |dP/dtheta| [m/rad]

  CavityGeometry geometry_;
  double rimZ_ = 0.0;        // [m] local z of the rim plane
  double rimTheta_ = 0.0;    // [rad]
  double bumpRadius_ = 0.0;  // [m] R
  double volume_ = 0.0;      // [m^3]
  double centroidZ_ = 0.0;   // [m] local z of the eye-frame origin
};

}  // namespace anatomy
