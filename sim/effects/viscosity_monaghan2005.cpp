#include "sim/effects/viscosity_monaghan2005.h"
#include "sim/world/pair_loop.h"

#include <limits>

namespace sim {

void ViscosityMonaghan2005::attach(World& world) {
  viscosityOfMaterial_.clear();
  // An elastic material is marked -1: a fluid particle sees an elastic neighbour as a wall moving
  // with it (the fluid's viscosity), the elastic particle gets the opposite pair force, and
  // elastic-elastic pairs are skipped (docs/methods/elasticity.md).
  for (const auto& m : world.materials)
    viscosityOfMaterial_.push_back(isFluid(m.kind) ? m.dynamicViscosity : -1.0);
}

Real ViscosityMonaghan2005::maxTimeStep(const World& world) const {
  Real nuMax = 0;
  for (const auto& m : world.materials) nuMax = std::max(nuMax, m.kinematicViscosity());
  if (nuMax <= 0) return std::numeric_limits<Real>::infinity();
  // Diffusion limit with the particle spacing d (the smoothing length of the classic bound, Morris
  // et al. 1997), not the support radius 2d, which would be 4x too large.
  const Real d = world.particleSpacing();
  return kStableStepFactor * d * d / nuMax;
}

void ViscosityMonaghan2005::apply(World& world, const StepContext& context) {
  if (smoothing_ > 0)
    applyImpl<true>(world, context);
  else
    applyImpl<false>(world, context);
}

// Elastic particle i: the reaction of its fluid neighbours' moving-wall drag (applyImpl), the
// same pair term with the fluid's viscosity and the opposite sign, so momentum goes from fluid to
// solid, none is lost. Nothing between elastic pairs. Without the factor 2(d+2).
Vec3 ViscosityMonaghan2005::elasticReaction(const World& world, Index i, Real h2) const {
  const auto& p = world.particles;
  Vec3 a = Vec3::Zero();
  fluidPairs(world).forEach(i, [&](Index j, const Vec3& gradW) {
    const Real muj = viscosityOfMaterial_[static_cast<std::size_t>(p.material[j])];
    if (muj <= 0) return;
    const Vec3 xij = p.x[i] - p.x[j];
    const Real vx = (p.v[i] - p.v[j]).dot(xij);
    a += (p.mass[j] * muj / (p.density[i] * p.density[j]) * vx / (xij.squaredNorm() + h2)) * gradW;
  });
  return a;
}

template <bool kSmoothing>
void ViscosityMonaghan2005::applyImpl(World& world, const StepContext& context) {
  auto& p = world.particles;
  const auto& walls = world.walls;
  const NeighborList& nf = world.fluidNeighbors();
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Kernel& kernel = world.kernel;
  const Real h2 = 0.01 * world.supportRadius() * world.supportRadius();
  constexpr Real kFactor = 2.0 * (3 + 2);                                  // 2(d+2), d = 3
  const Real smoothingScale = kSmoothing ? smoothing_ / context.dt : 0.0;  // XSPH eps/dt [1/s]
  const Index n = static_cast<Index>(p.size());
  // XSPH reads the kernel values the neighbour pass cached (no square root per pair).
  const std::vector<PairValue>& cachedW = world.fluidKernelValues();
  const PairValue* cache = cachedW.size() == nf.indices.size() ? cachedW.data() : nullptr;
  // The viscosity per particle once instead of a material lookup per pair.
  viscosity_.resize(p.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i)
    viscosity_[i] = viscosityOfMaterial_[static_cast<std::size_t>(p.material[i])];
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real mui = viscosity_[i];
    if (mui < 0) {
      p.a[i] += kFactor * elasticReaction(world, i, h2);
      continue;
    }
    Vec3 a = Vec3::Zero();
    Vec3 smooth = Vec3::Zero();
    fluid.forEach(i, [&](Index j, const Vec3& gradW, Index k) {
      const Vec3 xij = p.x[i] - p.x[j];
      // XSPH's rule (xsph_monaghan1989.h): same material only, which also leaves out solids.
      if constexpr (kSmoothing)
        if (p.material[j] == p.material[i])
          smooth += XsphMonaghan1989::pairTerm(p, i, j,
                                               pairValue(cache, k, [&] { return kernel.W(xij); }));
      const Real muj = viscosity_[j];
      // An elastic neighbour is a wall moving with the solid's velocity: the fluid's viscosity.
      const Real mu = muj < 0 ? mui : 0.5 * (mui + muj);
      if (mu == 0) return;
      const Real vx = (p.v[i] - p.v[j]).dot(xij);
      a += (p.mass[j] * mu / (p.density[i] * p.density[j]) * vx / (xij.squaredNorm() + h2)) * gradW;
    });
    if (wallFriction_ && mui > 0)
      wall.forEach(i, [&](Index b, const Vec3& gradW) {
        const Vec3 xib = p.x[i] - walls.x[b];
        const Real vx = p.v[i].dot(xib);
        a += (walls.volume[b] * mui / p.density[i] * vx / (xib.squaredNorm() + h2)) * gradW;
      });
    p.a[i] += kFactor * a;
    if constexpr (kSmoothing) p.a[i] += smoothingScale * smooth;
  }
}

}  // namespace sim
