#include "young_laplace_sphere.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace testref {
namespace {

constexpr double kPi = std::numbers::pi;

struct State {
  double r, z, psi, volume;  // volume: int z d(pi r^2)
};

struct Meridian {
  double b, c, z0;
  State derivative(const State& y) const {
    const double curvature = b + c * (y.z - z0);
    const double bend = y.r < 1e-12 ? 0.5 * curvature : curvature - std::sin(y.psi) / y.r;
    return {std::cos(y.psi), std::sin(y.psi), bend, 2.0 * kPi * y.r * y.z * std::cos(y.psi)};
  }
};

State add(const State& y, const State& k, double h) {
  return {y.r + h * k.r, y.z + h * k.z, y.psi + h * k.psi, y.volume + h * k.volume};
}

State rk4(const Meridian& m, const State& y, double h) {
  const State k1 = m.derivative(y), k2 = m.derivative(add(y, k1, h / 2)),
              k3 = m.derivative(add(y, k2, h / 2)), k4 = m.derivative(add(y, k3, h));
  return {y.r + h / 6 * (k1.r + 2 * k2.r + 2 * k3.r + k4.r),
          y.z + h / 6 * (k1.z + 2 * k2.z + 2 * k3.z + k4.z),
          y.psi + h / 6 * (k1.psi + 2 * k2.psi + 2 * k3.psi + k4.psi),
          y.volume + h / 6 * (k1.volume + 2 * k2.volume + 2 * k3.volume + k4.volume)};
}

struct Shot {
  std::vector<std::pair<double, double>> points;  // (r, z) every few steps, filled on request
  bool hit = false;
  double cosAngle = 0.0;     // cos(theta_lower) at the wall
  double lowerVolume = 0.0;  // [m^3]
  double contactHeight = 0.0;
};

// Integrates from the apex (0, z0) until the meridian meets the sphere (the crossing refined by
// bisection of the last step). A meridian that turns back to the axis or winds misses.
Shot shoot(double R, double c, double b, double z0, bool keepPoints = false) {
  const Meridian m{b, c, z0};
  const double ds = R / 1000.0;
  State y{0.0, z0, 0.0, 0.0};
  auto outside = [&](const State& s) { return s.r * s.r + s.z * s.z - R * R; };
  std::vector<std::pair<double, double>> points;
  for (int step = 0; step < 40000; ++step) {
    if (keepPoints && step % 8 == 0) points.emplace_back(y.r, y.z);
    const State next = rk4(m, y, ds);
    if (next.r < 0.0 || std::abs(next.psi) > 1.5 * kPi) return {};
    if (outside(next) >= 0.0) {
      double lo = 0.0, hi = ds;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (outside(rk4(m, y, mid)) < 0.0 ? lo : hi) = mid;
      }
      const State e = rk4(m, y, 0.5 * (lo + hi));
      Shot s;
      s.points = std::move(points);
      if (keepPoints) s.points.emplace_back(e.r, e.z);
      s.hit = true;
      s.cosAngle = (e.r * std::sin(e.psi) - e.z * std::cos(e.psi)) / R;
      s.contactHeight = e.z;
      const double H = R + e.z;  // the sphere's cap below z_c
      s.lowerVolume = kPi * H * H * (3 * R - H) / 3 + (e.volume - e.z * kPi * e.r * e.r);
      return s;
    }
    y = next;
  }
  return {};
}

// The apex curvature b at which the meridian from (0, z0) meets the wall at the angle. Shots hit
// the wall on an interval of b around 0 (a strongly curved meridian curls back to the axis);
// its ends are found by doubling and bisection, and the angle, monotone in b across it, by
// bisection. No root inside: no meniscus from this apex height.
Shot shootAngle(double R, double c, double cosAngle, double z0, double& b) {
  auto edge = [&](double sign) {
    double hit = 0.0, miss = sign / R;
    while (shoot(R, c, miss, z0).hit && std::abs(miss) < 1e4 / R) {
      hit = miss;
      miss *= 2.0;
    }
    for (int it = 0; it < 20; ++it) {
      const double mid = 0.5 * (hit + miss);
      (shoot(R, c, mid, z0).hit ? hit : miss) = mid;
    }
    return hit;
  };
  double lo = edge(-1.0), hi = edge(1.0);
  const Shot atLo = shoot(R, c, lo, z0), atHi = shoot(R, c, hi, z0);
  if (!atLo.hit || !atHi.hit) return {};
  double signLo = atLo.cosAngle - cosAngle;
  if (signLo * (atHi.cosAngle - cosAngle) > 0.0) {
    // Not monotone across the interval (a small puddle near the bottom): look for a sign change
    // between 64 shots inside it.
    const double from = lo, to = hi;
    bool found = false;
    for (int k = 1; k <= 64 && !found; ++k) {
      const double bk = from + (to - from) * k / 64.0;
      const Shot s = shoot(R, c, bk, z0);
      if (s.hit && (s.cosAngle - cosAngle) * signLo <= 0.0) {
        hi = bk;
        lo = from + (to - from) * (k - 1) / 64.0;
        signLo = shoot(R, c, lo, z0).cosAngle - cosAngle;
        found = true;
      }
    }
    if (!found) return {};
  }
  Shot mid;
  for (int it = 0; it < 45; ++it) {
    b = 0.5 * (lo + hi);
    mid = shoot(R, c, b, z0);
    if (!mid.hit) return {};
    ((mid.cosAngle - cosAngle) * signLo > 0.0 ? lo : hi) = b;
  }
  return mid;
}

}  // namespace

