// Floating elastic block (docs/methods/elasticity.md validation 3; Wang et al. 2023 Figure 8: an
// elastic body of half the fluid's density floats half submerged with INDSPH). Coarse version of
// tools/bench/solid_buoyancy_bench.cpp, whose 5 mm runs are in docs/methods/elasticity.md.
//
// The water level is the far-field VOLUME level: the number of water particles per far column
// times d (each particle's lattice cell is d^3; the layered floor's face is y = 0). In the bench
// this level and the level where the far field's hydrostatic pressure line reaches p = 0 agree to
// 0.01 d, and the pressure under the block equals rho g (that level - depth) to 0.1 Pa: it is the
// level the block's weight is balanced against. The visible surface (mean column top + d/2) lies
// ~0.3 d below it, because the settled, no longer lattice-ordered water packs n particles into
// less than n d of height at the kernel's rest number density; measured against that surface the
// block reads ~0.035 H too high (docs/methods/elasticity.md, "Buoyancy").
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "floating_block.h"

using namespace sim;

namespace {

struct Floating {
  Real volumeFraction = 0;   // [1] submerged fraction against the volume level, window mean
  Real visibleFraction = 0;  // [1] the same against mean column top + d/2
  Real sidewaysDrift = 0;    // [m] largest horizontal distance of the block centre from the start
  bool finite = true;
};

// The floating-block scene (layered walls, INDSPH, started at its Archimedes draft); fractions
// averaged over [duration / 2, duration] sampled every 0.01 s.
Floating floatBlock(const testing::FloatingBlockSpec& spec, Real duration) {
  const Real d = spec.d;  // [m]
  testing::FloatingBlock scene = testing::floatingBlock(spec);
  World& world = *scene.world;
  Pipeline& pipeline = *scene.pipeline;
  const int block = scene.block;

  const Real half = scene.halfWidth;  // [m]
  const Vec3 start = scene.footprintCentre;
  Floating r;
  int samples = 0;
  for (Real t = 0.01; t <= duration + 1e-9; t += 0.01) {
    while (world.time < t) pipeline.step(world);
    const auto& p = world.particles;
    Real minY = 1e30, maxY = -1e30;
    Vec3 centre = Vec3::Zero();
    int n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.material[i] == block) {
        minY = std::min(minY, p.x[i].y()), maxY = std::max(maxY, p.x[i].y());
        centre += p.x[i], ++n;
      }
    centre /= n;
    r.sidewaysDrift =
        std::max(r.sidewaysDrift, std::hypot(centre.x() - start.x(), centre.z() - start.z()));
    if (world.time <= duration / 2) continue;
    // Faces: mean of the lowest / highest particle layer -/+ d/2 (exact for the lattice block).
    Real bottom = 0, top = 0;
    int nBottom = 0, nTop = 0;
    // Far field: columns whose cell is at least 2 d from the block's side faces.
    std::map<std::pair<int, int>, std::pair<int, Real>> columns;  // count, top
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3& x = p.x[i];
      if (p.material[i] == block) {
        if (x.y() < minY + 0.5 * d) bottom += x.y(), ++nBottom;
        if (x.y() > maxY - 0.5 * d) top += x.y(), ++nTop;
        continue;
      }
      if (std::max(std::abs(x.x() - centre.x()), std::abs(x.z() - centre.z())) < half + 2 * d)
        continue;
      auto& c = columns[{static_cast<int>(std::floor(x.x() / d)),
                         static_cast<int>(std::floor(x.z() / d))}];
      c.first += 1;
      c.second = c.first == 1 ? x.y() : std::max(c.second, x.y());
    }
    bottom = bottom / nBottom - 0.5 * d, top = top / nTop + 0.5 * d;
    Real count = 0, tops = 0;
    for (const auto& [key, c] : columns) count += c.first, tops += c.second;
    const Real volumeLevel = d * count / columns.size();        // [m]
    const Real visibleLevel = tops / columns.size() + 0.5 * d;  // [m]
    r.volumeFraction += (volumeLevel - bottom) / (top - bottom);
    r.visibleFraction += (visibleLevel - bottom) / (top - bottom);
    ++samples;
  }
  r.volumeFraction /= samples, r.visibleFraction /= samples;
  r.finite = allFinite(world);
  return r;
}

}  // namespace

// d = 1 cm, tank 16 d x 10 d deep, block 6 x 6 d x 6 d high (H), INDSPH, layered walls, 0.6 s
// (~10 s at 1 thread per case). The claim is "within 3 %" of the block's volume, i.e. of H: 0.18 d,
// and that is the tolerance asserted. Why a coarse run can be held to it: the faces are placed at
// the block's outer particle layers -/+ d/2, which is exact for the lattice the block is sampled
// as and stays so (E = 100 kPa under rho g H ~ 300 Pa: 0.3 % strain, 0.02 d); the volume level
// is a count (no position noise) averaged over >= 60 columns and 30 samples. The O(d) choice that
// remains is which water level: the visible one is 0.3 d = 5 % of H lower, which is why it is
// reported (CAPTURE) but not asserted. Measured: 0.504 (visible 0.470) here; 0.512-0.515 in the
// bench at d = 5 mm, tanks 20 d and 32 d (docs/methods/elasticity.md). The quarter-density block is
// not asserted here: in this coarse scene it reads 0.291 (+4.1 % of H; the 5 mm bench: 0.26-0.27),
// so the claim for s.g. 0.25 is checked by the bench only (docs/methods/elasticity.md).
TEST_CASE("an elastic block of half the water's density floats half submerged",
          "[validation][elasticity]") {
  testing::FloatingBlockSpec spec;
  spec.d = 0.01;  // [m]
  spec.specificGravity = 0.5;
  spec.tankWidth = 16, spec.waterDepth = 10, spec.blockWidth = 6, spec.blockLayers = 6;  // [d]
  const Floating r = floatBlock(spec, 0.6);
  const Real d = spec.d;
  CAPTURE(r.volumeFraction, r.visibleFraction, r.sidewaysDrift / d);
  REQUIRE(r.finite);
  CHECK(r.volumeFraction == Approx(0.5).margin(0.03));
  CHECK(r.sidewaysDrift < 0.5 * d);  // symmetric scene: only the solver's noise moves it
}
