#include "sim/effects/viscosity_weiler2018.h"

#include "sim/effects/viscosity_monaghan2005.h"
#include "sim/world/pair_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace sim {
namespace {

constexpr Real kDimensionFactor =
    2.0 * (3 + 2);                      // [1] 2(d+2), d = 3 (Weiler 2018, after Monaghan 2005)
constexpr Real kRegularisation = 0.01;  // [1] 0.01 h^2 keeps 1/|x_ij|^2 finite

// Harmonic mean of two dynamic viscosities [Pa s] (header comment: stress continuity). Written
// symmetric in its arguments so that the pair coefficient is bitwise equal seen from i and j.
Real pairViscosity(Real mui, Real muj) {
  const Real sum = mui + muj;
  return sum > 0 ? 2.0 * (mui * muj) / sum : 0.0;
}

// s such that c (v . x) / (|x|^2 + eps h^2) gradW = s (gradW . v) gradW, using x = gradW r^2 /
// (x . gradW) (the kernel gradient is parallel to x). Zero where the gradient vanishes.
Real pairScale(Real c, const Vec3& xij, const Vec3& gradWij, Real regularisation) {
  const Real r2 = xij.squaredNorm();
  const Real xg = xij.dot(gradWij);  // = r W'(r) <= 0
  if (xg == 0) return 0;
  return c * r2 / ((r2 + regularisation) * xg);
}

}  // namespace

ViscosityWeiler2018::ViscosityWeiler2018(const ImplicitViscosityParameters& parameters)
    : params_(parameters) {
  require(params_.tolerance > 0 && params_.tolerance < 1,
          "implicit viscosity: CG tolerance must be in (0, 1), got " +
              std::to_string(params_.tolerance));
  require(params_.maxIterations > 0, "implicit viscosity: maxIterations must be > 0");
}

void ViscosityWeiler2018::attach(World& world) {
  viscosityOfMaterial_.clear();
  // Elastic materials count as viscosity 0: the harmonic pair mean is then 0, so their rows are
  // m v = m v* and fluid rows skip them (docs/methods/elasticity.md) at no cost in the solve.
  for (const auto& m : world.materials)
    viscosityOfMaterial_.push_back(isFluid(m.kind) ? m.dynamicViscosity : 0.0);
  // The warm start is state a resumed run needs to reproduce the CG iterates bit for bit, so it
  // is a checkpointed registry field (moved with its particle by the Z-order sort).
  warmStart_ = &world.particles.fields.addOrGet<Vec3>(
      {"implicit_viscosity_acceleration", "m/s^2", true, false});
  wallVelocity_ = world.walls.fields.has(kWallVelocityField)
                      ? &world.walls.fields.get<Vec3>(kWallVelocityField)
                      : nullptr;
  const std::size_t n = world.particles.size();
  for (auto* v : {&velocityStar_, &rhs_, &solution_, &residual_, &search_, &product_, &precond_})
    v->assign(n, Vec3::Zero());
  preconditioner_.assign(n, Mat3::Zero());
  // Size the reduction buffers now, so that apply() allocates nothing.
  reducer_.sum(n, [](std::size_t) { return 0.0; });
  reducer_.sumVec(n, [](std::size_t) { return Vec3(Vec3::Zero()); });
  fluidPair_.reserve(2 * world.fluidNeighbors().totalPairs());
  wallPair_.reserve(2 * world.wallNeighbors().totalPairs());
}

void ViscosityWeiler2018::assemble(const World& world, Real dt) {
  const auto& p = world.particles;
  const NeighborList& nf = world.fluidNeighbors();
  const NeighborList& nw = world.wallNeighbors();
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Real h = world.supportRadius();
  const Real eps = kRegularisation * h * h;
  fluidPair_.resize(nf.totalPairs());
  wallPair_.resize(nw.totalPairs());
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real mui = viscosityOfMaterial_[static_cast<std::size_t>(p.material[i])];
    Mat3 block = p.mass[i] * Mat3::Identity();
    fluid.forEach(i, [&](Index j, const Vec3& gradW, Index k) {
      const Real mu =
          pairViscosity(mui, viscosityOfMaterial_[static_cast<std::size_t>(p.material[j])]);
      const Real c =
          kDimensionFactor * (p.mass[i] * p.mass[j]) * mu / (p.density[i] * p.density[j]);
      const Real s = c == 0 ? 0 : pairScale(c, p.x[i] - p.x[j], gradW, eps);
      fluidPair_[k] = s;
      block -= (dt * s) * gradW * gradW.transpose();
    });
    Vec3 wallForce = Vec3::Zero();  // [N] the part of the wall force set by the wall velocity
    wall.forEach(i, [&](Index b, const Vec3& gradW, Index k) {
      const Real c = params_.wallFriction
                         ? kDimensionFactor * p.mass[i] * world.walls.volume[b] * mui / p.density[i]
                         : 0.0;
      const Real s = c == 0 ? 0 : pairScale(c, p.x[i] - world.walls.x[b], gradW, eps);
      wallPair_[k] = s;
      block -= (dt * s) * gradW * gradW.transpose();
      if (wallVelocity_ != nullptr) wallForce -= s * gradW.dot((*wallVelocity_)[b]) * gradW;
    });
    preconditioner_[i] = block.inverse();
    // Right-hand side b = M v* + dt f_wall(v_b) (the wall velocity is known, so it moves over).
    rhs_[i] = p.mass[i] * velocityStar_[i] + dt * wallForce;
  }
}

