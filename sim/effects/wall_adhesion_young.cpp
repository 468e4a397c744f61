#include "sim/effects/wall_adhesion_young.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "sim/boundary/wall_layers.h"
#include "sim/boundary/wetted_surface.h"
#include "sim/effects/symmetric_stress_sum.h"
#include "sim/world/pair_loop.h"

namespace sim {
namespace {

// 2-D cubic spline with support radius h (Monaghan 1992 normalisation 40 / (7 pi h^2)), used
// only to measure the area per wall particle on the sampled wall surface.
Real cubicSpline2d(Real r, Real h) {
  const Real q = r / h;
  if (q >= 1) return 0;
  const Real norm = 40.0 / (7.0 * std::numbers::pi * h * h);
  if (q <= 0.5) return norm * (6 * (q * q * q - q * q) + 1);
  const Real t = 1 - q;
  return norm * 2 * t * t * t;
}

}  // namespace

WallLayerPhase wallLayerPhaseFor(bool backgroundPressure) {
  return backgroundPressure ? WallLayerPhase::kLarger : WallLayerPhase::kNonWetting;
}

void WallAdhesionYoung::attach(World& world) {
  const auto& materials = world.materials;
  const auto& angles = materials.contactAngles();
  const auto& tensions = materials.interfacialTensions();
  require(!angles.empty(), "wall_adhesion is on but no contact angle is given");
  require(!tensions.empty(),
          "a contact angle needs an interfacial tension between the fluid that touches the wall "
          "and the other fluid: set sigma (MaterialTable::setInterfacialTension)");
  const InterfacialTension& pair = tensions.front();
  materialA_ = pair.materialA;
  materialB_ = pair.materialB;
  sigma_ = pair.sigma;
  {
    const auto& p = world.particles;
    Real volumeA = 0, volumeB = 0;  // [m^3] at rest density
    for (Index i = 0; i < static_cast<Index>(p.size()); ++i) {
      if (p.material[i] == materialA_) volumeA += p.mass[i] / materials[materialA_].restDensity;
      if (p.material[i] == materialB_) volumeB += p.mass[i] / materials[materialB_].restDensity;
    }
    layerOnA_ = volumeA > volumeB;
  }
  const std::size_t nWalls = world.walls.size();
  cosThetaA_.assign(nWalls, std::numeric_limits<Real>::quiet_NaN());
  // Layered walls (sim/boundary/wall_layers.h): only the surface layer is the wetted surface;
  // the layers behind it would triple the area density and see no fluid of their own.
  surface_.resize(nWalls);
  for (std::size_t b = 0; b < nWalls; ++b) surface_[b] = isSurfaceWall(world.walls, b) ? 1 : 0;
  assignContactAngles(world);
  measureWallAreas(world);
}

// cos(theta_A) per surface wall particle and per wetted-tissue tag, from the contact angles.
void WallAdhesionYoung::assignContactAngles(const World& world) {
  const auto& materials = world.materials;
  const std::size_t nWalls = world.walls.size();
  const std::vector<std::int32_t>* wetted = findWettedSurfaceField(world.particles);  // tag + 1
  for (const auto& angle : materials.contactAngles()) {
    const std::string& fluid = materials[angle.fluidMaterial].name;
    require(angle.fluidMaterial == materialA_ || angle.fluidMaterial == materialB_,
            "contact angle given through '" + fluid +
                "', which is not in the first tension pair ('" + materials[materialA_].name +
                "', '" + materials[materialB_].name +
                "'): wall wetting supports one pair of liquids; list that pair first");
    // theta through B is 180 deg - theta through A.
    const Real thetaA = angle.fluidMaterial == materialA_ ? angle.angle : 180.0 - angle.angle;
    const Real cosA = std::cos(thetaA * std::numbers::pi / 180.0);
    tagCosA_.emplace_back(angle.wallTag, cosA);
    bool found = false;
    for (std::size_t b = 0; b < nWalls; ++b)
      if (world.walls.tag[b] == angle.wallTag && surface_[b]) {
        cosThetaA_[b] = cosA;
        found = true;
      }
    if (wetted && std::find(wetted->begin(), wetted->end(), angle.wallTag + 1) != wetted->end()) {
      found = true;
      wettedTissue_ = true;
    }
    require(found, "contact angle for wall tag " + std::to_string(angle.wallTag) + " (through '" +
                       fluid + "') but no wall particle and no wetted tissue surface has that tag");
  }
  for (Index i = 0; wetted && i < static_cast<Index>(world.particles.size()); ++i)
    require((*wetted)[i] == 0 || !materials.isFluid(world.particles.material[i]),
            "a fluid particle of '" + materials[world.particles.material[i]].name +
                "' is marked as a wetted surface: only elastic tissue can be one");
}

// Area per wall particle from the surface number density of the wall sample.
void WallAdhesionYoung::measureWallAreas(const World& world) {
  const std::size_t nWalls = world.walls.size();
  const NeighborList& ss = world.search().staticStatic();
  const Real h = world.supportRadius();
  wallArea_.resize(nWalls);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nWalls; ++b) {
    Real density = cubicSpline2d(0, h);  // [1/m^2]
    for (const Index* k = ss.begin(static_cast<Index>(b)); k != ss.end(static_cast<Index>(b)); ++k)
      if (*k != b && surface_[*k])
        density += cubicSpline2d((world.walls.x[b] - world.walls.x[*k]).norm(), h);
    wallArea_[b] = 1.0 / density;
  }
}

