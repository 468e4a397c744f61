#include "sim/fluid/number_density_solenthaler2008.h"

#include <algorithm>

#include "sim/fluid/indsph_wang2023.h"
#include "sim/fluid/neighbor_sums.h"
#include "sim/fluid/tait_equation.h"

namespace sim {

NumberDensitySolenthaler2008::NumberDensitySolenthaler2008(const WcsphParameters& parameters)
    : params_(parameters) {
  require(params_.speedOfSound > 0,
          "number-density SPH needs a speed of sound > 0 m/s (PipelineOptions.wcsph.speedOfSound, "
          "about 10x the flow speed)");
  require(params_.courantNumber > 0 && params_.courantNumber <= 1,
          "number-density SPH Courant number must be in (0, 1]");
}

void NumberDensitySolenthaler2008::attach(World& world) {
  auto& f = world.particles.fields;
  numberDensity_ = &f.addOrGet<Real>({"number_density", "1/m^3", false, true});
  pressure_ = &f.addOrGet<Real>({"pressure", "Pa", false, true});
}

Real NumberDensitySolenthaler2008::maxTimeStep(const World& world) const {
  return params_.courantNumber * world.particleSpacing() / params_.speedOfSound;
}

void NumberDensitySolenthaler2008::beginStep(World& world, const StepContext&) {
  auto& p = world.particles;
  computeNumberDensities(world, *numberDensity_);
  const Real c2 = params_.speedOfSound * params_.speedOfSound;
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real rho0 = world.restDensityOf(i);
    p.density[i] = p.mass[i] * (*numberDensity_)[i];  // adapted density rho~ (eq. 7)
    (*pressure_)[i] = taitPressure(p.density[i], rho0, c2);
  }
}

void NumberDensitySolenthaler2008::correctVelocities(World& world, const StepContext& context) {
  auto& p = world.particles;
  const NeighborList& nf = world.fluidNeighbors();
  const Kernel& kernel = world.kernel;
  const Real h = kernel.supportRadius();
  const Real alphaC = params_.artificialViscosity * params_.speedOfSound;
  const auto& pressure = *pressure_;
  const auto& delta = *numberDensity_;
  const Index n = static_cast<Index>(p.size());
  acceleration_.resize(n);
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real pi = pressure[i] / (delta[i] * delta[i]);
    Vec3 force = Vec3::Zero();
    for (const Index* jp = nf.begin(i); jp != nf.end(i); ++jp) {
      const Index j = *jp;
      const Vec3 xij = p.x[i] - p.x[j];
      force -= (pi + pressure[j] / (delta[j] * delta[j])) * kernel.gradW(xij);
      const Real vx = (p.v[i] - p.v[j]).dot(xij);
      if (vx < 0 && alphaC > 0) {  // Monaghan artificial viscosity, as in the WCSPH solver
        const Real mu = 0.5 * h * vx / (xij.squaredNorm() + 0.01 * h * h);
        force += p.mass[i] * p.mass[j] * alphaC * mu / (0.5 * (p.density[i] + p.density[j])) *
                 kernel.gradW(xij);
      }
    }
    const Vec3 g = wallVolumeSum(world, i, Vec3(Vec3::Zero()),
                                 [&](const Vec3& xib) -> Vec3 { return kernel.gradW(xib); });
    force -= pi * g / world.restVolumeOf(i);
    acceleration_[i] = force / p.mass[i];
  }
  const Real dt = context.dt;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) p.v[i] += dt * acceleration_[i];
  stats_.densityIterations = 0;
  stats_.divergenceIterations = 0;
  stats_.averageCompression = reducer_.sum(n, [&](std::size_t i) {
    return std::max(delta[i] * world.restVolumeOf(static_cast<Index>(i)) - 1.0, Real(0));
  }) / n;
  stats_.maxCompression = DeterministicReducer::max(
      static_cast<std::size_t>(n),
      [&](std::size_t i) { return delta[i] * world.restVolumeOf(static_cast<Index>(i)) - 1.0; });
}

}  // namespace sim
