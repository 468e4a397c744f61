#include "sim/fluid/dfsph_bender2017.h"

#include <algorithm>
#include <cmath>

#include "sim/fluid/density.h"
#include "sim/world/pair_loop.h"

namespace sim {

DfsphBender2017::DfsphBender2017(const DfsphParameters& parameters) : params_(parameters) {
  require(params_.densityTolerance > 0 && params_.divergenceTolerance > 0,
          "DFSPH tolerances must be > 0");
  require(params_.maxIterations >= params_.minIterations && params_.minIterations >= 1,
          "DFSPH needs 1 <= minIterations <= maxIterations");
}

void DfsphBender2017::attach(World& world) {
  auto& f = world.particles.fields;
  factor_ = &f.addOrGet<Real>({"dfsph_factor", "m^5/kg", false, false});
  pressure_ = &f.addOrGet<Real>({"pressure", "Pa", false, true});
  // Warm-start values change the next step's result, so a bit-identical resume needs them.
  kappaDensity_ = &f.addOrGet<Real>({"dfsph_kappa_density", "m^2/s^2", true, false});
  kappaDivergence_ = &f.addOrGet<Real>({"dfsph_kappa_divergence", "m^2/s^2", true, false});
}

void DfsphBender2017::applyPressureVelocity(World& world, const std::vector<Real>& kappa, Real dt) {
  auto& p = world.particles;
  const PairLoop fluid = fluidPairs(world);
  const auto& rho = p.density;
  const Index n = static_cast<Index>(p.size());
  // k_j / rho_j once per particle instead of once per pair (a division per pair saved; the same
  // quotient, so bit-identical).
  auto& scaled = kappaOverRho_;
  scaled.resize(n);
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) scaled[i] = kappa[i] / rho[i];
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real ki = scaled[i];
    Vec3 dv = Vec3::Zero();
    fluid.forEach(i,
                  [&](Index j, const Vec3& gradW) { dv += p.mass[j] * (ki + scaled[j]) * gradW; });
    dv += ki * wallGradient_[i];
    p.v[i] -= dt * dv;
  }
}

Real DfsphBender2017::densityRate(const World& world, Index i) const {
  const auto& p = world.particles;
  Real rate = 0;
  fluidPairs(world).forEach(
      i, [&](Index j, const Vec3& gradW) { rate += p.mass[j] * (p.v[i] - p.v[j]).dot(gradW); });
  return rate + p.v[i].dot(wallGradient_[i]);
}

Real DfsphBender2017::predictDensity(World& world, Real dt) {
  const auto& p = world.particles;
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real rho0 = world.restDensityOf(i);
    // Only compression is corrected: a free surface may expand (Bender 2017, clamping).
    predicted_[i] = std::max(p.density[i] + dt * densityRate(world, i), rho0);
  }
  return reducer_.sum(n, [&](std::size_t i) {
    return predicted_[i] / world.restDensityOf(static_cast<Index>(i)) - 1.0;
  }) / n;
}

Real DfsphBender2017::maxCompression(const World& world) const {
  return DeterministicReducer::max(predicted_.size(), [&](std::size_t i) {
    return predicted_[i] / world.restDensityOf(static_cast<Index>(i)) - 1.0;
  });
}

Real DfsphBender2017::computeDensityRate(World& world) {
  const Index n = static_cast<Index>(world.particles.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i)
    predicted_[i] = neighborCount(world, i) < params_.minNeighborsForDivergence
                        ? 0.0
                        : std::max(densityRate(world, i), Real(0));
  return reducer_.sum(n, [&](std::size_t i) {
    return predicted_[i] / world.restDensityOf(static_cast<Index>(i));
  }) / n;
}

void DfsphBender2017::beginStep(World& world, const StepContext& context) {
  auto& p = world.particles;
  const Index n = static_cast<Index>(p.size());
  computeDensities(world, p.density);
  // The pipeline may redo correctVelocities with a shorter dt (step rejection); every attempt must
  // warm-start from the last ACCEPTED step, not from the rejected attempt's accumulation.
  densityWarmStart_ = *kappaDensity_;
  divergenceDt_ = context.dt;
  predicted_.resize(n);
  kappa_.resize(n);
  wallGradient_.resize(n);

  stats_.divergenceIterations = 0;
  const Real dt = context.dt;
  const bool divergence = params_.divergenceSolve && dt > 0;
  stiffnessFactors(world, divergence);
  if (!divergence) return;
  solveDivergence(world, dt);
}

