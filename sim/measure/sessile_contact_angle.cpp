#include "sim/measure/sessile_contact_angle.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "sim/measure/scan_golden_minimum.h"

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

SphereFit fitSphereGeometric(const std::vector<Vec3>& points, const SphereFit& start) {
  require(points.size() >= 4, "sphere fit needs at least 4 points");
  // Gauss-Newton on r_k = |x_k - c| - R (unknowns c, R): the Jacobian row is (-(x_k - c)/|x_k - c|,
  // -1). Started from the algebraic fit it converges in a few iterations; the step is halved
  // while it does not lower the residual (a damped Gauss-Newton).
  Vec3 c = start.centre;
  Real radius = start.radius;
  auto cost = [&](const Vec3& cc, Real rr) {
    Real sum = 0;
    for (const Vec3& x : points) {
      const Real e = (x - cc).norm() - rr;
      sum += e * e;
    }
    return sum;
  };
  Real current = cost(c, radius);
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::Matrix4d jtj = Eigen::Matrix4d::Zero();
    Eigen::Vector4d jtr = Eigen::Vector4d::Zero();
    for (const Vec3& x : points) {
      const Vec3 r = x - c;
      const Real dist = r.norm();
      if (dist == 0) continue;
      const Eigen::Vector4d row(-r.x() / dist, -r.y() / dist, -r.z() / dist, -1.0);
      jtj += row * row.transpose();
      jtr += row * (dist - radius);
    }
    const Eigen::Vector4d step = jtj.ldlt().solve(-jtr);
    if (!step.allFinite()) break;
    Real scale = 1;
    bool lowered = false;
    for (int halving = 0; halving < 30 && !lowered; ++halving, scale *= 0.5) {
      const Vec3 cc = c + scale * step.head<3>();
      const Real rr = radius + scale * step[3];
      const Real trial = cost(cc, rr);
      if (rr > 0 && trial < current) {
        lowered = true;
        const Real change = current - trial;
        c = cc;
        radius = rr;
        current = trial;
        if (change <= 1e-14 * current) iteration = 50;  // converged
      }
    }
    if (!lowered) break;
  }
  SphereFit fit;
  fit.centre = c;
  fit.radius = radius;
  fit.rmsResidual = std::sqrt(current / static_cast<Real>(points.size()));
  return fit;
}

namespace {

// [m] Sphere radius of the cap of `volume` [m^3] meeting the wall at the angle whose cosine is u:
// V = pi R^3 (2 + u)(1 - u)^2 / 3; the centre lies -R u above the wall.
Real capRadius(Real volume, Real u) {
  return std::cbrt(3 * volume / (std::numbers::pi * (2 + u) * (1 - u) * (1 - u)));
}

}  // namespace

Real capAngleOfFootprint(Real volume, Real sectionRadius, Real height) {
  require(volume > 0 && sectionRadius >= 0 && height >= 0,
          "footprint angle needs a positive volume and a non-negative radius and height");
  // Section radius at `height` of the volume's cap of angle theta (centre -R cos above the wall).
  auto section = [&](Real theta) {
    const Real u = std::cos(theta);
    const Real radius = capRadius(volume, u);
    const Real dz = height + radius * u;  // height above the centre
    return std::sqrt(std::max<Real>(0, radius * radius - dz * dz));
  };
  // The widest section: caps flatter than its angle are lower than `height` near their rim and
  // narrower there, so only the angles from it to 180 deg are a footprint's.
  const Real degree = std::numbers::pi / 180;
  const Real widest =
      scanGoldenMinimum([&](Real theta) { return -section(theta); },
                        {degree, std::numbers::pi, degree, degree, std::numbers::pi});
  Real lo = widest, hi = std::numbers::pi;  // section(lo) >= r >= section(hi)
  if (sectionRadius >= section(lo)) return lo / degree;
  if (sectionRadius <= section(hi)) return 180;
  for (int k = 0; k < 60; ++k) {
    const Real mid = 0.5 * (lo + hi);
    (section(mid) > sectionRadius ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) / degree;
}

Real capAngleOfCentroid(Real volume, Real centroidHeight) {
  require(volume > 0, "centroid angle needs a positive volume");
  auto height = [&](Real theta) {
    const Real u = std::cos(theta);
    const Real radius = capRadius(volume, u), capHeight = radius * (1 - u);
    return capHeight * (4 * radius - capHeight) / (4 * (3 * radius - capHeight));
  };
  Real lo = 1e-6, hi = std::numbers::pi - 1e-6;  // height(lo) <= centroidHeight <= height(hi)
  if (centroidHeight <= height(lo)) return 0;
  if (centroidHeight >= height(hi)) return 180;
  for (int k = 0; k < 60; ++k) {
    const Real mid = 0.5 * (lo + hi);
    (height(mid) < centroidHeight ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) * 180 / std::numbers::pi;
}

Real capAngleOfVolume(const std::vector<Vec3>& points, const WallPlane& wall, const Vec3& axisPoint,
                      Real volume) {
  require(points.size() >= 4 && volume > 0, "cap fit needs points and a positive volume");
  const Vec3 n = wall.normal.normalized();
  const Vec3 foot = axisPoint - (axisPoint - wall.point).dot(n) * n;  // the axis meets the wall
  // Cap of angle theta (through the droplet) and volume V (capRadius), centre -R cos(theta)
  // above the wall on the axis.
  auto cost = [&](Real theta) {
    const Real u = std::cos(theta);
    const Real radius = capRadius(volume, u);
    const Vec3 c = foot - radius * u * n;
    Real sum = 0;
    for (const Vec3& x : points) {
      const Real e = (x - c).norm() - radius;
      sum += e * e;
    }
    return sum;
  };
  // 1 deg samples over 1-179 deg, then golden-section search in the best sample's bracket.
  const Real degree = std::numbers::pi / 180;
  return scanGoldenMinimum([&](Real thetaDeg) { return cost(thetaDeg * degree); },
                           ScanGoldenSearch{1, 179, 1, 0, 180, 60});
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
  const auto& p = world.particles;
  const Real restDensity = world.materials[dropletMaterial].restDensity;
  Vec3 centroid = Vec3::Zero();
  Real volume = 0;
  for (Index i = 0; i < p.size(); ++i) {
    if (p.material[i] != dropletMaterial) continue;
    const Real v = p.mass[i] / (p.density[i] > 0 ? p.density[i] : restDensity);  // [m^3]
    centroid += v * p.x[i];
    volume += v;
  }
  centroid /= volume;
  CapFit out;
  out.sphere = fitSphere(points);
  const Real zc = (out.sphere.centre - wall.point).dot(n);
  out.sphereAngle =
      std::acos(std::clamp(-zc / out.sphere.radius, Real(-1), Real(1))) * 180.0 / std::numbers::pi;
  out.volume = volume;
  out.contactAngle = capAngleOfVolume(points, wall, centroid, volume);
  out.centroidAngle = capAngleOfCentroid(volume, (centroid - wall.point).dot(n));
  const Real u = std::cos(out.contactAngle * std::numbers::pi / 180.0);
  out.capRadius = capRadius(volume, u);
  out.points = std::move(points);
  out.centroid = centroid;
  return out;
}

}  // namespace sim
