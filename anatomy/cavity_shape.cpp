#include "anatomy/cavity_shape.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "anatomy/anatomy_error.h"

namespace anatomy {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMm = 1e-3;  // [m]
// Smallest concave radius of curvature the staphyloma rim may have: an outward offset of the wall
// by up to this much (the sclera, <= 1 mm thick; Vurgese 2012) must not fold.
constexpr double kMinimumConcaveRadius = 1.5e-3;  // [m]

// 5-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr std::array<double, 5> kGaussNodes = {0.0, -0.5384693101056831, 0.5384693101056831,
                                               -0.9061798459386640, 0.9061798459386640};
constexpr std::array<double, 5> kGaussWeights = {0.5688888888888889, 0.4786286704993665,
                                                 0.4786286704993665, 0.2369268850561891,
                                                 0.2369268850561891};

}  // namespace

CavityShape::CavityShape(const CavityGeometry& g) : geometry_(g) {
  const double a = g.semiAxisHorizontal, b = g.semiAxisVertical, c = g.semiAxisAxial;
  require(a > 0.0 && b > 0.0 && c > 0.0 && std::isfinite(a + b + c),
          "cavity: ellipsoid semi-axes must be positive and finite (got " + mmText(a) + ", " +
              mmText(b) + ", " + mmText(c) + ")");
  require(g.capSag >= 0.0, "cavity: cap sag must be >= 0 (got " + mmText(g.capSag) + ")");
  rimZ_ = c + g.apexDepth - g.capPlaneDepth;
  require(rimZ_ > -0.5 * c && rimZ_ < 0.95 * c,
          "cavity: the cap plane (" + mmText(g.capPlaneDepth) +
              " behind the corneal apex) must cut "
              "the ellipsoid between its anterior tip (" +
              mmText(g.apexDepth) +
              ") and a quarter of "
              "its axial length behind the centre; move the lens/IOL plane");
  rimTheta_ = std::acos(-rimZ_ / c);
  require(g.capSag < 0.5 * (rimZ_ + c),
          "cavity: cap sag " + mmText(g.capSag) + " reaches too far toward the posterior pole");

  setStaphyloma();
  computeVolumeAndCentroid();
}

// Sets the staphyloma's radius and checks it stays on the posterior wall and does not fold.
void CavityShape::setStaphyloma() {
  const CavityGeometry& g = geometry_;
  const double a = g.semiAxisHorizontal, b = g.semiAxisVertical;
  require(g.staphylomaDepth >= 0.0 && g.staphylomaWidth >= 0.0,
          "cavity: staphyloma depth and width must be >= 0");
  if (g.staphylomaDepth > 0.0) {
    bumpRadius_ = 0.5 * g.staphylomaWidth;
    require(bumpRadius_ <= 0.7 * std::min(a, b),
            "cavity: staphyloma width " + mmText(g.staphylomaWidth) + " is too wide; at most " +
                mmText(1.4 * std::min(a, b)) +
                " (70 % of the eye's transverse diameter) so that it "
                "stays on the posterior wall");
    require(bumpRadius_ >= 1.0 * kMm, "cavity: staphyloma width " + mmText(g.staphylomaWidth) +
                                          " is too narrow (at least 2 mm)");
    // Concave radius at the staphyloma's edge: 1/(depth g''(R)) = 2 R^2 / (pi^2 depth).
    const double concaveRadius = 2.0 * bumpRadius_ * bumpRadius_ / (kPi * kPi * g.staphylomaDepth);
    require(concaveRadius >= kMinimumConcaveRadius,
            "cavity: staphyloma depth " + mmText(g.staphylomaDepth) + " over width " +
                mmText(g.staphylomaWidth) + " folds its edge (concave radius " +
                mmText(concaveRadius) +
                " < 1.5 mm, the sclera could not be offset); use depth <= " +
                mmText(2.0 * bumpRadius_ * bumpRadius_ / (kPi * kPi * kMinimumConcaveRadius)) +
                " or a wider staphyloma");
  }
}

