// Coverage below the particle spacing (sim/measure/wall_oil_extended.h) on a static lattice whose
// phases are the axisymmetric Young-Laplace equilibrium in a sphere of R = 12 mm
// (young_laplace_sphere.h: clinical oil 970 in aqueous 1004 kg/m^3, sigma = 40 mN/m, 1 g, 5-20 %
// aqueous): the oil-covered share of the wall read from the particles against the exact share
// above the contact line. The same lattice read next to the wall (the colour at the wall point, as
// a particle reading does) is shown alongside for what the extension changes.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "sim/equilibrium/threshold_dynamics_xu2017.h"
#include "sim/measure/wall_oil_extended.h"
#include "sphere_wall_reading.h"
#include "young_laplace_sphere.h"

using namespace sim;

namespace {

constexpr double kR = 12e-3, kSigma = 0.04, kOil = 970.0, kAqueous = 1004.0, kG = 9.81;
constexpr double kSpacing = 1.2e-3;  // [m] the draft runs' trial spacing
constexpr double kDeg = std::numbers::pi / 180.0;

// The meniscus height at radius r (the meridian runs outward from the apex), or +inf beyond the
// contact radius (no interface there: above the contact line, so oil).
double meniscusHeight(const testref::SphereMeniscus& m, double r) {
  for (std::size_t k = 1; k < m.meridian.size(); ++k) {
    const auto [r0, z0] = m.meridian[k - 1];
    const auto [r1, z1] = m.meridian[k];
    if (r >= r0 && r <= r1) return z0 + (z1 - z0) * (r - r0) / (r1 - r0);
  }
  return std::numeric_limits<double>::infinity();
}

struct Lattice {
  std::vector<Vec3> x;
  std::vector<std::uint8_t> isOil;
};

// A cubic lattice at kSpacing inside the sphere, shifted by `shift` spacings along z; aqueous below
// the meniscus. Every lattice point inside the wall is kept, as the scenes place their fluid (an
// imported sphere's particles reach the mesh surface: 12.00 mm in a 12 mm sphere at 1.2 mm).
Lattice latticeWith(const testref::SphereMeniscus& m, double shift) {
  Lattice l;
  const int n = static_cast<int>(kR / kSpacing) + 1;
  for (int i = -n; i < n; ++i)
    for (int j = -n; j < n; ++j)
      for (int k = -n; k < n; ++k) {
        const Vec3 x = kSpacing * Vec3(i + 0.5, j + 0.5, k + 0.5 + shift);
        if (x.norm() > kR) continue;
        const double r = std::hypot(x.x(), x.y());
        const bool aqueous = r <= m.meridian.back().first && x.z() < meniscusHeight(m, r);
        l.x.push_back(x);
        l.isOil.push_back(aqueous ? 0 : 1);
      }
  return l;
}

// The particles read at the wall point itself: the Shepard colour of the lattice within `support`
// (cubic spline), oil when at least one half; what a reading of the particles next to the wall
// sees.
double readAtWall(const Lattice& l, const std::vector<Vec3>& wall, double support) {
  double covered = 0.0;
  for (const Vec3& w : wall) {
    double weighted = 0.0, weights = 0.0;
    for (std::size_t i = 0; i < l.x.size(); ++i) {
      const double q = 2.0 * (l.x[i] - w).norm() / support;  // cubic spline on [0, 2]
      if (q >= 2.0) continue;
      const double k = q < 1.0 ? 1.0 - 1.5 * q * q + 0.75 * q * q * q : 0.25 * std::pow(2.0 - q, 3);
      weighted += k * l.isOil[i];
      weights += k;
    }
    covered += weights > 0.0 && weighted >= 0.5 * weights ? 1.0 : 0.0;
  }
  return covered / static_cast<double>(wall.size());
}

}  // namespace

TEST_CASE("Coverage read below the spacing matches the Young-Laplace contact line",
          "[unit][interface]") {
  const double c = (kAqueous - kOil) * kG / kSigma;
  const testref::SphereWallReading reading(kR, kSpacing);
  // The reader's settings (docs/methods/interface.md, "Coverage below the spacing"): support 1.5
  // spacings; offset 1.25 spacings, the offset whose mean over alignments came closest to the
  // Young-Laplace line over these nine cases (1, 1.25, 1.5 and 2 spacings compared there; 2
  // spacings read 18 deg 1.8-2.8 points low once the particles reach the wall).
  ExtendedWallReadingOptions options;
  options.supportRadius = 1.5 * kSpacing;
  options.offset = 1.25 * kSpacing;
  for (const double fill : {0.8, 0.9, 0.95})
    for (const double theta : {18.0, 40.0, 90.0}) {
      const testref::SphereMeniscus m = testref::youngLaplaceSphere(kR, c, theta * kDeg, 1 - fill);
      options.contactAngle = theta * kDeg;
      // Three alignments of the lattice along gravity: where the interface falls between particle
      // layers moves the lattice's own contact line by up to 1.5 points at 1.2 mm (measured at
      // 90 deg, where the extension changes nothing), so each alignment is held to 3 points and
      // their mean, where that scatter averages out, to 1 point. Measured: mean -0.5 to +0.6,
      // single alignments -2.4 to +2.3 points.
      double sum = 0.0, atWallSum = 0.0;
      for (const double shift : {0.0, 0.25, 0.5}) {
        const Lattice lattice = latticeWith(m, shift);
        const double extended = reading.coverage(lattice.x, lattice.isOil, options);
        INFO("fill " << fill << ", theta " << theta << " deg, shift " << shift << ": exact "
                     << m.upperWetFraction << ", extended " << extended);
        CHECK(std::abs(extended - m.upperWetFraction) <= 0.03);
        sum += extended;
        if (theta == 18.0)
          atWallSum += readAtWall(lattice, reading.wallPoints(), options.supportRadius);
      }
      const double mean = sum / 3.0;
      INFO("fill " << fill << ", theta " << theta << " deg: exact " << m.upperWetFraction
                   << ", extended (mean of 3 alignments) " << mean);
      CHECK(std::abs(mean - m.upperWetFraction) <= 0.01);
      // At the retina's angle a reading next to the wall calls the aqueous wedge oil (measured
      // +4.9 / +5.2 / +3.8 points at fill 0.8 / 0.9 / 0.95): what the extension exists to remove.
      // Asserted above the extension's own single-alignment scatter (2.4 points) with margin.
      if (theta == 18.0) CHECK(atWallSum / 3.0 - m.upperWetFraction > 0.03);
    }
}