SphereMeniscus youngLaplaceSphere(double R, double c, double lowerAngle, double fraction) {
  const double target = fraction * 4.0 / 3.0 * kPi * R * R * R;
  const double cosAngle = std::cos(lowerAngle);
  // The lower phase's volume grows with the apex height z0. Not every apex height has a meniscus
  // at the angle, so a scan finds two neighbouring heights that have one and bracket the volume,
  // then bisection.
  auto solveAt = [&](double z0, double& b) { return shootAngle(R, c, cosAngle, z0, b); };
  // 40 heights first; a thin pool at a small angle (18 deg at 5 % of the volume) has a meniscus
  // only within a few tenths of a millimetre of the bottom, so a finer scan follows if needed.
  double lo = 0.0, hi = 0.0;
  bool bracketed = false;
  for (const int kScan : {40, 800}) {
    bool havePrevious = false;
    double zPrevious = 0.0, vPrevious = 0.0;
    for (int k = 0; k <= kScan && !bracketed; ++k) {
      const double z0 = -R * (1.0 - 1e-3) + 2.0 * R * (1.0 - 1e-3) * k / kScan;
      double b = 0.0;
      const Shot s = solveAt(z0, b);
      if (!s.hit) {
        havePrevious = false;
        continue;
      }
      if (havePrevious && (vPrevious - target) * (s.lowerVolume - target) <= 0.0) {
        lo = zPrevious;
        hi = z0;
        bracketed = true;
      }
      havePrevious = true;
      zPrevious = z0;
      vPrevious = s.lowerVolume;
    }
    if (bracketed) break;
  }
  if (!bracketed) throw std::runtime_error("Young-Laplace: no meniscus holds the volume");
  const bool rising = true;
  SphereMeniscus out;
  for (int it = 0; it < 30; ++it) {
    const double z0 = 0.5 * (lo + hi);
    double b = 0.0;
    const Shot s = solveAt(z0, b);
    if (!s.hit) throw std::runtime_error("Young-Laplace: no meniscus inside the bracket");
    ((s.lowerVolume < target) == rising ? lo : hi) = z0;
    out = {s.contactHeight, (R - s.contactHeight) / (2 * R), z0, b, {}};
  }
  out.meridian = shoot(R, c, out.apexCurvature, out.apexHeight, true).points;
  return out;
}

double zeroGravityWetFraction(double angle, double volumeFraction) {
  // Phase P above the contact height z_c of the unit sphere; the interface a spherical cap on the
  // rim circle (radius a, polar angle gamma of the rim) with tangent angle phi to the rim's plane
  // at the rim, so its height is delta = a tan(phi / 2) (downward bulge positive). P's rim angle
  // is then cos(alpha) = cos(phi + gamma): phi = alpha - gamma. P's volume: the sphere's cap
  // above z_c plus the segment pi delta (3 a^2 + delta^2) / 6.
  auto upperVolume = [&](double zc) {
    const double a = std::sqrt(1.0 - zc * zc), gamma = std::acos(zc);
    const double delta = a * std::tan(0.5 * (angle - gamma));
    const double H = 1.0 - zc;
    return kPi * H * H * (3.0 - H) / 3.0 + kPi * delta * (3 * a * a + delta * delta) / 6.0;
  };
  const double target = volumeFraction * 4.0 / 3.0 * kPi;
  double lo = -1.0 + 1e-12, hi = 1.0 - 1e-12;  // the volume falls as z_c rises
  for (int it = 0; it < 200; ++it) {
    const double zc = 0.5 * (lo + hi);
    (upperVolume(zc) > target ? lo : hi) = zc;
  }
  return (1.0 - 0.5 * (lo + hi)) / 2.0;
}

}  // namespace testref
