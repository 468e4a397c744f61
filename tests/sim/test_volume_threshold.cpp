// The threshold step at fixed volume (sim/equilibrium/volume_threshold.h): the fractional
// threshold against the closed form of a planar interface, and its invariants (the volume it holds,
// the order of psi it keeps) on random fields.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "sim/equilibrium/volume_threshold.h"

using namespace sim::equilibrium;

TEST_CASE("Fractional threshold of a planar psi gives each voxel its share of the plane",
          "[unit][equilibrium]") {
  // A row of ten whole voxels across a planar interface: psi grows by `width` per voxel, so the
  // oil of volume 3.3 voxels fills three voxels and 0.3 of the fourth (u_i = clamp(3.3 - i, 0, 1),
  // exact: the volume is linear in the level there). Rounding only: 1e-12.
  const double width = 7.0;
  std::vector<double> psi(10), f(10, 1.0), u(10);
  std::vector<std::size_t> fluid(10);
  for (std::size_t i = 0; i < 10; ++i) {
    psi[i] = width * (static_cast<double>(i) + 0.5) - 3.0;
    fluid[i] = i;
  }
  double level = std::numeric_limits<double>::quiet_NaN();
  selectFractional(psi, fluid, f, 3.3, width, level, u);
  for (std::size_t i = 0; i < 10; ++i)
    CHECK(u[i] == Approx(std::clamp(3.3 - static_cast<double>(i), 0.0, 1.0)).margin(1e-12));
}

TEST_CASE("Fractional threshold holds the volume and the order of psi", "[unit][equilibrium]") {
  // Random psi and fluid fractions, started cold (NaN) and from a level far off: the oil's volume
  // sum u f meets the target to 1e-9 of it (the solver's volume is exact), every u lies in [0, 1],
  // and a voxel with lower psi never holds less oil.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::size_t n = 5000;
  std::vector<double> psi(n), f(n), u(n);
  std::vector<std::size_t> fluid(n);
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    psi[i] = 100.0 * unit(random);
    f[i] = 0.05 + 0.95 * unit(random);
    fluid[i] = i;
    total += f[i];
  }
  for (const double start : {std::numeric_limits<double>::quiet_NaN(), -1e6, 50.0})
    for (const double share : {0.01, 0.3, 0.9}) {
      double level = start;
      selectFractional(psi, fluid, f, share * total, 2.0, level, u);
      double volume = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        volume += u[i] * f[i];
        REQUIRE(u[i] >= 0.0);
        REQUIRE(u[i] <= 1.0);
      }
      CHECK(volume == Approx(share * total).epsilon(1e-9));
      for (std::size_t i = 1; i < n; ++i)
        if (psi[i] < psi[i - 1]) REQUIRE(u[i] >= u[i - 1]);
    }
}