void CavityShape::computeVolumeAndCentroid() {
  const CavityGeometry& g = geometry_;
  const double a = g.semiAxisHorizontal, b = g.semiAxisVertical, c = g.semiAxisAxial;
  const double rimA = a * std::sin(rimTheta_), rimB = b * std::sin(rimTheta_);
  // Volume and centroid (local z) from the closed forms in the header; the staphyloma's moment
  // has no closed form and is integrated numerically (midpoint rule, smooth integrand).
  const double h = rimZ_;
  const double volumeEllipsoid = kPi * a * b * ((h + c) - (h * h * h + c * c * c) / (3 * c * c));
  const double momentEllipsoid =
      kPi * a * b * ((h * h - c * c) / 2.0 - (h * h * h * h - c * c * c * c) / (4 * c * c));
  const double sag = g.capSag;
  const double volumeDent = kPi * rimA * rimB * sag / 2.0;
  const double momentDent = kPi * rimA * rimB * (h * sag / 2.0 - sag * sag / 6.0);
  double volumeBump = 0.0, momentBump = 0.0;
  if (g.staphylomaDepth > 0.0) {
    const double R = bumpRadius_;
    volumeBump = kPi * g.staphylomaDepth * R * R * (0.5 - 2.0 / (kPi * kPi));
    const int nRho = 800, nPsi = 360;
    for (int i = 0; i < nRho; ++i) {
      const double rho = (i + 0.5) * R / nRho;
      const double bumpHeight = bump(rho);
      for (int k = 0; k < nPsi; ++k) {
        const double psi = (k + 0.5) * 2.0 * kPi / nPsi;
        const double w =
            1.0 - rho * rho * (std::pow(std::cos(psi) / a, 2) + std::pow(std::sin(psi) / b, 2));
        const double zEllipsoid = -c * std::sqrt(w);
        // moment of the slab between zEllipsoid - bump and zEllipsoid
        momentBump += (zEllipsoid * bumpHeight - 0.5 * bumpHeight * bumpHeight) * rho * (R / nRho) *
                      (2.0 * kPi / nPsi);
      }
    }
  }
  volume_ = volumeEllipsoid - volumeDent + volumeBump;
  centroidZ_ = (momentEllipsoid - momentDent + momentBump) / volume_;
}

double CavityShape::bump(double rho) const {
  if (geometry_.staphylomaDepth <= 0.0 || rho >= bumpRadius_) return 0.0;
  return geometry_.staphylomaDepth * 0.5 * (1.0 + std::cos(kPi * rho / bumpRadius_));
}

double CavityShape::bumpSlopeOverRho(double rho) const {
  if (geometry_.staphylomaDepth <= 0.0 || rho >= bumpRadius_) return 0.0;
  const double k = kPi / bumpRadius_;
  if (rho < 1e-9 * bumpRadius_) return -geometry_.staphylomaDepth * 0.5 * k * k;  // limit rho->0
  return -geometry_.staphylomaDepth * 0.5 * k * std::sin(k * rho) / rho;
}

Vec3 CavityShape::localWall(double theta, double meridian) const {
  const double s = std::sin(theta);
  const double x = geometry_.semiAxisHorizontal * s * std::cos(meridian);
  const double y = geometry_.semiAxisVertical * s * std::sin(meridian);
  return {x, y, -geometry_.semiAxisAxial * std::cos(theta) - bump(std::hypot(x, y))};
}

Vec3 CavityShape::wallPoint(const WallCoordinate& w) const {
  Vec3 p = localWall(w.theta, w.meridian);
  p.z() -= centroidZ_;
  return p;
}

Vec3 CavityShape::ellipsoidNormal(const WallCoordinate& w) const {
  const double a = geometry_.semiAxisHorizontal, b = geometry_.semiAxisVertical,
               c = geometry_.semiAxisAxial;
  // Gradient of x^2/a^2 + y^2/b^2 + z^2/c^2 at the point, scaled by 1/sin(theta); at the pole
  // the normal is -z.
  const double s = std::sin(w.theta);
  if (s < 1e-12) return {0.0, 0.0, -1.0};
  return Vec3(std::cos(w.meridian) / a, std::sin(w.meridian) / b, -std::cos(w.theta) / (c * s))
      .normalized();
}