Real ViscosityWeiler2018::multiply(const World& world, Real dt, const std::vector<Vec3>& in,
                                   std::vector<Vec3>& out) {
  const auto& p = world.particles;
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Index n = static_cast<Index>(p.size());
  // The pair loop is the cost: a plain static loop so that every thread gets work even when the
  // particle count is below a few reduction blocks; the dot product is a separate cheap pass.
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Vec3 f = Vec3::Zero();  // [N] linear part of the viscous force on i
    fluid.forEach(i, [&](Index j, const Vec3& gradW, Index k) {
      f += (fluidPair_[k] * gradW.dot(in[i] - in[j])) * gradW;
    });
    wall.forEach(i, [&](Index, const Vec3& gradW, Index k) {
      f += (wallPair_[k] * gradW.dot(in[i])) * gradW;
    });
    out[i] = p.mass[i] * in[i] - dt * f;
  }
  return reducer_.sum(p.size(), [&](std::size_t i) { return in[i].dot(out[i]); });
}

void ViscosityWeiler2018::computeForces(const World& world, const std::vector<Vec3>& v,
                                        std::vector<Vec3>& out) const {
  const auto& p = world.particles;
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Index n = static_cast<Index>(p.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Vec3 f = Vec3::Zero();
    fluid.forEach(i, [&](Index j, const Vec3& gradW, Index k) {
      f += (fluidPair_[k] * gradW.dot(v[i] - v[j])) * gradW;
    });
    wall.forEach(i, [&](Index b, const Vec3& gradW, Index k) {
      const Vec3 vb = wallVelocity_ != nullptr ? (*wallVelocity_)[b] : Vec3::Zero();
      f += (wallPair_[k] * gradW.dot(v[i] - vb)) * gradW;
    });
    out[i] = f;
  }
}

void ViscosityWeiler2018::apply(World& world, const StepContext& context) {
  auto& p = world.particles;
  const std::size_t n = p.size();
  if (n == 0) return;
  if (warmStart_ == nullptr || velocityStar_.size() != n)  // message built only on failure
    throw SimError(
        "implicit viscosity: attach() must run before apply() and the particle count "
        "must not change afterwards (" +
        std::to_string(velocityStar_.size()) + " attached, " + std::to_string(n) + " now)");
  const Real dt = context.dt;
  // The solve starts from the step-start velocity v^n = v* - dt a (a: this step's explicit
  // accelerations, gravity among them), and its viscous change is added to v*. Solving from v*
  // instead let the no-slip wall term take up gravity's increment g dt of the particles next to
  // a wall before the pressure solve could: the wall then carried part of the fluid's weight by
  // friction, an O(dt) splitting error that INDSPH's large steps made visible (emmetropic eye,
  // 1000 cSt oil, d = 1.5 mm, dt 1.86 ms: ~4 mm/s of velocity noise and aqueous creeping ~1 d up
  // the wall, retinal coverage 0.83 -> 0.78 in 0.3 s; from v^n: 0.83 held, oil kinetic energy
  // 7e-7 J/kg against 6e-6). A viscous force acts on motion, and g dt is not motion: the
  // pressure solve removes it. (SPlisHSPlasH's Weiler 2018 viscosity likewise solves from the
  // step-start velocity.) The momentum-exact update below is unchanged: v = v* + dt M^-1 f(u).
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) velocityStar_[i] = p.v[i] - dt * p.a[i];
  assemble(world, dt);
  solve(world, dt);
  const auto& mass = p.mass;

  // Momentum-exact update: the pair forces of the CG solution, applied to v* (header comment).
  computeForces(world, solution_, product_);
  auto& warmOut = *warmStart_;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = product_[i] / mass[i];
    p.v[i] += dt * a;  // v* + dt M^-1 f(u)
    warmOut[i] = a;
  }
}

