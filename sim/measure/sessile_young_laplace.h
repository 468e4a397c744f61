// The shape of a sessile droplet under gravity (validation 3 under gravity): the
// axisymmetric Young-Laplace equation in Bashforth & Adams' form (1883), integrated from the apex,
//   dx/ds = cos phi,  dz/ds = sin phi,  dphi/ds = 2 b + c z - sin(phi) / x,
// x the distance from the axis, z the depth below the apex, phi the tangent's angle, s the arc
// length, b the apex curvature [1/m] and c = (rho_drop - rho_around) g / sigma [1/m^2] (> 0: the
// droplet is pressed onto the wall; c = 0 is the spherical cap). The profile ends where phi
// reaches the contact angle theta (through the droplet), which is where the wall is. For a given
// volume, c and theta, b is the one that gives the volume. Without gravity the cap of
// sessile_contact_angle.h is the special case; a wide droplet (a puddle) tends to the height
// 2 sqrt(sigma / (delta rho g)) sin(theta / 2) (de Gennes, Brochard-Wyart & Quere 2004, ch. 2):
// both are tests of this integration (tests/sim/test_sessile_young_laplace.cpp).
#pragma once

#include <utility>
#include <vector>

#include "sim/core/types.h"

namespace sim {

struct SessileShape {
  Real apexCurvature = 0;  // [1/m] b
  Real height = 0;         // [m] apex above the wall
  Real contactRadius = 0;  // [m] radius of the wetted disc
  Real widest = 0;         // [m] largest radius of the profile
  Real volume = 0;         // [m^3]
};

// The Young-Laplace droplet of `volume` [m^3] meeting the wall at `thetaDeg` (through the droplet,
// in (0, 180)), c = delta rho g / sigma >= 0 [1/m^2]. `sectionHeight` >= 0 [m]: also return, in
// *sectionRadius, the profile's radius at that height above the wall (the outermost crossing; 0
// above the apex). Throws SimError for arguments outside these ranges.
SessileShape youngLaplaceSessile(Real volume, Real capillaryConstant, Real thetaDeg,
                                 Real sectionHeight = 0, Real* sectionRadius = nullptr);

// The same droplet's outline as (height above the wall, radius) pairs [m] from the apex down to
// the wall, `samples` + 1 of them evenly along the profile. The height falls monotonically along
// it (the tangent turns from 0 to theta < 180 deg), so the radius is a function of the height.
// The samples are the integration's step ends (steps of 1e-2 of the apex radius or capillary
// length, whichever is smaller): asked for more samples than steps, consecutive ones repeat.
std::vector<std::pair<Real, Real>> youngLaplaceOutline(Real volume, Real capillaryConstant,
                                                       Real thetaDeg, int samples = 400);

// The angle [deg] through the droplet, in [90, 180], of the Young-Laplace droplet of `volume`
// whose section at `height` above the wall has radius `sectionRadius`: capAngleOfFootprint
// (sessile_contact_angle.h) under gravity. A radius wider than the 90 deg droplet's reads 90,
// narrower than the 179.5 deg droplet's reads 180.
Real youngLaplaceAngleOfFootprint(Real volume, Real capillaryConstant, Real sectionRadius,
                                  Real height);

// [m] Root-mean-square distance of the interface `points` from the outline of the Young-Laplace
// droplet of `volume` [m^3], c and `thetaDeg`, in the meridian plane of the droplet sitting on the
// wall plane through `wallPoint` (unit normal `wallNormal` into the fluid) with its axis through
// `axisPoint`: the cost of the outline fits below.
Real youngLaplaceOutlineResidual(const std::vector<Vec3>& points, const Vec3& wallPoint,
                                 const Vec3& wallNormal, const Vec3& axisPoint, Real volume,
                                 Real capillaryConstant, Real thetaDeg);

// The angle [deg] through the droplet, in [90, 179], of the Young-Laplace droplet of `volume`
// [m^3] (c as above) sitting on the wall plane through `wallPoint` with unit normal `wallNormal`
// (into the fluid), its axis through `axisPoint`, whose outline fits the interface `points` best
// (least squares of their distances to the outline in the meridian plane; a 2 deg scan, then a
// golden-section search): fitSessileCap's volume-constrained cap under gravity.
Real youngLaplaceAngleOfPoints(const std::vector<Vec3>& points, const Vec3& wallPoint,
                               const Vec3& wallNormal, const Vec3& axisPoint, Real volume,
                               Real capillaryConstant);

// The Young-Laplace droplet fitted with its capillary constant free as well as its angle:
// axisymmetric drop shape analysis (Rotenberg, Boruvka & Neumann 1983), which reads the contact
// angle and the interfacial tension of a real droplet from its outline alone. Here the tension is
// known, so the fitted c says how the simulated droplet's balance of gravity against tension
// departs from the nominal one, and the angle is read without assuming that balance.
struct YoungLaplaceShapeFit {
  Real angle = 0;              // [deg] through the droplet, in [90, 179]
  Real capillaryConstant = 0;  // [1/m^2] the fitted c
  Real nominalRatio = 0;       // [1] nominal c / fitted c: sigma_eff / sigma if delta rho g holds
  Real rmsResidual = 0;        // [m] of the points from the fitted outline
};

// youngLaplaceAngleOfPoints with c free: nominal c / c is searched over [0.5, 1.5] (0.05 steps,
// then a golden-section search), the angle fitted for each. `nominalCapillaryConstant` > 0.
YoungLaplaceShapeFit youngLaplaceShapeOfPoints(const std::vector<Vec3>& points,
                                               const Vec3& wallPoint, const Vec3& wallNormal,
                                               const Vec3& axisPoint, Real volume,
                                               Real nominalCapillaryConstant);

}  // namespace sim