void WallAdhesionYoung::updateWettedTissue(World& world) {
  const auto& p = world.particles;
  const Index n = static_cast<Index>(p.size());
  const auto& tags = *findWettedSurfaceField(p);  // tag + 1, 0 = none
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Kernel& kernel = world.kernel;
  const Real h = world.supportRadius();
  tissueCosA_.resize(n);
  tissueNormal_.resize(n);
  tissueArea_.resize(n);
  tissueFluidSum_.resize(n);
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < n; ++k) {
    tissueCosA_[k] = std::numeric_limits<Real>::quiet_NaN();
    if (tags[k] == 0) continue;
    Real cosA = std::numeric_limits<Real>::quiet_NaN();
    for (const auto& [tag, c] : tagCosA_)
      if (tag == tags[k] - 1) cosA = c;
    if (std::isnan(cosA)) continue;
    // The normal is the gradient of the non-fluid volume fraction (tissue and walls against the
    // fluid), the kernel gradients gradW(x_k - x_j) pointing from k towards j: into the tissue.
    Vec3 g = Vec3::Zero();
    Real surfaceDensity = cubicSpline2d(0, h), fluidSum = 0;  // [1/m^2], [1]
    fluid.forEach(k, [&](Index j, const Vec3& gradW) {
      const Real vj = p.mass[j] / p.density[j];
      if (world.materials.isFluid(p.material[j])) {
        g -= vj * gradW;
        if (p.material[j] == materialA_ || p.material[j] == materialB_)
          fluidSum += vj * kernel.W(p.x[k] - p.x[j]);
      } else {
        g += vj * gradW;
        if (tags[j] != 0) surfaceDensity += cubicSpline2d((p.x[k] - p.x[j]).norm(), h);
      }
    });
    wall.forEach(k, [&](Index b, const Vec3& gradW) { g += world.walls.volume[b] * gradW; });
    if (g.squaredNorm() == 0) continue;
    tissueNormal_[k] = g.normalized();
    tissueArea_[k] = 1.0 / surfaceDensity;
    tissueFluidSum_[k] = fluidSum;
    tissueCosA_[k] = cosA;
  }
}

void WallAdhesionYoung::apply(World& world, const StepContext&) {
  if (wettedTissue_) updateWettedTissue(world);
  sumWallFluid(world);
  if (!wallStress(world)) return;
  applyStressForces(world);
}

// S_b: serial scatter over the wall lists (deterministic order; O(particles near walls)).
// Allocates nothing after the first step.
void WallAdhesionYoung::sumWallFluid(const World& world) {
  const auto& p = world.particles;
  const auto& walls = world.walls;
  const Index n = static_cast<Index>(p.size());
  const NeighborList& nw = world.wallNeighbors();
  const Kernel& kernel = world.kernel;
  wallFluidSum_.assign(walls.size(), 0.0);
  for (Index i = 0; i < n; ++i) {
    if (nw.count(i) == 0) continue;
    const Real vi = p.mass[i] / p.density[i];
    for (const Index* b = nw.begin(i); b != nw.end(i); ++b)
      if (surface_[*b]) wallFluidSum_[*b] += vi * kernel.W(p.x[i] - walls.x[*b]);
  }
}

