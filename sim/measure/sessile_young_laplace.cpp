#include "sim/measure/sessile_young_laplace.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "sim/core/error.h"
#include "sim/measure/scan_golden_minimum.h"

namespace sim {
namespace {

// State along the profile: x, z, phi and the volume enclosed so far, pi x^2 dz.
using State = std::array<Real, 4>;

State derivative(const State& y, Real b, Real c) {
  const Real x = y[0], z = y[1], phi = y[2];
  // At the apex sin(phi) / x -> dphi/ds = b, so dphi/ds = b there.
  const Real curvature = x > 0 ? 2 * b + c * z - std::sin(phi) / x : b;
  return {std::cos(phi), std::sin(phi), curvature, std::numbers::pi * x * x * std::sin(phi)};
}

struct Profile {
  SessileShape shape;
  Real sectionRadius = 0;
};

// Integrates from the apex (RK4 in s) to phi = theta. With sectionHeight >= 0 the outermost
// radius at that height above the (then known) wall is found on a second pass over the same
// steps, which is cheaper than storing them.
Profile integrate(Real b, Real c, Real theta, Real sectionHeight, Real stepFraction,
                  const std::function<void(Real depth, Real radius)>& onStep = {}) {
  // Step: a small fraction of the smallest length of the problem (apex radius, capillary length).
  const Real length = c > 0 ? std::min(1 / b, 1 / std::sqrt(c)) : 1 / b;
  const Real ds = length * stepFraction;
  auto rk4 = [&](const State& y, Real h) {
    const State k1 = derivative(y, b, c);
    State t;
    for (int i = 0; i < 4; ++i) t[i] = y[i] + 0.5 * h * k1[i];
    const State k2 = derivative(t, b, c);
    for (int i = 0; i < 4; ++i) t[i] = y[i] + 0.5 * h * k2[i];
    const State k3 = derivative(t, b, c);
    for (int i = 0; i < 4; ++i) t[i] = y[i] + h * k3[i];
    const State k4 = derivative(t, b, c);
    State next;
    for (int i = 0; i < 4; ++i) next[i] = y[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return next;
  };
  auto run = [&](auto&& visit) {
    State y{0, 0, 0, 0};
    Real widest = 0;
    for (long k = 0; k < 20000000; ++k) {
      State next = rk4(y, ds);
      if (next[2] >= theta) {
        // The wall: the partial step that ends at phi = theta, by secant iteration on its length
        // (a linear interpolation of the whole step would cost the 1e-6 accuracy of the rest).
        Real h0 = 0, p0 = y[2], h1 = ds, p1 = next[2];
        for (int it = 0; it < 20 && std::abs(p1 - theta) > 1e-14; ++it) {
          const Real h2 = h1 + (theta - p1) * (h1 - h0) / (p1 - p0);
          h0 = h1, p0 = p1;
          h1 = std::clamp(h2, Real(0), ds);
          next = rk4(y, h1);
          p1 = next[2];
        }
        visit(y, next);
        return std::pair{next, std::max(widest, next[0])};
      }
      // A profile that turns back up (phi falling below 0) never meets the wall at theta.
      require(next[2] > 0 && next[0] >= 0, "Young-Laplace profile does not reach the wall");
      visit(y, next);
      widest = std::max(widest, next[0]);
      y = next;
    }
    throw SimError("Young-Laplace profile: too many steps");
  };
  const auto [end, widest] = run([&](const State&, const State& e) {
    if (onStep) onStep(e[1], e[0]);
  });
  Profile p;
  p.shape.apexCurvature = b;
  p.shape.height = end[1];
  p.shape.contactRadius = end[0];
  p.shape.widest = widest;
  p.shape.volume = end[3];
  if (sectionHeight >= 0 && sectionHeight < end[1]) {
    const Real depth = end[1] - sectionHeight;  // [m] below the apex
    Real outer = 0;
    run([&](const State& a, const State& e) {
      if ((a[1] - depth) * (e[1] - depth) <= 0 && a[1] != e[1]) {
        const Real f = (depth - a[1]) / (e[1] - a[1]);
        outer = std::max(outer, a[0] + f * (e[0] - a[0]));
      }
    });
    p.sectionRadius = outer;
  }
  return p;
}

// Steps of the integration, as fractions of the problem's smallest length. The shape and its
// sections: 2e-3 (the section is interpolated linearly between steps, to 1e-5 of the radius). The
// outline the fits compare with: 1e-2, five times fewer steps, still 1e-8 of the droplet's size
// (RK4's error falls as the step's fourth power) with two or more steps per outline sample.
constexpr Real kShapeStep = 2e-3;
constexpr Real kOutlineStep = 1e-2;

// The apex curvature b of the droplet of `volume` (arguments checked by the caller).
Real apexCurvature(Real volume, Real capillaryConstant, Real theta, Real stepFraction) {
  // The volume falls as the apex curvature b grows. Without gravity b is the cap's 1 / R; gravity
  // flattens the apex, so the root lies below that.
  const Real u = std::cos(theta);
  const Real capR = std::cbrt(3 * volume / (std::numbers::pi * (2 + u) * (1 - u) * (1 - u)));
  // A puddle's apex is flat to within exp(-radius / l_c): the bracket reaches far below 1 / R.
  // The root is sought in log b: bisection until the bracket spans a factor 2, where the volume
  // is smooth in log b, then the Illinois variant of regula falsi (Dowell & Jarratt 1971), which
  // needs about 8 integrations where bisection to the same 1e-13 needed 40 more (the outline
  // fits integrate thousands of droplets).
  const auto excess = [&](Real logB) {  // > 0: b too small (the droplet too big)
    return integrate(std::exp(logB), capillaryConstant, theta, -1, stepFraction).shape.volume /
               volume -
           1;
  };
  Real lo = std::log(1e-30 / capR), hi = std::log(1.01 / capR);
  Real excessLo = std::numeric_limits<Real>::quiet_NaN(), excessHi = excessLo;
  while (hi - lo > std::numbers::ln2) {
    const Real mid = 0.5 * (lo + hi);
    const Real e = excess(mid);
    if (e > 0)
      lo = mid, excessLo = e;
    else
      hi = mid, excessHi = e;
  }
  if (std::isnan(excessLo)) excessLo = excess(lo);
  if (std::isnan(excessHi)) excessHi = excess(hi);
  Real root = excessLo == 0 ? lo : hi;
  int lastSide = 0;  // which end moved last: the other end's value is halved when it repeats
  for (int k = 0; k < 100 && excessLo != 0 && excessHi != 0 && hi - lo > 1e-13; ++k) {
    root = (lo * excessHi - hi * excessLo) / (excessHi - excessLo);
    const Real e = excess(root);
    if (e > 0) {
      lo = root, excessLo = e;
      if (lastSide == -1) excessHi *= 0.5;
      lastSide = -1;
    } else {
      hi = root, excessHi = e;
      if (lastSide == 1) excessLo *= 0.5;
      lastSide = 1;
    }
    if (std::abs(e) < 1e-14) break;
  }
  return std::exp(root);
}

void checkArguments(Real volume, Real capillaryConstant, Real thetaDeg) {
  require(volume > 0 && capillaryConstant >= 0 && thetaDeg > 0 && thetaDeg < 180,
          "Young-Laplace droplet needs a positive volume, c >= 0 and theta in (0, 180) deg");
}

}  // namespace

SessileShape youngLaplaceSessile(Real volume, Real capillaryConstant, Real thetaDeg,
                                 Real sectionHeight, Real* sectionRadius) {
  checkArguments(volume, capillaryConstant, thetaDeg);
  require(sectionHeight >= 0, "Young-Laplace section height must be >= 0");
  const Real theta = thetaDeg * std::numbers::pi / 180;
  const Profile p = integrate(apexCurvature(volume, capillaryConstant, theta, kShapeStep),
                              capillaryConstant, theta, sectionHeight, kShapeStep);
  if (sectionRadius) *sectionRadius = p.sectionRadius;
  return p.shape;
}

std::vector<std::pair<Real, Real>> youngLaplaceOutline(Real volume, Real capillaryConstant,
                                                       Real thetaDeg, int samples) {
  checkArguments(volume, capillaryConstant, thetaDeg);
  require(samples >= 1, "Young-Laplace outline needs at least one sample");
  const Real theta = thetaDeg * std::numbers::pi / 180;
  const Real b = apexCurvature(volume, capillaryConstant, theta, kOutlineStep);
  // Arc length by the step count: a sample every (steps / samples) steps.
  std::vector<std::pair<Real, Real>> all;  // (depth below the apex, radius) per step end
  const Profile whole = integrate(b, capillaryConstant, theta, -1, kOutlineStep,
                                  [&](Real z, Real x) { all.emplace_back(z, x); });
  std::vector<std::pair<Real, Real>> out;
  out.emplace_back(whole.shape.height, 0.0);
  for (int k = 1; k <= samples; ++k) {
    const auto& [z, x] = all[std::min(all.size() - 1, all.size() * k / samples)];
    out.emplace_back(whole.shape.height - z, x);
  }
  out.back() = {0.0, whole.shape.contactRadius};
  return out;
}

Real youngLaplaceAngleOfFootprint(Real volume, Real capillaryConstant, Real sectionRadius,
                                  Real height) {
  require(sectionRadius >= 0 && height >= 0,
          "footprint angle needs a non-negative radius and height");
  auto section = [&](Real thetaDeg) {
    Real r = 0;
    youngLaplaceSessile(volume, capillaryConstant, thetaDeg, height, &r);
    return r;
  };
  Real lo = 90, hi = 179.5;  // section(lo) >= sectionRadius >= section(hi)
  if (sectionRadius >= section(lo)) return 90;
  if (sectionRadius <= section(hi)) return 180;
  for (int k = 0; k < 30; ++k) {
    const Real mid = 0.5 * (lo + hi);
    (section(mid) > sectionRadius ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Real youngLaplaceOutlineResidual(const std::vector<Vec3>& points, const Vec3& wallPoint,
                                 const Vec3& wallNormal, const Vec3& axisPoint, Real volume,
                                 Real capillaryConstant, Real thetaDeg) {
  require(!points.empty(), "Young-Laplace residual needs interface points");
  const Vec3 n = wallNormal.normalized();
  const Vec3 foot = axisPoint - (axisPoint - wallPoint).dot(n) * n;  // the axis meets the wall
  const auto outline = youngLaplaceOutline(volume, capillaryConstant, thetaDeg, 200);
  const std::size_t segments = outline.size() - 1;
  // Squared distance of (h, r) to segment k (outline[k] to outline[k + 1]).
  const auto segmentDistance2 = [&](std::size_t k, Real h, Real r) {
    const Real ah = outline[k].first, ar = outline[k].second;
    const Real eh = outline[k + 1].first - ah, er = outline[k + 1].second - ar;
    const Real len2 = eh * eh + er * er;
    const Real t =
        len2 > 0 ? std::clamp(((h - ah) * eh + (r - ar) * er) / len2, Real(0), Real(1)) : 0;
    const Real dh = h - ah - t * eh, dr = r - ar - t * er;
    return dh * dh + dr * dr;
  };
  // The height falls monotonically along the outline, so a segment is at least as far from a
  // point as its height range is: start at the segment level with the point and walk both ways
  // until that bound exceeds the best distance found (exact, and a few segments per point
  // instead of all 200).
  const auto heightGap2 = [&](std::size_t k, Real h) {
    const Real gap = std::max({Real(0), outline[k + 1].first - h, h - outline[k].first});
    return gap * gap;
  };
  Real sum = 0;
  for (const Vec3& x : points) {
    // The point in the meridian plane: (height above the wall, distance from the axis).
    const Real h = (x - foot).dot(n);
    const Real r = (x - foot - h * n).norm();
    const auto level = std::partition_point(
        outline.begin(), outline.begin() + static_cast<std::ptrdiff_t>(segments),
        [&](const std::pair<Real, Real>& sample) { return sample.first > h; });
    const std::size_t start = std::min(
        segments - 1,
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (level - outline.begin()) - 1)));
    Real best = segmentDistance2(start, h, r);
    for (std::size_t k = start + 1; k < segments && heightGap2(k, h) < best; ++k)
      best = std::min(best, segmentDistance2(k, h, r));
    for (std::size_t k = start; k-- > 0 && heightGap2(k, h) < best;)
      best = std::min(best, segmentDistance2(k, h, r));
    sum += best;
  }
  return std::sqrt(sum / static_cast<Real>(points.size()));
}

Real youngLaplaceAngleOfPoints(const std::vector<Vec3>& points, const Vec3& wallPoint,
                               const Vec3& wallNormal, const Vec3& axisPoint, Real volume,
                               Real capillaryConstant) {
  require(points.size() >= 4, "Young-Laplace fit needs at least 4 interface points");
  auto cost = [&](Real thetaDeg) {
    return youngLaplaceOutlineResidual(points, wallPoint, wallNormal, axisPoint, volume,
                                       capillaryConstant, thetaDeg);
  };
  // 2 deg samples over 90-178 deg (the outline fit serves non-wetting droplets), then 20
  // golden-section steps (the 4 deg bracket shrinks to 3e-4 deg).
  return scanGoldenMinimum(cost, ScanGoldenSearch{90, 178, 2, 90, 179, 20});
}

YoungLaplaceShapeFit youngLaplaceShapeOfPoints(const std::vector<Vec3>& points,
                                               const Vec3& wallPoint, const Vec3& wallNormal,
                                               const Vec3& axisPoint, Real volume,
                                               Real nominalCapillaryConstant) {
  require(nominalCapillaryConstant > 0,
          "Young-Laplace shape fit needs a nominal capillary constant > 0 (gravity onto the wall)");
  const auto fitAt = [&](Real ratio) {
    YoungLaplaceShapeFit fit;
    fit.nominalRatio = ratio;
    fit.capillaryConstant = nominalCapillaryConstant / ratio;
    fit.angle = youngLaplaceAngleOfPoints(points, wallPoint, wallNormal, axisPoint, volume,
                                          fit.capillaryConstant);
    fit.rmsResidual = youngLaplaceOutlineResidual(points, wallPoint, wallNormal, axisPoint, volume,
                                                  fit.capillaryConstant, fit.angle);
    return fit;
  };
  // The 0.1 bracket shrinks to 8e-4 in 10 golden-section steps: 0.1 % of sigma.
  const Real ratio = scanGoldenMinimum([&](Real r) { return fitAt(r).rmsResidual; },
                                       ScanGoldenSearch{0.5, 1.5, 0.05, 0.5, 1.5, 10});
  return fitAt(ratio);
}

}  // namespace sim
