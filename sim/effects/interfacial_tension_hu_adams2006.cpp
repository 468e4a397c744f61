#include "sim/effects/interfacial_tension_hu_adams2006.h"
#include "sim/effects/symmetric_stress_sum.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "sim/effects/gradient_correction.h"
#include "sim/world/pair_loop.h"

namespace sim {
namespace {

// Colour of material m for the pair (a, b): 1 on a, 0 on b, -1 if it takes no part.
inline int colourOf(int m, const InterfacialTension& pair) {
  return m == pair.materialA ? 1 : (m == pair.materialB ? 0 : -1);
}

}  // namespace

std::string_view surfaceStressFormName(SurfaceStressForm form) {
  switch (form) {
    case SurfaceStressForm::kAuto: return "auto";
    case SurfaceStressForm::kCorrected: return "corrected";
    case SurfaceStressForm::kSymmetric: return "symmetric";
  }
  return "?";
}

SurfaceStressForm surfaceStressFormFromName(std::string_view name) {
  for (const SurfaceStressForm form :
       {SurfaceStressForm::kCorrected, SurfaceStressForm::kSymmetric})
    if (name == surfaceStressFormName(form)) return form;
  return SurfaceStressForm::kAuto;
}

SurfaceStressForm resolveSurfaceStressForm(SurfaceStressForm requested, std::string_view solver) {
  if (requested != SurfaceStressForm::kAuto) return requested;
  return solver == "wcsph" ? SurfaceStressForm::kSymmetric : SurfaceStressForm::kCorrected;
}

void InterfacialTensionHuAdams2006::attach(World& world) {
  const auto& tensions = world.materials.interfacialTensions();
  require(!tensions.empty(),
          "interfacial_tension is on but no pair of materials has a tension sigma > 0 N/m: set one "
          "(MaterialTable::setInterfacialTension) or switch the stage off");
  for (const auto& t : tensions)
    require(world.materials[t.materialA].kind == MaterialKind::kFluid &&
                world.materials[t.materialB].kind == MaterialKind::kFluid,
            "interfacial tension between '" + world.materials[t.materialA].name + "' and '" +
                world.materials[t.materialB].name + "': both must be fluids");
  colourGradient_ =
      &world.particles.fields.addOrGet<Vec3>({field::kColourGradient, "1/m", false, true});
}

Real InterfacialTensionHuAdams2006::maxTimeStep(const World& world) const {
  Real dt = std::numeric_limits<Real>::infinity();
  const Real d = world.particleSpacing();
  for (const auto& t : world.materials.interfacialTensions()) {
    const Real rhoAvg =
        0.5 * (world.materials[t.materialA].restDensity + world.materials[t.materialB].restDensity);
    dt = std::min(dt, std::sqrt(rhoAvg * d * d * d / (2.0 * std::numbers::pi * t.sigma)));
  }
  return dt;
}

void InterfacialTensionHuAdams2006::apply(World& world, const StepContext&) {
  const Index n = static_cast<Index>(world.particles.size());
  const auto& tensions = world.materials.interfacialTensions();
  stress_.resize(n);
  stressed_.resize(n);
  gradient_.resize(n);
  for (std::size_t pairIndex = 0; pairIndex < tensions.size(); ++pairIndex) {
    const InterfacialTension& pair = tensions[pairIndex];
    surfaceStress(world, pair);
    if (pairIndex == 0) *colourGradient_ = gradient_;
    stressDivergence(world, pair);
  }
}

// Phase 1: colour gradient and surface stress of every particle of the pair. Allocates nothing.
void InterfacialTensionHuAdams2006::surfaceStress(const World& world,
                                                  const InterfacialTension& pair) {
  const auto& p = world.particles;
  const Index n = static_cast<Index>(p.size());
  const PairLoop fluid = fluidPairs(world);
  const bool corrected = form_ == SurfaceStressForm::kCorrected;
  const Real dimension = 3.0;
  const bool elastic = world.materials.countOfKind(MaterialKind::kElastic) > 0;
  const Real sigma = pair.sigma;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const int ci = colourOf(p.material[i], pair);
    stressed_[i] = 0;
    if (ci < 0) {
      gradient_[i].setZero();
      continue;
    }
    Vec3 g = Vec3::Zero();
    fluid.forEach(i, [&](Index j, const Vec3& gradW) {
      const int cj = colourOf(p.material[j], pair);
      if (cj < 0 || cj == ci) return;  // (C_j - C_i) = 0 within a phase
      g += (p.mass[j] / p.density[j]) * Real(cj - ci) * gradW;
    });
    // L_i only where gradC is not 0, i.e. on the interface: the bulk costs no extra pass.
    if (corrected && g.squaredNorm() > 0)
      // The colour lives on the fluids; elastic neighbours are a wall to them (phase 2), and
      // next to a wall the correction is the fluid's one-sided moment, not completed by it.
      g = gradientCorrection(fluidGradientMoment(world, i, /*liquidsOnly=*/elastic),
                             kMinFluidCorrectionDeterminant) *
          g;
    const Real norm = g.norm();  // [1/m]
    gradient_[i] = g;
    // Below 1e-6 of the interface's |gradC| ~ 1/h the direction is round-off: no stress.
    if (norm * world.supportRadius() < 1e-6) continue;
    stress_[i] = sigma * (norm / dimension * Mat3::Identity() - g * g.transpose() / norm);
    stressed_[i] = 1;
  }
}

