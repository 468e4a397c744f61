// The meniscus between two parallel walls (validation 3, diagnostic benchmark): oil fills one end
// of a closed slot between a floor and a lid that both carry the contact angle, aqueous the other
// end, no gravity. The interface is then a circular cylinder meeting both walls at theta, and its
// contact lines are straight and as long as the slot is deep, so the contact-line balance is
// measured without the curvature of a small droplet's contact circle (the sessile droplet above
// 140 deg has a contact radius of 1-5 d). Run by `sim_interface_bench meniscus`.
#pragma once

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "interface_fixtures.h"
#include "interface_settle.h"

namespace sim::testing {

struct MeniscusCase {
  Real theta = 90;         // [deg] requested on floor and lid, through the oil
  Real gapPerD = 12;       // [1] H / d, the slot's height in spacings
  Real spacing = 0.0005;   // [m] d
  Real depthPerD = 8;      // [1] the slot's depth (contact-line length) in spacings
  Real tEnd = 0.3;         // [s]
  Real viscosity = 0.005;  // [Pa s] both phases
  Real jitter = 0.2;       // [d]
  bool print = true;
};

struct MeniscusFit {
  Real angle = 90;  // [deg] through the oil, where the fitted circle meets the walls
  Real radius = 0;  // [m]
  Real rms = 0;     // [m]
  std::size_t points = 0;
};

// Circle through the interface midpoints projected on the x-y plane, its centre on the slot's
// mid-height (the two walls carry the same angle), geometric least squares (Gauss-Newton in the
// centre's x and the radius, started from the algebraic fit). Points within `exclude` of the
// floor, the lid or the side walls in z are left out: the walls' kernel support distorts them.
inline MeniscusFit fitMeniscus(const World& w, int oil, Real gap, Real depth, Real exclude) {
  const auto& p = w.particles;
  const Real d = w.particleSpacing();
  const Real yMid = 0.5 * gap;
  std::vector<Eigen::Vector2d> points;
  const NeighborList& nf = w.fluidNeighbors();
  for (Index i = 0; i < static_cast<Index>(p.size()); ++i) {
    if (p.material[i] != oil) continue;
    for (Index k = nf.offsets[i]; k < nf.offsets[i + 1]; ++k) {
      const Index j = nf.indices[k];
      if (p.material[j] == oil || (p.x[j] - p.x[i]).norm() > 1.5 * d) continue;
      const Vec3 mid = 0.5 * (p.x[i] + p.x[j]);
      if (mid.y() < exclude || mid.y() > gap - exclude) continue;
      if (mid.z() < exclude || mid.z() > depth - exclude) continue;
      points.emplace_back(mid.x(), mid.y() - yMid);
    }
  }
  MeniscusFit fit;
  fit.points = points.size();
  if (points.size() < 8) return fit;
  // Algebraic start: x^2 + y^2 = 2 x xc + c, c = r^2 - xc^2.
  Eigen::MatrixXd a(points.size(), 2);
  Eigen::VectorXd b(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    a(k, 0) = 2 * points[k].x();
    a(k, 1) = 1;
    b(k) = points[k].squaredNorm();
  }
  const Eigen::Vector2d s = a.colPivHouseholderQr().solve(b);
  Real xc = s(0), r = std::sqrt(std::max(s(1) + xc * xc, Real(0)));
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::Matrix2d jtj = Eigen::Matrix2d::Zero();
    Eigen::Vector2d jtr = Eigen::Vector2d::Zero();
    for (const auto& q : points) {
      const Real dist = std::hypot(q.x() - xc, q.y());
      const Eigen::Vector2d jac(-(q.x() - xc) / dist, -1.0);
      jtj += jac * jac.transpose();
      jtr += jac * (dist - r);
    }
    const Eigen::Vector2d step = jtj.ldlt().solve(-jtr);
    xc += step(0);
    r += step(1);
    if (step.norm() < 1e-9 * gap) break;
  }
  Real sum = 0, meanX = 0;
  for (const auto& q : points) {
    sum += std::pow(std::hypot(q.x() - xc, q.y()) - r, 2);
    meanX += q.x();
  }
  meanX /= static_cast<Real>(points.size());
  fit.radius = r;
  fit.rms = std::sqrt(sum / static_cast<Real>(points.size()));
  // The oil is at x below the interface. An arc right of its centre bulges into the aqueous at
  // mid-height: the walls hold the oil back, theta > 90 deg; left of it, theta < 90 deg.
  const Real side = meanX > xc ? -1.0 : 1.0;
  const Real c = std::clamp(side * 0.5 * gap / r, Real(-1), Real(1));
  fit.angle = std::acos(c) * 180 / std::numbers::pi;
  return fit;
}

using MeniscusResult = AngleRunResult;

inline MeniscusResult runMeniscus(const MeniscusCase& c) {
  const Real d = c.spacing;
  const Real gap = c.gapPerD * d, depth = c.depthPerD * d, length = 3 * gap;
  TankSpec spec;
  spec.innerMin = Vec3::Zero();
  spec.innerMax = Vec3(length, gap, depth);
  spec.closedTop = true;
  OilAqueousBox box = oilAqueousLayeredBox(spec, d, c.viscosity);
  World& w = *box.world;
  const int oil = box.oil, aqueous = box.aqueous;
  for (std::size_t b = 0; b < w.walls.size(); ++b)
    if (std::abs(w.walls.normal[b].y()) > 0.5) w.walls.tag[b] = kFloorTag;  // floor and lid
  const int nx = static_cast<int>(std::lround(length / d));
  const int ny = static_cast<int>(std::lround(gap / d));
  const int nz = static_cast<int>(std::lround(depth / d));
  fillJitteredLattice(w, Vec3::Zero(), nx, ny, nz, d, c.jitter, 0.0, [&](const Vec3& x) {
    return x.x() < 0.5 * length ? oil : aqueous;  // a flat (90 deg) start
  });
  w.materials.setContactAngle(oil, kFloorTag, c.theta);
  w.initialize();
  const auto measure = [&](const World& world) {
    return fitMeniscus(world, oil, gap, depth, d).angle;
  };
  const auto describe = [&](const World& world) {
    const MeniscusFit f = fitMeniscus(world, oil, gap, depth, d);
    char line[128];
    std::snprintf(line, sizeof line,
                  "theta = %.1f deg (R = %.2f mm = %.2f H, rms %.3f mm, %zu points)", f.angle,
                  f.radius * 1e3, f.radius / gap, f.rms * 1e3, f.points);
    return std::string(line);
  };
  return settleContactAngle(w, c.tEnd, c.print, measure, describe);
}

}  // namespace sim::testing