// Preconditioned CG for the velocities of the step (into solution_), from the warm start.
// Allocates nothing.
void ViscosityWeiler2018::solve(const World& world, Real dt) {
  const std::size_t n = world.particles.size();
  const auto& mass = world.particles.mass;
  const auto& warm = *warmStart_;

  // Initial guess: v* plus last step's viscous velocity change at this step's length.
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    solution_[i] = params_.warmStart ? Vec3(velocityStar_[i] + dt * warm[i]) : velocityStar_[i];
  multiply(world, dt, solution_, product_);
  const Vec3 start = reducer_.sumVec(n, [&](std::size_t i) {
    residual_[i] = rhs_[i] - product_[i];
    precond_[i] = preconditioner_[i] * residual_[i];
    search_[i] = precond_[i];
    return Vec3((residual_[i] / mass[i]).squaredNorm(), residual_[i].dot(precond_[i]),
                (rhs_[i] / mass[i]).squaredNorm());
  });
  Real rz = start.y();
  const Real threshold = params_.tolerance * params_.tolerance * start.z();  // [m^2/s^2]
  Real rr = start.x();
  int iterations = 0;
  // Preconditioned conjugate gradients (block Jacobi), fixed-order reductions throughout.
  while (rr > threshold && iterations < params_.maxIterations) {
    const Real pAp = multiply(world, dt, search_, product_);
    if (!(pAp > 0)) break;  // search direction exhausted (exact solution reached)
    const Real alpha = rz / pAp;
    const Vec3 sums = reducer_.sumVec(n, [&](std::size_t i) {
      solution_[i] += alpha * search_[i];
      residual_[i] -= alpha * product_[i];
      precond_[i] = preconditioner_[i] * residual_[i];
      return Vec3((residual_[i] / mass[i]).squaredNorm(), residual_[i].dot(precond_[i]), 0.0);
    });
    ++iterations;
    rr = sums.x();
    const Real beta = sums.y() / rz;
    rz = sums.y();
    if (rr <= threshold) break;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) search_[i] = precond_[i] + beta * search_[i];
  }
  lastIterations_ = iterations;
  lastResidual_ = start.z() > 0 ? std::sqrt(rr / start.z()) : 0.0;
  totalIterations_ += iterations;
  ++solves_;
}

Real advectionTimeStep(const World& world, Real solverLimit) {
  const auto& params = world.parameters();
  const Real d = world.particleSpacing();
  Real dt = std::min(params.maxTimeStep, solverLimit);
  const Real g = world.gravity.norm();
  if (g > 0) dt = std::min(dt, params.cflNumber * std::sqrt(d / g));
  const auto& v = world.particles.v;
  const Real vmax = std::sqrt(
      DeterministicReducer::max(v.size(), [&](std::size_t i) { return v[i].squaredNorm(); }));
  if (vmax > 0) dt = std::min(dt, params.cflNumber * d / vmax);
  return dt;
}

ViscosityTreatment chooseViscosityTreatment(const World& world, Real solverLimit) {
  ViscosityTreatment t;
  Real nuMax = 0;  // [m^2/s]
  for (const auto& m : world.materials) nuMax = std::max(nuMax, m.kinematicViscosity());
  std::ostringstream why;
  if (nuMax <= 0) {
    t.reason = "every material is inviscid";
    return t;
  }
  const Real d = world.particleSpacing();
  t.viscous = true;
  t.explicitLimit = ViscosityMonaghan2005::kStableStepFactor * d * d / nuMax;
  t.advectionStep = advectionTimeStep(world, solverLimit);
  t.implicit = t.explicitLimit < t.advectionStep;
  why.precision(3);
  why << "max nu = " << nuMax << " m^2/s: explicit viscous limit "
      << ViscosityMonaghan2005::kStableStepFactor << " d^2/nu = " << t.explicitLimit << " s ";
  if (t.implicit)
    why << "< CFL step " << t.advectionStep << " s, so explicit viscosity would take "
        << t.advectionStep / t.explicitLimit
        << "x more steps; the implicit solve (Weiler 2018) is unconditionally stable";
  else
    why << ">= CFL step " << t.advectionStep
        << " s, so explicit viscosity costs no extra steps and no linear solve";
  t.reason = why.str();
  return t;
}

}  // namespace sim
