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
Profile integrate(Real b, Real c, Real theta, Real sectionHeight,
                  const std::function<void(Real depth, Real radius)>& onStep = {}) {
  // Step: a small fraction of the smallest length of the problem (apex radius, capillary length).
  const Real length = c > 0 ? std::min(1 / b, 1 / std::sqrt(c)) : 1 / b;
  const Real ds = length * 2e-3;
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

// The apex curvature b of the droplet of `volume` (arguments checked by the caller).
Real apexCurvature(Real volume, Real capillaryConstant, Real theta) {
  // The volume falls as the apex curvature b grows. Without gravity b is the cap's 1 / R; gravity
  // flattens the apex, so the root lies below that.
  const Real u = std::cos(theta);
  const Real capR = std::cbrt(3 * volume / (std::numbers::pi * (2 + u) * (1 - u) * (1 - u)));
  // A puddle's apex is flat to within exp(-radius / l_c): the bracket reaches far below 1 / R.
  Real lo = 1e-30 / capR, hi = 1.01 / capR;  // volume(lo) > volume > volume(hi)
  for (int k = 0; k < 200 && hi / lo > 1 + 1e-13; ++k) {
    const Real b = std::sqrt(lo * hi);
    (integrate(b, capillaryConstant, theta, -1).shape.volume > volume ? lo : hi) = b;
  }
  return std::sqrt(lo * hi);
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
  const Profile p = integrate(apexCurvature(volume, capillaryConstant, theta), capillaryConstant,
                              theta, sectionHeight);
  if (sectionRadius) *sectionRadius = p.sectionRadius;
  return p.shape;
}

std::vector<std::pair<Real, Real>> youngLaplaceOutline(Real volume, Real capillaryConstant,
                                                       Real thetaDeg, int samples) {
  checkArguments(volume, capillaryConstant, thetaDeg);
  require(samples >= 1, "Young-Laplace outline needs at least one sample");
  const Real theta = thetaDeg * std::numbers::pi / 180;
  const Real b = apexCurvature(volume, capillaryConstant, theta);
  // Arc length by the step count: a sample every (steps / samples) steps.
  std::vector<std::pair<Real, Real>> all;  // (depth below the apex, radius) per step end
  const Profile whole =
      integrate(b, capillaryConstant, theta, -1, [&](Real z, Real x) { all.emplace_back(z, x); });
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

Real youngLaplaceAngleOfPoints(const std::vector<Vec3>& points, const Vec3& wallPoint,
                               const Vec3& wallNormal, const Vec3& axisPoint, Real volume,
                               Real capillaryConstant) {
  require(points.size() >= 4, "Young-Laplace fit needs at least 4 interface points");
  const Vec3 n = wallNormal.normalized();
  const Vec3 foot = axisPoint - (axisPoint - wallPoint).dot(n) * n;  // the axis meets the wall
  // Each point in the meridian plane: (height above the wall, distance from the axis).
  std::vector<std::pair<Real, Real>> meridian;
  meridian.reserve(points.size());
  for (const Vec3& x : points) {
    const Real height = (x - foot).dot(n);
    meridian.emplace_back(height, (x - foot - height * n).norm());
  }
  auto cost = [&](Real thetaDeg) {
    const auto outline = youngLaplaceOutline(volume, capillaryConstant, thetaDeg, 200);
    Real sum = 0;
    for (const auto& [h, r] : meridian) {
      Real best = std::numeric_limits<Real>::infinity();
      for (std::size_t k = 1; k < outline.size(); ++k) {  // squared distance to each segment
        const Real ah = outline[k - 1].first, ar = outline[k - 1].second;
        const Real eh = outline[k].first - ah, er = outline[k].second - ar;
        const Real len2 = eh * eh + er * er;
        const Real t =
            len2 > 0 ? std::clamp(((h - ah) * eh + (r - ar) * er) / len2, Real(0), Real(1)) : 0;
        const Real dh = h - ah - t * eh, dr = r - ar - t * er;
        best = std::min(best, dh * dh + dr * dr);
      }
      sum += best;
    }
    return sum;
  };
  // 2 deg samples over 90-178 deg (the outline fit serves non-wetting droplets), then 20
  // golden-section steps (the 4 deg bracket shrinks to 3e-4 deg).
  return scanGoldenMinimum(cost, ScanGoldenSearch{90, 178, 2, 90, 179, 20});
}

}  // namespace sim
