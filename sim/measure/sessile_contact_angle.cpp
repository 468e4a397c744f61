#include "sim/measure/sessile_contact_angle.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace sim {

SphereFit fitSphere(const std::vector<Vec3>& points) {
  require(points.size() >= 4, "sphere fit needs at least 4 points");
  // Normal equations of |x|^2 = 2 c.x + k (unknowns c, k), solved in the coordinates relative to
  // the points' mean for conditioning.
  Vec3 mean = Vec3::Zero();
  for (const Vec3& x : points) mean += x;
  mean /= static_cast<Real>(points.size());
  Eigen::Matrix4d ata = Eigen::Matrix4d::Zero();
  Eigen::Vector4d atb = Eigen::Vector4d::Zero();
  for (const Vec3& x : points) {
    const Vec3 y = x - mean;
    const Eigen::Vector4d row(2 * y.x(), 2 * y.y(), 2 * y.z(), 1.0);
    ata += row * row.transpose();
    atb += row * y.squaredNorm();
  }
  const Eigen::Vector4d sol = ata.ldlt().solve(atb);
  require(sol.allFinite(), "sphere fit is degenerate (points coplanar?)");
  SphereFit fit;
  const Vec3 c = sol.head<3>();
  const Real r2 = sol[3] + c.squaredNorm();
  require(r2 > 0, "sphere fit is degenerate");
  fit.centre = c + mean;
  fit.radius = std::sqrt(r2);
  Real sum = 0;
  for (const Vec3& x : points) {
    const Real e = (x - fit.centre).norm() - fit.radius;
    sum += e * e;
  }
  fit.rmsResidual = std::sqrt(sum / static_cast<Real>(points.size()));
  return fit;
}

std::vector<Vec3> interfacePairMidpoints(const World& world, int material) {
  const auto& p = world.particles;
  const NeighborList& nf = world.fluidNeighbors();
  const Real maxPair = 1.5 * world.particleSpacing();
  std::vector<Vec3> points;
  for (Index i = 0; i < p.size(); ++i) {
    if (p.material[i] != material) continue;
    for (const Index* j = nf.begin(i); j != nf.end(i); ++j) {
      if (p.material[*j] == material) continue;
      if ((p.x[i] - p.x[*j]).norm() > maxPair) continue;
      points.push_back(0.5 * (p.x[i] + p.x[*j]));
    }
  }
  return points;
}

CapFit fitSessileCap(const World& world, int dropletMaterial, const WallPlane& wall,
                     Real excludeNearWall) {
  const Vec3 n = wall.normal.normalized();
  std::vector<Vec3> points = interfacePairMidpoints(world, dropletMaterial);
  std::erase_if(points, [&](const Vec3& x) { return (x - wall.point).dot(n) < excludeNearWall; });
  require(points.size() >= 4, "sessile cap fit: fewer than 4 interface points above the wall");
  CapFit out;
  out.sphere = fitSphere(points);
  out.pointCount = static_cast<int>(points.size());
  const Real zc = (out.sphere.centre - wall.point).dot(n);
  out.contactAngle =
      std::acos(std::clamp(-zc / out.sphere.radius, Real(-1), Real(1))) * 180.0 / std::numbers::pi;
  return out;
}

}  // namespace sim