Vec3 CavityShape::wallNormal(const WallCoordinate& w) const {
  const Vec3 p = localWall(w.theta, w.meridian);
  const double rho = std::hypot(p.x(), p.y());
  if (rho >= bumpRadius_ || geometry_.staphylomaDepth <= 0.0) return ellipsoidNormal(w);
  // Inside the staphyloma the wall is the graph z = zEllipsoid(x, y) - bump(rho); outward normal
  // (dz/dx, dz/dy, -1) with dzEllipsoid/dx = c x / (a^2 cos theta).
  const double a = geometry_.semiAxisHorizontal, b = geometry_.semiAxisVertical,
               c = geometry_.semiAxisAxial;
  const double cosTheta = std::cos(w.theta);
  const double slope = bumpSlopeOverRho(rho);
  const Vec3 n(c * p.x() / (a * a * cosTheta) - slope * p.x(),
               c * p.y() / (b * b * cosTheta) - slope * p.y(), -1.0);
  return n.normalized();
}

Vec3 CavityShape::capPoint(double u, double meridian) const {
  const double s = std::sin(rimTheta_);
  return {geometry_.semiAxisHorizontal * s * u * std::cos(meridian),
          geometry_.semiAxisVertical * s * u * std::sin(meridian),
          rimZ_ - geometry_.capSag * (1.0 - u * u) - centroidZ_};
}

Vec3 CavityShape::capNormal(double u, double meridian) const {
  const double s = std::sin(rimTheta_);
  const double rimA = geometry_.semiAxisHorizontal * s, rimB = geometry_.semiAxisVertical * s;
  // Gradient of z - zRim + sag (1 - x^2/A^2 - y^2/B^2).
  const Vec3 n(-2.0 * geometry_.capSag * u * std::cos(meridian) / rimA,
               -2.0 * geometry_.capSag * u * std::sin(meridian) / rimB, 1.0);
  return n.normalized();
}

double CavityShape::meridianOfAzimuth(double azimuth) const {
  // tan(azimuth) = (b / a) tan(meridian)  =>  meridian = atan2(a sin(azimuth), b cos(azimuth)).
  return std::atan2(geometry_.semiAxisHorizontal * std::sin(azimuth),
                    geometry_.semiAxisVertical * std::cos(azimuth));
}

double CavityShape::meridianSpeed(double theta, double meridian) const {
  const double a = geometry_.semiAxisHorizontal, b = geometry_.semiAxisVertical,
               c = geometry_.semiAxisAxial;
  const double radiusOfMeridian = std::hypot(a * std::cos(meridian), b * std::sin(meridian));
  const double rho = radiusOfMeridian * std::sin(theta);
  const double dRho = radiusOfMeridian * std::cos(theta);
  // dz/dtheta = c sin(theta) - bump'(rho) drho/dtheta, bump' = rho * bumpSlopeOverRho.
  const double dz = c * std::sin(theta) - rho * bumpSlopeOverRho(rho) * dRho;
  return std::hypot(dRho, dz);
}

double CavityShape::arcLength(double theta0, double theta1, double meridian) const {
  if (theta1 < theta0) return -arcLength(theta1, theta0, meridian);
  // Composite 5-point Gauss-Legendre on panels of <= 0.01 rad (~0.1 mm of wall): the integrand
  // is smooth except for a jump in its derivative at the staphyloma edge, so the error stays far
  // below a micrometre.
  const int panels = std::max(1, static_cast<int>(std::ceil((theta1 - theta0) / 1e-2)));
  const double width = (theta1 - theta0) / panels;
  double sum = 0.0;
  for (int k = 0; k < panels; ++k) {
    const double mid = theta0 + (k + 0.5) * width;
    for (size_t q = 0; q < kGaussNodes.size(); ++q)
      sum += kGaussWeights[q] * meridianSpeed(mid + 0.5 * width * kGaussNodes[q], meridian);
  }
  return 0.5 * width * sum;
}