// Wall delta function, wall normal and wall-interface stress per particle; false when no
// particle is stressed. Allocates nothing after the first step.
bool WallAdhesionYoung::wallStress(const World& world) {
  const auto& p = world.particles;
  const auto& walls = world.walls;
  const Index n = static_cast<Index>(p.size());
  const NeighborList& nf = world.fluidNeighbors();
  const NeighborList& nw = world.wallNeighbors();
  const Kernel& kernel = world.kernel;
  stress_.resize(n);
  stressed_.assign(n, 0);
  bool any = false;
#pragma omp parallel for schedule(static) reduction(|| : any)
  for (Index i = 0; i < n; ++i) {
    if (!inPair(p.material[i]) || (nw.count(i) == 0 && !wettedTissue_)) continue;
    Real delta = 0, cosWeighted = 0, weight = 0;  // [1/m], [1], [1/m^3]
    Vec3 m = Vec3::Zero();
    // Wetted tissue particles enter as wall particles do, with this step's area and normal.
    if (wettedTissue_)
      for (Index q = nf.offsets[i]; q < nf.offsets[i + 1]; ++q) {
        const Index k = nf.indices[q];
        if (std::isnan(tissueCosA_[k]) || tissueFluidSum_[k] < 1e-3) continue;
        const Real w = kernel.W(p.x[i] - p.x[k]);
        delta += tissueArea_[k] / tissueFluidSum_[k] * w;
        cosWeighted += w * tissueCosA_[k];
        weight += w;
        m -= w * tissueNormal_[k];
      }
    for (const Index* bp = nw.begin(i); bp != nw.end(i); ++bp) {
      const Index b = *bp;
      if (std::isnan(cosThetaA_[b])) continue;
      const Real w = kernel.W(p.x[i] - walls.x[b]);
      // A wall particle that sees almost no fluid (a dry corner) would make A_b / S_b blow up;
      // 1e-3 of a half-filled kernel is far below any wetted wall.
      if (wallFluidSum_[b] < 1e-3) continue;
      delta += wallArea_[b] / wallFluidSum_[b] * w;
      cosWeighted += w * cosThetaA_[b];
      weight += w;
      m -= w * walls.normal[b];  // wall normals point into the wall
    }
    if (weight <= 0 || m.squaredNorm() == 0) continue;
    m.normalize();
    const Real cosA = cosWeighted / weight;
    // Only gamma_wB - gamma_wA = sigma cos(theta_A) matters; all of it goes to one phase
    // (WallLayerPhase in the header). A layer on one phase ends only at the contact line and
    // where that phase's wetted wall ends.
    const bool isA = p.material[i] == materialA_;
    const bool onA = layer_ == WallLayerPhase::kLarger ? layerOnA_ : cosA < 0;
    if (isA != onA) continue;
    const Real gamma = isA ? -sigma_ * cosA : sigma_ * cosA;  // [N/m]
    if (gamma == 0.0) continue;
    stress_[i] = gamma * delta * (Mat3::Identity() - m * m.transpose());
    stressed_[i] = 1;
    any = true;
  }
  return any;
}

// Divergence of the stress over the fluid neighbours. Allocates nothing.
void WallAdhesionYoung::applyStressForces(World& world) {
  auto& p = world.particles;
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    if (!inPair(p.material[i])) continue;
    const Real vi = p.mass[i] / p.density[i];
    // Tissue neighbours stay out of the sum, as wall particles do (they are not in the fluid
    // lists). With them a stressed particle read gamma delta P sum_j V_j gradW_ij over the
    // tissue, the tangential gradient of the tissue's number density: 0 above the lattice's
    // columns, and off them a force towards the columns for a layer under tension (away from
    // them under compression) that walls do not exert (docs/methods/interface.md, validation 3).
    const Vec3 f = symmetricStressSum(world, i, vi, stress_, stressed_, [&](Index j) {
      return world.materials.isFluid(p.material[j]);
    });  // [N]
    p.a[i] += f / p.mass[i];
  }
}

}  // namespace sim
