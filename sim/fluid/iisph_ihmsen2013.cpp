#include "sim/fluid/iisph_ihmsen2013.h"

#include <algorithm>

#include "sim/fluid/density.h"
#include "sim/world/pair_loop.h"

namespace sim {

IisphIhmsen2013::IisphIhmsen2013(const IisphParameters& parameters) : params_(parameters) {
  require(params_.tolerance > 0, "IISPH tolerance must be > 0");
  require(params_.relaxation > 0 && params_.relaxation <= 1, "IISPH relaxation must be in (0, 1]");
  require(params_.maxIterations >= params_.minIterations && params_.minIterations >= 1,
          "IISPH needs 1 <= minIterations <= maxIterations");
}

void IisphIhmsen2013::attach(World& world) {
  pressure_ = &world.particles.fields.addOrGet<Real>({"pressure", "Pa", true, true});
}

void IisphIhmsen2013::beginStep(World& world, const StepContext&) {
  computeDensities(world, world.particles.density);
  previous_ = *pressure_;  // a rejected attempt restarts from the accepted step
}

void IisphIhmsen2013::pressureAcceleration(const World& world) {
  const auto& p = world.particles;
  const auto& walls = world.walls;
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const auto& pressure = *pressure_;
  const Real wallFactor = params_.mirrorWallPressure ? 2.0 : 1.0;
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real pi = pressure[i] / (p.density[i] * p.density[i]);
    Vec3 a = Vec3::Zero();
    fluid.forEach(i, [&](Index j, const Vec3& gradW) {
      a -= p.mass[j] * (pi + pressure[j] / (p.density[j] * p.density[j])) * gradW;
    });
    Vec3 g = Vec3::Zero();
    wall.forEach(i, [&](Index b, const Vec3& gradW) { g += walls.volume[b] * gradW; });
    acceleration_[i] = a - wallFactor * world.restDensityOf(i) * pi * g;
  }
}

void IisphIhmsen2013::correctVelocities(World& world, const StepContext& context) {
  auto& p = world.particles;
  const Real dt = context.dt, dt2 = dt * dt;
  const Index n = static_cast<Index>(p.size());
  auto& pressure = *pressure_;
  advected_.resize(n);
  diagonal_.resize(n);
  product_.resize(n);
  acceleration_.resize(n);

  advectedDensityAndDiagonal(world, dt);
  // A full neighbourhood has |a_ii| ~ dt^2 / d^2; below 1e-6 of that the particle is isolated.
  const Real guard = 1e-6 * dt2 / (world.particleSpacing() * world.particleSpacing());

  Real error = 0;
  int iteration = 0;
  for (;; ++iteration) {
    pressureAcceleration(world);
    pressureProduct(world, dt2);
    // Mean compression of the predicted density rho_adv + A p (only compression counts).
    error = reducer_.sum(n, [&](std::size_t i) {
      const Index k = static_cast<Index>(i);
      return std::max((advected_[k] + product_[k]) / world.restDensityOf(k) - 1.0, Real(0));
    }) / n;
    if ((iteration >= params_.minIterations && error < params_.tolerance) ||
        iteration >= params_.maxIterations)
      break;
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
      if (-diagonal_[i] < guard) {  // small-diagonal guard
        pressure[i] = 0;
        continue;
      }
      const Real residual = world.restDensityOf(i) - advected_[i] - product_[i];
      pressure[i] = std::max(pressure[i] + params_.relaxation * residual / diagonal_[i], Real(0));
    }
  }
  // The last acceleration_ belongs to the final pressures.
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) p.v[i] += dt * acceleration_[i];
  stats_.densityIterations = iteration;
  stats_.densityIterationLimit = params_.maxIterations;
  stats_.divergenceIterations = 0;
  stats_.averageCompression = error;
  stats_.maxCompression =
      DeterministicReducer::max(static_cast<std::size_t>(n), [&](std::size_t i) {
        const Index k = static_cast<Index>(i);
        return (advected_[k] + product_[k]) / world.restDensityOf(k) - 1.0;
      });
}

// rho_adv from v* and the diagonal a_ii = d(A p)_i / d p_i (docs/methods/solvers.md); also the
// warm-started pressures. Allocates nothing.
void IisphIhmsen2013::advectedDensityAndDiagonal(const World& world, Real dt) {
  const auto& p = world.particles;
  const auto& walls = world.walls;
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Real dt2 = dt * dt;
  const Real wallFactor = params_.mirrorWallPressure ? 2.0 : 1.0;
  const Index n = static_cast<Index>(p.size());
  auto& pressure = *pressure_;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real rho0 = world.restDensityOf(i);
    Real rate = 0, sumSq = 0;
    Vec3 gFluid = Vec3::Zero(), gWall = Vec3::Zero();
    fluid.forEach(i, [&](Index j, const Vec3& gradW) {
      rate += p.mass[j] * (p.v[i] - p.v[j]).dot(gradW);
      gFluid += p.mass[j] * gradW;
      sumSq += p.mass[j] * gradW.squaredNorm();
    });
    Real wallRate = 0;
    wall.forEach(i, [&](Index b, const Vec3& gradW) {
      wallRate += walls.volume[b] * p.v[i].dot(gradW);
      gWall += walls.volume[b] * gradW;
    });
    advected_[i] = p.density[i] + dt * (rate + rho0 * wallRate);
    const Real invRho2 = 1.0 / (p.density[i] * p.density[i]);
    // a_i depends on p_i through -p_i/rho_i^2 (gFluid + wallFactor rho0 gWall); a_j through
    // +m_i p_i/rho_i^2 gradW_ij. Both enter (A p)_i as in the PPE above.
    const Vec3 own = gFluid + wallFactor * rho0 * gWall;
    diagonal_[i] = -dt2 * invRho2 * (own.dot(gFluid + rho0 * gWall) + p.mass[i] * sumSq);
    pressure[i] = params_.warmStartFactor * previous_[i];
  }
}

// product_ = (A p) from the current acceleration_. Allocates nothing.
void IisphIhmsen2013::pressureProduct(const World& world, Real dt2) {
  const auto& p = world.particles;
  const auto& walls = world.walls;
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Real value = 0;
    fluid.forEach(i, [&](Index j, const Vec3& gradW) {
      value += p.mass[j] * (acceleration_[i] - acceleration_[j]).dot(gradW);
    });
    Real wallSum = 0;
    wall.forEach(i, [&](Index b, const Vec3& gradW) {
      wallSum += walls.volume[b] * acceleration_[i].dot(gradW);
    });
    product_[i] = dt2 * (value + world.restDensityOf(i) * wallSum);
  }
}

}  // namespace sim