WallCoordinate CavityShape::closestWallCoordinate(const Vec3& p) const {
  Vec3 local = p;
  local.z() += centroidZ_;
  const double azimuth =
      std::hypot(local.x(), local.y()) > 0.0 ? std::atan2(local.y(), local.x()) : 0.0;
  const double meridian = meridianOfAzimuth(azimuth);
  // localWall() with the meridian's trigonometry hoisted out: this runs ~90 times per query.
  const double ax = geometry_.semiAxisHorizontal * std::cos(meridian);
  const double by = geometry_.semiAxisVertical * std::sin(meridian);
  const double radiusOfMeridian = std::hypot(ax, by);
  const double c = geometry_.semiAxisAxial;
  auto distance2 = [&](double theta) {
    const double s = std::sin(theta);
    const double dx = ax * s - local.x(), dy = by * s - local.y();
    const double dz = -c * std::cos(theta) - bump(radiusOfMeridian * s) - local.z();
    return dx * dx + dy * dy + dz * dz;
  };
  // Coarse scan (samples ~0.6 mm of wall apart), then golden-section search in the bracket
  // around the best sample down to ~1e-9 rad (40 steps of 0.618 from 0.1 rad).
  const int samples = 48;
  int best = 0;
  double bestValue = std::numeric_limits<double>::max();
  for (int k = 0; k <= samples; ++k) {
    const double value = distance2(rimTheta_ * k / samples);
    if (value < bestValue) bestValue = value, best = k;
  }
  double lo = rimTheta_ * std::max(0, best - 1) / samples;
  double hi = rimTheta_ * std::min(samples, best + 1) / samples;
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = distance2(x1), f2 = distance2(x2);
  for (int it = 0; it < 40; ++it) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - ratio * (hi - lo), f1 = distance2(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + ratio * (hi - lo), f2 = distance2(x2);
    }
  }
  return {0.5 * (lo + hi), meridian};
}

CavityProjection CavityShape::project(const Vec3& p, const Vec3* normal) const {
  CavityProjection result;
  result.wall = closestWallCoordinate(p);
  result.wallDistance = (wallPoint(result.wall) - p).norm();
  const double s = std::sin(rimTheta_);
  const double rimA = geometry_.semiAxisHorizontal * s, rimB = geometry_.semiAxisVertical * s;
  const double u2 = std::pow(p.x() / rimA, 2) + std::pow(p.y() / rimB, 2);
  // Beyond the rim ellipse the nearest cap point is on the rim, which the wall also contains.
  if (u2 > 1.0) return result;
  // The vertical distance to the cap graph bounds the true distance from above.
  const double capDistance = std::abs(p.z() + centroidZ_ - (rimZ_ - geometry_.capSag * (1.0 - u2)));
  // Within 1 um of both parts (the rim) the normal decides; without one the wall wins, so rim
  // vertices get the wall's sclera thickness and clinical position.
  constexpr double kTie = 1e-6;  // [m]
  if (std::abs(capDistance - result.wallDistance) < kTie) {
    if (normal != nullptr) {
      const double meridian = std::atan2(p.y() / rimB, p.x() / rimA);
      const double capMatch = normal->dot(capNormal(std::sqrt(u2), meridian));
      const double wallMatch = normal->dot(wallNormal(result.wall));
      result.part = capMatch > wallMatch ? CavityPart::kCap : CavityPart::kWall;
    }
  } else if (capDistance < result.wallDistance) {
    result.part = CavityPart::kCap;
  }
  return result;
}

Vec3 CavityShape::cornealApex() const {
  return {0.0, 0.0, geometry_.semiAxisAxial + geometry_.apexDepth - centroidZ_};
}

double CavityShape::axialLength() const { return cornealApex().z() - posteriorPole().z(); }

double CavityShape::axialDepth() const { return capPoint(0.0, 0.0).z() - posteriorPole().z(); }