// Phase 2: divergence of the stress; walls mirror the stress. Allocates nothing.
void InterfacialTensionHuAdams2006::stressDivergence(World& world, const InterfacialTension& pair) {
  auto& p = world.particles;
  const Index n = static_cast<Index>(p.size());
  const bool corrected = form_ == SurfaceStressForm::kCorrected;
  const bool elastic = world.materials.countOfKind(MaterialKind::kElastic) > 0;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    if (colourOf(p.material[i], pair) < 0) continue;
    const Real vi = p.mass[i] / p.density[i];
    Vec3 f = Vec3::Zero();               // [N]
    Mat3 correction = Mat3::Identity();  // L_i of the divergence (corrected form)
    if (corrected) {
      if (!addCorrectedPairForce(world, i, vi, correction, f)) continue;
    } else {
      addSymmetricPairForce(world, i, vi, f);
    }
    if (stressed_[i]) addMirroredStressForce(world, i, vi, correction, elastic, f);
    p.a[i] += f / p.mass[i];
  }
}

// Adds particle i's pair sum of the corrected form to f and sets its correction; returns false
// (f untouched) where no stress acts.
bool InterfacialTensionHuAdams2006::addCorrectedPairForce(const World& world, Index i, Real vi,
                                                          Mat3& correction, Vec3& f) const {
  const auto& p = world.particles;
  const NeighborList& nf = world.fluidNeighbors();
  const NeighborList& nw = world.wallNeighbors();
  // Difference form sum_j V_j (Pi_j - Pi_i) L_i gradW_ij: zero for a uniform stress on any
  // particle order (the symmetric sum is not: 2 Pi_i sum_j V_j gradW_ij remains).
  // The correction acts on the kernel gradient (the derivative's index), not on the result.
  // It is computed only where a stress acts (i or a neighbour stressed): elsewhere f = 0.
  bool acted = stressed_[i] != 0;
  for (Index k = nf.offsets[i]; k < nf.offsets[i + 1] && !acted; ++k)
    acted = stressed_[nf.indices[k]] != 0;
  if (!acted) return false;
  const Mat3 fluid = fluidGradientMoment(world, i);
  correction =
      gradientCorrection(nw.count(i) > 0 ? Mat3(fluid + wallGradientMoment(world, i)) : fluid,
                         kMinCorrectionDeterminant);
  const Mat3 zero = Mat3::Zero();
  const Mat3& own = stressed_[i] ? stress_[i] : zero;
  fluidPairs(world).forEach(i, [&](Index j, const Vec3& gradW) {
    if (!stressed_[i] && !stressed_[j]) return;
    const Mat3 difference = (stressed_[j] ? stress_[j] : zero) - own;
    f += vi * (p.mass[j] / p.density[j]) * (difference * (correction * gradW));
  });
  return true;
}

// Adds particle i's pair sum of the symmetric form to f.
void InterfacialTensionHuAdams2006::addSymmetricPairForce(const World& world, Index i, Real vi,
                                                          Vec3& f) const {
  f += symmetricStressSum(world, i, vi, stress_, stressed_, [](Index) { return true; });
}

// Mirror image of the stress across the wall: Pi_b = R Pi_i R with the reflection
// R = I - 2 m m^T about the local wall normal m, so the wall takes only the normal part
// of the interface's pull and the contact line feels its full tangential part
// sigma cos(theta). (An unreflected copy Pi_b = Pi_i passes the tangential part to the
// wall: the contact line then feels only the wall_adhesion force and runs away, as
// measured: 120 deg requested went past 157 deg.)
// Elastic neighbours are a wall to the fluids (the sclera in place of the retina's wall
// particles) and take the mirrored stress too. Left as stress-free neighbours they end
// the stress field at the tissue, and there a non-wetting droplet lifts off (measured on
// walls, docs/methods/interface.md validation 3; on tissue
// tests/sim/interface_contact_angle.cpp).
void InterfacialTensionHuAdams2006::addMirroredStressForce(const World& world, Index i, Real vi,
                                                           const Mat3& correction, bool elastic,
                                                           Vec3& f) const {
  const auto& p = world.particles;
  const NeighborList& nw = world.wallNeighbors();
  const auto& wallVolume = world.walls.volume;
  const auto& wallNormal = world.walls.normal;
  const bool corrected = form_ == SurfaceStressForm::kCorrected;
  Vec3 wallSum = Vec3::Zero(), m = Vec3::Zero();
  wallPairs(world).forEach(i, [&](Index b, const Vec3& gradW) {
    wallSum += wallVolume[b] * gradW;
    m += wallNormal[b] * wallVolume[b];
  });
  Vec3 solidSum = Vec3::Zero();  // sum V_j gradW_ij over elastic j: points into the tissue
  if (elastic)
    fluidPairs(world).forEach(i, [&](Index j, const Vec3& gradW) {
      if (!world.materials.isFluid(p.material[j])) solidSum += (p.mass[j] / p.density[j]) * gradW;
    });
  if (solidSum.squaredNorm() > 0)
    m = m.squaredNorm() > 0 ? Vec3(m.normalized() + solidSum.normalized()) : solidSum;
  if (!(nw.count(i) > 0 || solidSum.squaredNorm() > 0)) return;
  Mat3 mirrored = stress_[i];
  if (m.squaredNorm() > 0) {
    m.normalize();
    const Mat3 reflect = Mat3::Identity() - 2.0 * m * m.transpose();
    mirrored = reflect * stress_[i] * reflect;
  }
  // The elastic neighbours already entered the pair sum above as stress-free (-Pi_i in
  // the difference form, Pi_i in the symmetric one): only their mirrored part is added.
  if (corrected)
    f += vi *
         ((mirrored - stress_[i]) * (correction * wallSum) + mirrored * (correction * solidSum));
  else
    f += vi * ((stress_[i] + mirrored) * wallSum + mirrored * solidSum);
}

}  // namespace sim
