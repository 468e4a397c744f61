// The sessile ridge (validation 3 benchmark, `sim_interface_bench ridge`): a sessile droplet that
// is a long cylindrical segment of oil on the floor of a closed aqueous box, its axis along z
// between two neutral walls, no gravity. Its cross-section is a circular segment meeting the floor
// at theta, and its two contact lines are straight and as long as the box is deep.
//
// Why a ridge and not only the round droplet (interface_sessile.h): at the angles where a round
// droplet's contact disc shrinks below the wall terms' 2 d support, the balance is no longer
// resolved. At 165 deg its contact radius is R sin 15 = 0.2 R0: 1.2 d at R0 = 6 d. Holding 4 d
// would need R0 = 20 d, about 75k particles. A ridge's contact lines are straight at any angle;
// only their distance (2 R sin theta) has to exceed the support. A flat 30 deg droplet has the
// opposite problem: at R0 = 6 d its cap is 2.7 d tall, all inside the wall's support. A ridge of
// the same cross-section area as a half-disc of R0 = 12 d stands 6.7 d tall at 30 deg, on about
// as many particles as a round R0 = 6 d droplet.
//
// The angle is fitted like the round droplet's volume cap (sim/measure/sessile_contact_angle.h):
// the circular segment of the ridge's cross-section area that best fits the interface points,
// centred on the oil's centroid in x. Points less than d from the floor or from the front and back
// walls are left out, since the walls' kernel support distorts them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "interface_fixtures.h"
#include "interface_settle.h"
#include "sim/measure/sessile_contact_angle.h"