double CavityShape::minimumCurvatureRadius() const {
  const double a = geometry_.semiAxisHorizontal, b = geometry_.semiAxisVertical,
               c = geometry_.semiAxisAxial;
  const double lo = std::min({a, b, c}), hi = std::max({a, b, c});
  double radius = lo * lo / hi;  // smallest radius of curvature of an ellipsoid
  if (geometry_.capSag > 0.0) {
    const double s = std::sin(rimTheta_);
    const double rimMin = std::min(a, b) * s;
    radius = std::min(radius, rimMin * rimMin / (2.0 * geometry_.capSag));  // 1 / z''
  }
  if (geometry_.staphylomaDepth > 0.0) {
    // |bump''| <= depth pi^2 / (2 R^2), added to the ellipsoid's own curvature.
    const double bumpCurvature =
        geometry_.staphylomaDepth * kPi * kPi / (2.0 * bumpRadius_ * bumpRadius_);
    radius = std::min(radius, 1.0 / (bumpCurvature + 1.0 / radius));
  }
  return radius;
}

meshing::TriangleMesh CavityShape::triangulate(int segments) const {
  require(segments >= 8 && segments <= 4096,
          "cavity mesh resolution " + std::to_string(segments) +
              " is out of range: use 8..4096 segments around the axis");
  const int n = segments;
  int rings = std::max(4, static_cast<int>(std::ceil(n * rimTheta_ / (2.0 * kPi))));
  if (geometry_.staphylomaDepth > 0.0) {
    const double bumpTheta = std::asin(std::min(
        1.0, bumpRadius_ / std::max(geometry_.semiAxisHorizontal, geometry_.semiAxisVertical)));
    rings = std::max(rings, static_cast<int>(std::ceil(6.0 * rimTheta_ / bumpTheta)));
  }
  const int capRings = std::max(2, static_cast<int>(std::ceil(n / (2.0 * kPi))));

  meshing::TriangleMesh mesh;
  mesh.vertices.reserve(static_cast<size_t>(2 + n * (rings + capRings - 1)));
  const auto meridianOf = [n](int j) { return 2.0 * kPi * j / n; };
  // Wall: pole, then rings 1..rings (the last is the rim).
  mesh.vertices.push_back(wallPoint({0.0, 0.0}));
  for (int i = 1; i <= rings; ++i)
    for (int j = 0; j < n; ++j)
      mesh.vertices.push_back(wallPoint({rimTheta_ * i / rings, meridianOf(j)}));
  const auto wallIndex = [n](int ring, int j) { return 1 + (ring - 1) * n + (j % n); };
  // Cap: rings capRings-1 .. 1 inward (u = m / capRings), then the centre.
  const int capBase = static_cast<int>(mesh.vertices.size());
  for (int m = capRings - 1; m >= 1; --m)
    for (int j = 0; j < n; ++j)
      mesh.vertices.push_back(capPoint(static_cast<double>(m) / capRings, meridianOf(j)));
  const int centre = static_cast<int>(mesh.vertices.size());
  mesh.vertices.push_back(capPoint(0.0, 0.0));
  const auto capIndex = [&](int m, int j) {  // m = capRings is the rim, shared with the wall
    if (m == capRings) return wallIndex(rings, j);
    return capBase + (capRings - 1 - m) * n + (j % n);
  };

  // Orientation: outward = dP/dmeridian x dP/dtheta on the wall, dP/du x dP/dmeridian on the cap.
  for (int j = 0; j < n; ++j) mesh.faces.push_back({0, wallIndex(1, j + 1), wallIndex(1, j)});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < n; ++j) {
      mesh.faces.push_back({wallIndex(i, j), wallIndex(i, j + 1), wallIndex(i + 1, j + 1)});
      mesh.faces.push_back({wallIndex(i, j), wallIndex(i + 1, j + 1), wallIndex(i + 1, j)});
    }
  for (int j = 0; j < n; ++j) mesh.faces.push_back({centre, capIndex(1, j), capIndex(1, j + 1)});
  for (int m = 1; m < capRings; ++m)
    for (int j = 0; j < n; ++j) {
      mesh.faces.push_back({capIndex(m, j), capIndex(m + 1, j), capIndex(m + 1, j + 1)});
      mesh.faces.push_back({capIndex(m, j), capIndex(m + 1, j + 1), capIndex(m, j + 1)});
    }
  return mesh;
}

}  // namespace anatomy