// Stiffness factor alpha_i (derivation in docs/methods/solvers.md). The same pass also computes
// the divergence solve's first density rate and warm start (below), which only need this
// particle's own values: one sweep over the pairs instead of two (bit-identical).
// Allocates nothing.
void DfsphBender2017::stiffnessFactors(const World& world, bool divergence) {
  const auto& p = world.particles;
  const auto& walls = world.walls;
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Kernel& kernel = world.kernel;
  const Index n = static_cast<Index>(p.size());
  // kappaDivergence_ holds last step's accumulated stiffness (a pressure per density, m^2/s^2),
  // not stiffness * dt: the pressure is what persists from step to step when dt changes.
  auto& warm = *kappaDivergence_;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Vec3 g = Vec3::Zero();
    Real sumSq = 0;
    fluid.forEach(i, [&](Index j, const Vec3& gradW) {
      const Vec3 massGradW = p.mass[j] * gradW;
      g += massGradW;
      sumSq += massGradW.squaredNorm() * p.mass[i] / p.mass[j];
    });
    Vec3 gw = Vec3::Zero();
    wall.forEach(i, [&](Index b, const Vec3& gradW) { gw += walls.volume[b] * gradW; });
    wallGradient_[i] = world.restDensityOf(i) * gw;
    g += wallGradient_[i];
    const Real denominator = g.squaredNorm() + sumSq;
    // A full neighbourhood gives a denominator of order (rho/h)^2; a particle with almost no
    // neighbours gets alpha = 0 instead of an enormous stiffness (Bender 2017).
    const Real h = kernel.supportRadius();
    const Real typical = p.density[i] * p.density[i] / (h * h);
    (*factor_)[i] = denominator > 1e-6 * typical ? p.density[i] / denominator : 0.0;
    if (!divergence) continue;
    // Warm start only where the fluid is still compressing: re-applying last step's pressure to
    // a particle that is now expanding would push it apart further and inject energy (the same
    // condition SPlisHSPlasH applies). Same values as computeDensityRate().
    predicted_[i] = neighborCount(world, i) < params_.minNeighborsForDivergence
                        ? 0.0
                        : std::max(densityRate(world, i), Real(0));
    kappa_[i] = predicted_[i] > 0 ? params_.warmStartFactor * warm[i] : 0.0;
    warm[i] = kappa_[i];
  }
}

// Divergence-free solve (Bender 2017, Algorithm 2): makes Drho/Dt = 0 for the current velocities.
// Allocates nothing.
void DfsphBender2017::solveDivergence(World& world, Real dt) {
  const Index n = static_cast<Index>(world.particles.size());
  auto& warm = *kappaDivergence_;
  if (params_.warmStartFactor > 0) applyPressureVelocity(world, kappa_, dt);
  Real error = computeDensityRate(world) * dt;
  int iteration = 0;
  while ((iteration < 1 || error > params_.divergenceTolerance) &&
         iteration < params_.maxDivergenceIterations) {
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
      kappa_[i] = params_.relaxation * predicted_[i] * (*factor_)[i] / dt;
      warm[i] += kappa_[i];
    }
    applyPressureVelocity(world, kappa_, dt);
    error = computeDensityRate(world) * dt;
    ++iteration;
  }
  stats_.divergenceIterations = iteration;
}

void DfsphBender2017::correctVelocities(World& world, const StepContext& context) {
  auto& p = world.particles;
  const Index n = static_cast<Index>(p.size());
  const Real dt = context.dt;
  const Real invDt2 = 1.0 / (dt * dt);
  auto& warm = *kappaDensity_;

  // Warm start with a fraction of last step's accumulated stiffness (Bender 2017, section 4.2).
  // The stored value is the stiffness itself (p/rho), so a change of dt does not rescale the
  // pressure (storing kappa * dt^2 made a rejected step, redone with dt/2, start from 4x the
  // pressure, which was rejected again: the jitter of the KNOWN PROBLEM).
  predictDensity(world, dt);
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    kappa_[i] = (!params_.warmStartOnlyCompressed || predicted_[i] > world.restDensityOf(i))
                    ? params_.warmStartFactor * densityWarmStart_[i]
                    : 0.0;
    warm[i] = kappa_[i];
  }
  if (params_.warmStartFactor > 0) applyPressureVelocity(world, kappa_, dt);

  // Constant-density solve (Bender 2017, Algorithm 3).
  Real error = predictDensity(world, dt);
  Real maxError = maxCompression(world);
  int iteration = 0;
  // Stop when the mean compression is below the tolerance (Bender 2017) AND no particle is
  // compressed by more than maxErrorFactor times it: the mean alone lets a few strongly
  // compressed particles at corners keep their error, and they then leak through walls.
  while ((iteration < params_.minIterations || error > params_.densityTolerance ||
          maxError > params_.maxErrorFactor * params_.densityTolerance) &&
         iteration < params_.maxIterations) {
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
      kappa_[i] =
          params_.relaxation * (predicted_[i] - world.restDensityOf(i)) * invDt2 * (*factor_)[i];
      warm[i] += kappa_[i];
    }
    applyPressureVelocity(world, kappa_, dt);
    error = predictDensity(world, dt);
    maxError = maxCompression(world);
    ++iteration;
  }
  stats_.densityIterations = iteration;
  stats_.densityIterationLimit = params_.maxIterations;
  stats_.averageCompression = error;
  stats_.maxCompression = maxError;
  // Pressure p = kappa * rho (kappa is p/rho in Bender's notation), for output. Both solves apply
  // pressure impulses over a step: the divergence solve at its start with the previous step's
  // length, so its equivalent pressure over this step is kappa_v * dt_prev / dt.
  const Real divergenceScale = divergenceDt_ > 0 ? divergenceDt_ / dt : 0.0;
  const auto& warmDivergence = *kappaDivergence_;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i)
    (*pressure_)[i] = (warm[i] + warmDivergence[i] * divergenceScale) * p.density[i];
}

}  // namespace sim
