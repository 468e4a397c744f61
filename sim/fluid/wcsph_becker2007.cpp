#include "sim/fluid/wcsph_becker2007.h"

#include <algorithm>
#include <cmath>

#include "sim/core/reduction.h"
#include "sim/fluid/density.h"
#include "sim/fluid/density_compression.h"
#include "sim/fluid/tait_equation.h"
#include "sim/world/pair_loop.h"

namespace sim {

WcsphBecker2007::WcsphBecker2007(const WcsphParameters& parameters) : params_(parameters) {
  require(params_.speedOfSound > 0,
          "WCSPH needs a speed of sound > 0 m/s (about 10x the flow speed)");
  require(params_.artificialViscosity >= 0, "WCSPH artificial viscosity must be >= 0");
  require(params_.courantNumber > 0 && params_.courantNumber <= 1,
          "WCSPH Courant number in (0, 1]");
}

void WcsphBecker2007::attach(World& world) {
  pressure_ = &world.particles.fields.addOrGet<Real>({"pressure", "Pa", false, true});
}

Real WcsphBecker2007::maxTimeStep(const World& world) const {
  return params_.courantNumber * world.particleSpacing() / params_.speedOfSound;
}

void WcsphBecker2007::beginStep(World& world, const StepContext&) {
  auto& p = world.particles;
  computeDensities(world, p.density);
  const Real c2 = params_.speedOfSound * params_.speedOfSound;
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real rho0 = world.restDensityOf(i);
    (*pressure_)[i] = taitPressure(p.density[i], rho0, c2);
  }
}

void WcsphBecker2007::correctVelocities(World& world, const StepContext& context) {
  auto& p = world.particles;
  const auto& walls = world.walls;
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Real dt = context.dt;
  const Real h = world.kernel.supportRadius();
  const Real alphaC = params_.artificialViscosity * params_.speedOfSound;
  const auto& pressure = *pressure_;
  const Index n = static_cast<Index>(p.size());
  pressureAcceleration_.resize(n);
  // x is not yet advanced, so pressure forces use this step's positions; v is the prediction v*.
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real pi = pressure[i] / (p.density[i] * p.density[i]);
    Vec3 a = Vec3::Zero();
    fluid.forEach(i, [&](Index j, const Vec3& gradW) {
      const Vec3 xij = p.x[i] - p.x[j];
      Real term = pi + pressure[j] / (p.density[j] * p.density[j]);
      const Real vx = (p.v[i] - p.v[j]).dot(xij);
      if (vx < 0 && alphaC > 0) {  // approaching pair: Monaghan artificial viscosity
        const Real mu = 0.5 * h * vx / (xij.squaredNorm() + 0.01 * h * h);
        term += -alphaC * mu / (0.5 * (p.density[i] + p.density[j]));
      }
      a -= p.mass[j] * term * gradW;
    });
    Vec3 g = Vec3::Zero();
    wall.forEach(i, [&](Index b, const Vec3& gradW) { g += walls.volume[b] * gradW; });
    a -= world.restDensityOf(i) * pi * g;
    pressureAcceleration_[i] = a;
  }
  // Applied after the loop: the viscosity term above reads neighbours' velocities.
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) p.v[i] += dt * pressureAcceleration_[i];
  recordDensityCompression(world, reducer_, stats_);
}

}  // namespace sim
