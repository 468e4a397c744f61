#include "sim/fluid/vslsph_li2023.h"

#include <algorithm>
#include <cmath>

#include "sim/fluid/density_compression.h"
#include "sim/fluid/neighbor_sums.h"

namespace sim {
namespace {

// The kernel of support h_i from the world's kernel of support h: every kernel of the engine is
// sigma/h^3 f(r/h), so W_{h_i}(r) = s^3 W_h(s r) and gradW_{h_i}(x, r) = s^5 gradW_h(x, s r)
// (gradW_h(x, r) = x W_h'(r)/r), with s = h / h_i.
Real scaledW(const Kernel& kernel, Real r, Real s) { return s * s * s * kernel.W(s * r); }
Vec3 scaledGradW(const Kernel& kernel, const Vec3& xij, Real r, Real s) {
  const Real s2 = s * s;
  return (s2 * s2 * s) * kernel.gradW(xij, s * r);
}
// Eq. 17's kernel average of the two particles' kernels, value and gradient.
Real averageW(const Kernel& kernel, Real r, Real si, Real sj) {
  return 0.5 * (scaledW(kernel, r, si) + scaledW(kernel, r, sj));
}
Vec3 averageGradW(const Kernel& kernel, const Vec3& xij, Real r, Real si, Real sj) {
  return 0.5 * (scaledGradW(kernel, xij, r, si) + scaledGradW(kernel, xij, r, sj));
}

// Fluid-wall pairs: the wall particle carries the fixed support h its volume was computed with
// (scale 1), averaged with the fluid particle's as eq. 17 does for two fluid particles.
Real wallW(const Kernel& kernel, Real r, Real si) { return averageW(kernel, r, si, 1.0); }
Vec3 wallGradW(const Kernel& kernel, const Vec3& xib, Real r, Real si) {
  return averageGradW(kernel, xib, r, si, 1.0);
}

}  // namespace

VslsphLi2023::VslsphLi2023(const VslsphParameters& parameters) : params_(parameters) {
  require(params_.speedOfSound > 0,
          "VSLSPH needs a speed of sound > 0 m/s (about 10x the flow speed; 0 takes WCSPH's)");
  require(params_.artificialViscosity >= 0, "VSLSPH artificial viscosity must be >= 0");
  require(params_.courantNumber > 0 && params_.courantNumber <= 1,
          "VSLSPH Courant number must be in (0, 1]");
  require(params_.minSupportFactor > 0 && params_.minSupportFactor <= 1,
          "VSLSPH smallest support factor must be in (0, 1] kernel supports");
  require(params_.maxSupportFactor >= 1 && params_.maxSupportFactor <= 3,
          "VSLSPH largest support factor must be in [1, 3] kernel supports");
}

void VslsphLi2023::attach(World& world) {
  auto& f = world.particles.fields;
  pressure_ = &f.addOrGet<Real>({"pressure", "Pa", false, true});
  // h_i decides the next step's neighbour lists, so a resumed run needs it (checkpointed).
  support_ = &f.addOrGet<Real>({"support_radius", "m", true, true});
  const Real h = world.supportRadius();
  for (Real& hi : *support_)
    if (hi <= 0) hi = h;  // a fresh run starts at the kernel's support (a resumed one keeps its)
  const std::size_t n = world.particles.size();
  scale_.resize(n);
  numberDensity_.resize(n);
  pressureAcceleration_.resize(n);
  world.useVariableSupport(*support_, params_.maxSupportFactor * h);
}

Real VslsphLi2023::maxTimeStep(const World& world) const {
  return params_.courantNumber * world.particleSpacing() / params_.speedOfSound;
}

void VslsphLi2023::beginStep(World& world, const StepContext&) {
  const Real h = world.supportRadius();
  const auto& support = *support_;
  const Index n = static_cast<Index>(world.particles.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) scale_[i] = h / support[i];
  computeDensities(world);
  computePressuresAndSupports(world);
}

void VslsphLi2023::computeDensities(World& world) {
  auto& p = world.particles;
  const Kernel& kernel = world.kernel;
  const Real w0 = kernel.W0();
  const bool cached = world.parameters().cachePairKernels;
  const PairValue* fluidW = cached ? world.fluidKernelValues().data() : nullptr;
  const PairValue* wallWs = cached ? world.wallKernelValues().data() : nullptr;
  // Walls carry the fixed support h (scale 1); their volume sum over particle i's rest volume
  // counts them as neighbours of i's own kind. A pair of particles both at h (the bulk: s = 1
  // exactly, since h_i is clamped to f_min h = h) reads the search's cached W, which is the
  // average's value rounded to the cache's precision (sim/neighbors/pair_precision.h); without
  // the cache the average is rounded the same way, so the state is the same bit for bit.
  neighborSums(
      world,
      [&](Index i) {
        const Real si = scale_[i];
        return si * si * si * w0;
      },
      [&](Index i, Index j, const Vec3& xij, Index k) {
        const Real si = scale_[i], sj = scale_[j];
        const auto average = [&] { return averageW(kernel, xij.norm(), si, sj); };
        return si == 1.0 && sj == 1.0 ? pairValue(fluidW, k, average) : average();
      },
      [&](Index i, const Vec3& xib, Index k) {
        const auto wall = [&] { return wallW(kernel, xib.norm(), scale_[i]); };
        return scale_[i] == 1.0 ? pairValue(wallWs, k, wall) : wall();
      },
      [&](Index i, Real fluid, Real wall) {
        const Real delta = fluid + wall / world.restVolumeOf(i);
        numberDensity_[i] = delta;
        p.density[i] = p.mass[i] * delta;
      });
}

void VslsphLi2023::computePressuresAndSupports(World& world) {
  auto& p = world.particles;
  const Real h = world.supportRadius();
  const Real hMin = params_.minSupportFactor * h, hMax = params_.maxSupportFactor * h;
  const Real c2 = params_.speedOfSound * params_.speedOfSound;
  auto& support = *support_;
  auto& pressure = *pressure_;
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real rho0 = world.restDensityOf(i);
    const Real excess = p.density[i] / rho0 - 1.0;
    pressure[i] = std::max(rho0 * c2 * excess, Real(0));  // k = rho0 c^2, free surface clamped
    // Eq. 16 with D = 3, for the next neighbour update; this step keeps scale_.
    support[i] = std::clamp((1.0 - excess / 3.0) * h, hMin, hMax);
  }
}

