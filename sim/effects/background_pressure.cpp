#include "sim/effects/background_pressure.h"

#include <cmath>

#include "sim/effects/interfacial_tension_hu_adams2006.h"
#include "sim/fluid/indsph_wang2023.h"
#include "sim/world/pair_loop.h"

namespace sim {

BackgroundPressure::BackgroundPressure(Real pressure, Real referenceDensity)
    : pressure_(pressure), referenceDensity_(referenceDensity) {
  require(pressure > 0 && std::isfinite(pressure),
          "background pressure must be a positive number of Pa");
  require(referenceDensity > 0, "background pressure needs a positive reference density");
}

Real BackgroundPressure::maxTimeStep(const World& world) const {
  return kBackgroundCourant * world.supportRadius() / std::sqrt(pressure_ / referenceDensity_);
}

void BackgroundPressure::attach(World& world) {
  shift_ = &world.particles.fields.addOrGet<Vec3>({field::kTransportShift, "m/s", false, false});
}

void BackgroundPressure::apply(World& world, const StepContext& context) {
  auto& p = world.particles;
  auto& shift = *shift_;
  const Real dt = context.dt;
  const auto& walls = world.walls;
  const NeighborList& nw = world.wallNeighbors();
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Index n = static_cast<Index>(p.size());
  // The first tension pair's colour gradient, this step's (interfacial_tension runs before).
  const std::vector<Vec3>* colour =
      p.fields.has(field::kColourGradient) ? &p.fields.get<Vec3>(field::kColourGradient) : nullptr;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    shift[i].setZero();
    if (!world.materials.isFluid(p.material[i])) continue;
    const Real vi = p.mass[i] / p.density[i];
    const Real vi2 = vi * vi;
    Vec3 bracket = Vec3::Zero();
    fluid.forEach(i, [&](Index j, const Vec3& gradW) {
      const Real vj = p.mass[j] / p.density[j];
      bracket += (vi2 + vj * vj) * gradW;
    });
    Vec3 wallSum = Vec3::Zero();
    wall.forEach(i, [&](Index b, const Vec3& gradW) { wallSum += walls.volume[b] * gradW; });
    bracket += (2.0 * vi2 / world.restVolumeOf(i)) * wallSum;
    // rho_ref V_i instead of m_i: the shift is a displacement that depends only on the particle
    // arrangement, the same in every phase (see the header: with m_i a heavy droplet was shifted
    // less than the liquid around it and settled at another contact angle).
    shift[i] = (-dt * pressure_ / (referenceDensity_ * vi)) * bracket;
    // Contact-line particles (a wall and the other liquid in reach) are not shifted: there the
    // shift moves the contact line itself. Measured on the cavity's 120 deg lens (closed form
    // 0.225 of the wall): 0.208 with them shifted, 0.228-0.234 without (docs/methods/interface.md,
    // validation 3).
    if (colour != nullptr && nw.count(i) > 0 && (*colour)[i].squaredNorm() > 0) shift[i].setZero();
  }
}

Real backgroundPressureFor(const World& world, const InterfacialTension& tension) {
  return kBackgroundPressurePerTension * tension.sigma / world.particleSpacing();
}

std::size_t countFreeSurfaceParticles(const World& world, Real fraction) {
  std::vector<Real> delta;
  computeNumberDensities(world, delta);
  const NeighborList& nw = world.wallNeighbors();
  std::size_t count = 0;
  for (Index i = 0; i < world.particles.size(); ++i)
    if (world.materials.isFluid(world.particles.material[i]) && nw.begin(i) == nw.end(i) &&
        delta[i] * world.restVolumeOf(i) < fraction)
      ++count;
  return count;
}

}  // namespace sim
