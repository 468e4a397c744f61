// What the equilibrium's oil touches, read below the voxel scale. Near the contact line the
// aqueous wedge between oil and wall is thinner than a voxel over several voxels (h / tan(theta):
// 3 h at the retina's 18 deg), so reading the oil share next to the wall calls that wedge oil. The
// reader therefore reconstructs the interface where it is resolved and extends it to the wall at
// the contact angle, as volume-of-fluid codes extend an interface to a wetting wall:
//  1. interface points where u (the oil share) crosses 1/2 between neighbouring whole fluid
//     voxels (the wall cuts none of them), placed by linear interpolation, each with its normal;
//  2. at a wall point w with outward normal n, the signed distance D(p) of p = w - delta n from
//     the tangent plane of the nearest interface point (positive in oil; the sign from u(p));
//     delta = 1.5 h reaches past the voxels the wall cuts;
//  3. the interface meets the wall at theta through the aqueous, so its normal m (into the oil)
//     has m . n = -cos(theta) there and D(w) = D(p) - delta cos(theta): exact for a planar wedge
//     (WallExtension::kPlanar). WallExtension::kArc instead lets the interface turn from its own
//     angle psi at p (cos psi = -m . n) to theta at the wall along a circular arc, whose run along
//     the wall is delta cot(a), a = (psi + theta) / 2: D(w) = D(p) - delta sin(psi) cot(a).
//     Exact for a meniscus of constant curvature in the wall's normal section; equal to kPlanar
//     when psi = theta.
//  4. next to a wall the interface turns from its far shape to theta over about a capillary
//     length l_c = sqrt(sigma / (|rho_oil - rho_aq| g)) (the linearised meniscus decays as
//     exp(-s / l_c); de Gennes, Brochard-Wyart & Quere 2004, "Capillarity and Wetting Phenomena",
//     sec. 2.1). When l_c < delta (weak tension: the flat limit) the interface is carried at its
//     own angle psi from p down to l_c from the wall and extended at theta only over that last
//     l_c; when l_c >= delta (the eye: l_c = 11 mm for silicone oil) steps 2-3 are unchanged.
// The wall point is oil-covered when D(w) > 0. docs/methods/equilibrium.md gives the reading's
// measured error on imposed Young-Laplace states.
#pragma once

#include <vector>

#include "sim/equilibrium/threshold_dynamics_xu2017.h"

namespace sim::equilibrium {

enum class WallExtension { kPlanar, kArc };

class WallOilReader {
 public:
  // `contactAngle` [rad] through the aqueous; `offsetVoxels` delta / h.
  WallOilReader(const EquilibriumSolution& solution, double contactAngle, double offsetVoxels = 1.5,
                WallExtension extension = WallExtension::kPlanar);

  // [m] D(w), the signed distance of wall point `w` [m] (outward unit normal `n`) from the
  // interface extended to the wall; > 0: oil-covered.
  double wallSignedDistance(const Vec3& w, const Vec3& n) const;
  bool oilCovered(const Vec3& w, const Vec3& n) const { return wallSignedDistance(w, n) > 0.0; }
  // [1] the fluid-weighted oil share u at x (0 where no fluid voxel is near).
  double oilShare(const Vec3& x) const;
  const std::vector<Vec3>& interfacePoints() const { return points_; }  // [m]

 private:
  std::size_t nearestPoint(const Vec3& x) const;  // points_.size() if none within reach_

  VoxelGrid grid_;
  std::vector<double> u_, f_;
  std::vector<Vec3> points_, normals_;  // interface points [m] and unit normals into the oil
  // Interface points binned in cubic cells of edge reach_ (CSR: cellStart_, cellPoints_).
  VoxelGrid bins_;
  std::vector<std::size_t> cellStart_, cellPoints_;
  double reach_ = 0.0;   // [m] farthest distance resolved
  double offset_ = 0.0;  // [m] delta
  // [m] min(delta, the solution's capillary length): the interface keeps its own angle down to
  // this distance from the wall and turns to theta below it
  double turning_ = 0.0;
  double theta_ = 0.0;  // [rad]
  double cosTheta_ = 0.0;
  WallExtension extension_ = WallExtension::kPlanar;
};

}  // namespace sim::equilibrium