Vec3 VslsphLi2023::pressureAcceleration(const World& world, Index i) const {
  const auto& p = world.particles;
  const NeighborList& nf = world.fluidNeighbors();
  const Kernel& kernel = world.kernel;
  const Real h = kernel.supportRadius();
  const Real alphaC = params_.artificialViscosity * params_.speedOfSound;
  const auto& pressure = *pressure_;
  const bool cached = world.parameters().cachePairKernels;
  const PairGradient* fluidGrad = cached ? world.fluidGradients().data() : nullptr;
  const PairGradient* wallGrad = cached ? world.wallGradients().data() : nullptr;
  const Real si = scale_[i], pi = pressure[i];
  Vec3 a = Vec3::Zero();
  for (Index k = nf.offsets[i]; k < nf.offsets[i + 1]; ++k) {
    const Index j = nf.indices[k];
    const Vec3 xij = p.x[i] - p.x[j];
    const Real r = xij.norm();
    // Both at h: the cached gradient is the average's at the cache's precision (computeDensities).
    const auto average = [&] { return averageGradW(kernel, xij, r, si, scale_[j]); };
    const Vec3 gradW =
        si == 1.0 && scale_[j] == 1.0 ? pairGradient(fluidGrad, k, average) : average();
    // Eq. 17 over m_i: V_i V_j (p_i + p_j) / m_i = (p_i + p_j) / (rho_i delta_j).
    Real term = (pi + pressure[j]) / (p.density[i] * numberDensity_[j]);
    const Real vx = (p.v[i] - p.v[j]).dot(xij);
    if (vx < 0 && alphaC > 0) {  // approaching pair: Monaghan artificial viscosity, as WCSPH
      const Real hij = 0.5 * (h / si + h / scale_[j]);
      const Real mu = 0.5 * hij * vx / (r * r + 0.01 * hij * hij);
      term -= p.mass[j] * alphaC * mu / (0.5 * (p.density[i] + p.density[j]));
    }
    a -= term * gradW;
  }
  const Vec3 g = wallVolumeSum(world, i, Vec3(Vec3::Zero()), [&](const Vec3& xib, Index k) -> Vec3 {
    const auto wall = [&] { return wallGradW(kernel, xib, xib.norm(), si); };
    return si == 1.0 ? pairGradient(wallGrad, k, wall) : wall();
  });
  // Walls have no pressure of their own (p_b = 0 in eq. 17), so a wall pair carries p_i once:
  // Akinci et al. 2012's wall force, as in WCSPH. The mirrored p_b = p_i doubles it; on the
  // settling column that threw a particle over the wall within 0.5 s, with or without variable h.
  return a - (pi / p.density[i]) * g;  // mirrored wall pressure p_b = p_i
}

void VslsphLi2023::correctVelocities(World& world, const StepContext& context) {
  auto& p = world.particles;
  const Index n = static_cast<Index>(p.size());
  // x is not yet advanced, so the forces use this step's positions; v is the prediction v*.
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) pressureAcceleration_[i] = pressureAcceleration(world, i);
  // Applied after the loop: the viscosity term above reads neighbours' velocities.
  const Real dt = context.dt;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) p.v[i] += dt * pressureAcceleration_[i];
  recordDensityCompression(world, reducer_, stats_);
}

}  // namespace sim