namespace sim::testing {

struct RidgeCase {
  Real theta = 90;        // [deg] requested on the floor, through the oil
  Real startTheta = 90;   // [deg] the start segment, through the oil
  Real r0PerD = 12;       // [1] radius of the half-disc whose area the cross-section has, in d
  Real spacing = 0.0005;  // [m] d
  Real depthPerD = 16;    // [1] the ridge's length (contact-line length) in spacings
  Real tEnd = 0.3;        // [s]
  Real viscosity = 0.05;  // [Pa s] both phases
  Real jitter = 0.2;      // [d] start positions moved by up to this per axis
  bool print = false;     // print the angle ten times during the run
};

struct RidgeFit {
  Real angle = 90;  // [deg] through the oil
  Real radius = 0;  // [m] of the fitted segment's circle
  Real rms = 0;     // [m] residual of the interface points
  std::size_t points = 0;
};

// [m] Radius of the circular segment of cross-section `area` that meets the floor at `theta`
// (rad, through the segment): area = R^2 (theta - sin theta cos theta).
inline Real ridgeRadius(Real area, Real theta) {
  return std::sqrt(area / (theta - std::sin(theta) * std::cos(theta)));
}

// [m] Half-width and top of that segment: the widest chord is 2 R when theta > 90 deg.
inline Real ridgeHalfWidth(Real area, Real theta) {
  const Real r = ridgeRadius(area, theta);
  return theta > std::numbers::pi / 2 ? r : r * std::sin(theta);
}
inline Real ridgeTop(Real area, Real theta) {
  return ridgeRadius(area, theta) * (1 - std::cos(theta));
}

inline RidgeFit fitRidge(const World& w, int oil, Real depth) {
  const Real d = w.particleSpacing();
  const auto& p = w.particles;
  std::vector<Vec3> points = interfacePairMidpoints(w, oil);
  std::erase_if(points, [&](const Vec3& x) { return x.y() < d || x.z() < d || x.z() > depth - d; });
  RidgeFit fit;
  fit.points = points.size();
  if (points.size() < 8) return fit;
  Real volume = 0, xc = 0;
  for (Index i = 0; i < static_cast<Index>(p.size()); ++i) {
    if (p.material[i] != oil) continue;
    const Real v = p.mass[i] / (p.density[i] > 0 ? p.density[i] : w.materials[oil].restDensity);
    volume += v;
    xc += v * p.x[i].x();
  }
  xc /= volume;
  const Real area = volume / depth;  // [m^2]
  const auto residual = [&](Real theta) {
    const Real r = ridgeRadius(area, theta), yc = -r * std::cos(theta);
    Real sum = 0;
    for (const Vec3& x : points) sum += std::pow(std::hypot(x.x() - xc, x.y() - yc) - r, 2);
    return sum;
  };
  // Golden-section search over (0.5, 179.5) deg: the residual has one minimum on a segment.
  const Real g = (std::sqrt(5.0) - 1) / 2;
  Real a = 0.5 * std::numbers::pi / 180, b = std::numbers::pi - a;
  Real c1 = b - g * (b - a), c2 = a + g * (b - a), f1 = residual(c1), f2 = residual(c2);
  for (int k = 0; k < 60; ++k) {
    if (f1 < f2) {
      b = c2, c2 = c1, f2 = f1, c1 = b - g * (b - a), f1 = residual(c1);
    } else {
      a = c1, c1 = c2, f1 = f2, c2 = a + g * (b - a), f2 = residual(c2);
    }
  }
  const Real theta = 0.5 * (a + b);
  fit.angle = theta * 180 / std::numbers::pi;
  fit.radius = ridgeRadius(area, theta);
  fit.rms = std::sqrt(residual(theta) / static_cast<Real>(points.size()));
  return fit;
}

struct RidgeScene {
  std::unique_ptr<World> world;
  int oil = -1;
  Real depth = 0;  // [m]
};

// The box and the start segment: the box clears the start and the requested segment by 3 h at
// the sides and 2 h above (a segment touching the neutral lid or side walls would bridge to them,
// docs/methods/interface.md validation 3); three lattice wall layers; the angle on the floor.
inline RidgeScene ridgeScene(const RidgeCase& c) {
  const Real d = c.spacing, h = 2 * d;
  const Real area = 0.5 * std::numbers::pi * std::pow(c.r0PerD * d, 2);  // [m^2]
  const Real start = c.startTheta * std::numbers::pi / 180;
  const Real requested = c.theta * std::numbers::pi / 180;
  const auto cells = [&](Real length) { return d * std::ceil(length / d); };
  const Real halfWidth =
      cells(std::max(ridgeHalfWidth(area, start), ridgeHalfWidth(area, requested)) + 3 * h);
  const Real height = cells(std::max(ridgeTop(area, start), ridgeTop(area, requested)) + 2 * h);
  RidgeScene scene;
  scene.depth = cells(c.depthPerD * d);
  TankSpec spec;
  spec.innerMin = Vec3::Zero();
  spec.innerMax = Vec3(2 * halfWidth, height, scene.depth);
  spec.closedTop = true;
  OilAqueousBox box = oilAqueousLayeredBox(spec, d, c.viscosity);
  scene.world = std::move(box.world);
  World& w = *scene.world;
  scene.oil = box.oil;
  const int aqueous = box.aqueous;
  for (std::size_t b = 0; b < w.walls.size(); ++b)
    if (w.walls.normal[b].y() < -0.5) w.walls.tag[b] = kFloorTag;  // the floor only
  const Real r = ridgeRadius(area, start), yc = -r * std::cos(start);
  const int nx = static_cast<int>(std::lround(2 * halfWidth / d));
  const int ny = static_cast<int>(std::lround(height / d));
  const int nz = static_cast<int>(std::lround(scene.depth / d));
  fillJitteredLattice(w, Vec3::Zero(), nx, ny, nz, d, c.jitter, 0.0, [&](const Vec3& x) {
    return std::hypot(x.x() - halfWidth, x.y() - yc) < r ? scene.oil : aqueous;
  });
  w.materials.setContactAngle(scene.oil, kFloorTag, c.theta);
  w.initialize();
  return scene;
}

using RidgeResult = AngleRunResult;

inline RidgeResult runRidge(const RidgeCase& c) {
  RidgeScene scene = ridgeScene(c);
  const auto measure = [&](const World& w) { return fitRidge(w, scene.oil, scene.depth).angle; };
  const auto describe = [&](const World& w) {
    const RidgeFit f = fitRidge(w, scene.oil, scene.depth);
    char line[128];
    std::snprintf(line, sizeof line, "theta = %.1f deg (R = %.2f mm, rms %.3f mm, %zu points)",
                  f.angle, f.radius * 1e3, f.rms * 1e3, f.points);
    return std::string(line);
  };
  return settleContactAngle(*scene.world, c.tEnd, c.print, measure, describe);
}

}  // namespace sim::testing
