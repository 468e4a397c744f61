#include "sim/world/pipeline.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string_view>

#include "sim/core/error.h"
#include "sim/core/reduction.h"
#include "sim/effects/background_pressure.h"
#include "sim/effects/viscosity_monaghan2005.h"
#include "sim/solid/fixed_particles.h"

namespace sim {
namespace {

Real maxSpeed(const std::vector<Vec3>& v) {  // [m/s]
  return std::sqrt(
      DeterministicReducer::max(v.size(), [&](std::size_t i) { return v[i].squaredNorm(); }));
}

}  // namespace

Pipeline::Pipeline(std::unique_ptr<PressureSolver> solver,
                   std::vector<std::unique_ptr<Effect>> effects,
                   std::vector<StageDecision> decisions)
    : solver_(std::move(solver)), effects_(std::move(effects)), decisions_(std::move(decisions)) {
  require(solver_ != nullptr, "a pipeline needs a pressure solver");
  neighborSlot_ = timers_.slot("neighbors");
  pairKernelSlot_ = timers_.slot("pair_kernels");
  solverBeginSlot_ = timers_.slot(std::string(solver_->name()) + ".begin");
  for (const auto& e : effects_) effectSlots_.push_back(timers_.slot(std::string(e->name())));
  solverSlot_ = timers_.slot(std::string(solver_->name()) + ".solve");
  integrateSlot_ = timers_.slot("integrate");
}

bool Pipeline::hasStage(std::string_view name) const {
  if (solver_->name() == name) return true;
  for (const auto& e : effects_)
    if (e->name() == name) return true;
  return false;
}

void Pipeline::attach(World& world) {
  require(world.initialized(), "World::initialize() must run before Pipeline::attach()");
  solver_->attach(world);
  for (auto& e : effects_) e->attach(world);
  // XSPH directly after the explicit viscosity runs inside its neighbour loop (bit-identical).
  for (std::size_t k = 0; k + 1 < effects_.size(); ++k)
    if (auto* v = dynamic_cast<ViscosityMonaghan2005*>(effects_[k].get()))
      if (auto* x = dynamic_cast<XsphMonaghan1989*>(effects_[k + 1].get())) v->absorbSmoothing(*x);
  auto& fields = world.particles.fields;
  transportShift_ =
      fields.has(field::kTransportShift) ? &fields.get<Vec3>(field::kTransportShift) : nullptr;
  attached_ = true;
}

TimeStepInfo Pipeline::chooseTimeStep(const World& world) const {
  TimeStepInfo info;
  chooseTimeStep(world, info);
  return info;
}

// Writes into `info` in place: step() passes its member, whose strings keep their buffers from
// step to step, so a stage name longer than a string's 15 in-place characters
// ("velocity_smoothing", "implicit_viscosity") costs no allocation per step.
void Pipeline::chooseTimeStep(const World& world, TimeStepInfo& info) const {
  const auto& params = world.parameters();
  const Real d = world.particleSpacing();
  const auto& v = world.particles.v;
  const Real vmax = maxSpeed(v);
  info.dt = params.maxTimeStep;
  info.limitedBy.assign("max");
  info.wanted = 0;
  info.wantedBy.clear();
  auto limit = [&](Real dt, std::string_view by) {
    if (dt < info.dt) {
      info.dt = dt;
      info.limitedBy.assign(by);
    }
  };
  // Advection CFL, plus a body-force bound so a scene starting at rest does not take a step in
  // which gravity alone moves particles by more than cfl * d.
  if (vmax > 0) limit(params.cflNumber * d / vmax, "cfl");
  const Real g = world.gravity.norm();
  if (g > 0) limit(params.cflNumber * std::sqrt(d / g), "cfl");
  limit(solver_->maxTimeStep(world), solver_->name());
  for (const auto& e : effects_) limit(e->maxTimeStep(world), e->name());
  if (info.dt < params.minTimeStep) {
    info.wanted = info.dt;
    info.wantedBy.assign(info.limitedBy);
    info.dt = params.minTimeStep;
    info.limitedBy.assign("min");
  }
}

Real Pipeline::step(World& world) {
  require(attached_, "Pipeline::attach() must run before step()");
  auto& p = world.particles;
  const std::size_t n = p.size();
  {
    // Two stages from one pass: the search proper, and the per-pair kernel gradients and values
    // it computes for the stages (NeighborSearch::pairKernelSeconds()).
    const auto start = std::chrono::steady_clock::now();
    world.updateNeighbors();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double kernels = world.search().pairKernelSeconds();
    timers_.add(neighborSlot_, seconds - kernels);
    timers_.add(pairKernelSlot_, kernels);
  }
  {
    ScopedStageTimer t(timers_, solverBeginSlot_);
    solver_->beginStep(world, StepContext{world.lastTimeStep});
  }
  chooseTimeStep(world, lastStep_);
  requireAboveMinimum(world, lastStep_);
  const Real maxDisplacement = world.parameters().maxDisplacement * world.particleSpacing();
  velocityAtStart_ = p.v;
  int attempt = 0;
  Real previousDisplacement = 0;  // [m] the largest displacement of the previous attempt
  for (;; ++attempt) {
    StepContext context{lastStep_.dt};
    advanceVelocities(world, context);
    // The CFL bound is set from the velocities at the start of the step, but the pressure solve
    // can create larger ones (an impact, a strongly compressed corner). A step whose corrected
    // velocities would move a particle further than maxDisplacement leaves the range where the
    // solver's linearised density prediction holds, and such errors grow from step to step. So
    // it is rejected and redone with a shorter step (at most 3 times, never below the minimum).
    const Real vmax = maxSpeed(p.v);
    const Real displacement = vmax * lastStep_.dt;  // [m]
    if (displacement <= maxDisplacement || attempt == 3 ||
        lastStep_.dt <= world.parameters().minTimeStep)
      break;
    // A shorter step shrinks what the step's forces move a particle, not what the pressure solve
    // moves it to correct its density: that correction is the same distance at any dt, at a
    // velocity of distance / dt. Retrying it would only turn it into kinetic energy (down to the
    // minimum step and hundreds of m/s, docs/methods/interface.md "Near-neutral buoyancy"). So a
    // retry that did not shrink the displacement by a quarter is undone: the previous, longer step
    // is redone and kept.
    if (attempt > 0 && displacement > 0.75 * previousDisplacement) {
      p.v = velocityAtStart_;
      lastStep_ = previousStep_;
      advanceVelocities(world, StepContext{lastStep_.dt});
      break;
    }
    previousDisplacement = displacement;
    previousStep_ = lastStep_;
    p.v = velocityAtStart_;
    const Real shorter = 0.5 * maxDisplacement / vmax;  // [s]
    if (shorter < world.parameters().minTimeStep)
      requireAboveMinimum(world, {world.parameters().minTimeStep, "min", shorter, "rejected"});
    lastStep_.dt = std::max(shorter, world.parameters().minTimeStep);
    lastStep_.limitedBy.assign("rejected");
    lastStep_.wanted = 0;
    lastStep_.wantedBy.clear();
  }
  rejectedSteps_ += attempt;
  const Real dt = lastStep_.dt;
  {
    ScopedStageTimer t(timers_, integrateSlot_);
    if (transportShift_ != nullptr) {
      // Transport-velocity correction of the background_pressure stage: advected with v + dv.
      const std::vector<Vec3>& dv = *transportShift_;
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) p.x[i] += dt * (p.v[i] + dv[i]);
    } else {
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) p.x[i] += dt * p.v[i];
    }
  }
  world.time += dt;
  world.lastTimeStep = dt;
  ++world.stepCount;
  return dt;
}

void Pipeline::requireAboveMinimum(const World& world, const TimeStepInfo& step) const {
  if (!world.parameters().stopBelowMinTimeStep || step.limitedBy != "min") return;
  std::ostringstream what;
  what.precision(3);
  what << "the run stopped as unstable at t = " << world.time << " s: the " << step.wantedBy
       << " limit needs a time step of " << step.wanted << " s, below the minimum time step "
       << world.parameters().minTimeStep << " s";
  throw SimError(what.str());
}

void Pipeline::advanceVelocities(World& world, const StepContext& context) {
  auto& p = world.particles;
  const std::size_t n = p.size();
  const Real dt = context.dt;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) p.a[i].setZero();
  for (std::size_t k = 0; k < effects_.size(); ++k) {
    if (effects_[k]->kind() != Effect::Kind::kExplicit) continue;
    ScopedStageTimer t(timers_, effectSlots_[k]);
    effects_[k]->apply(world, context);
  }
  {
    ScopedStageTimer t(timers_, integrateSlot_);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) p.v[i] += dt * p.a[i];
  }
  for (std::size_t k = 0; k < effects_.size(); ++k) {
    if (effects_[k]->kind() != Effect::Kind::kImplicit) continue;
    ScopedStageTimer t(timers_, effectSlots_[k]);
    effects_[k]->apply(world, context);
  }
  ScopedStageTimer t(timers_, solverSlot_);
  solver_->correctVelocities(world, context);
  constrainFixed(world);
}

// The constrain step: anchored particles (sim/solid/fixed_particles.h) keep velocity 0 whatever
// the pressure solver gave them. INDSPH holds them at v = 0 through its solves (its prediction then
// matches what this step keeps); the other solvers do not know anchors, so there a fixed particle
// takes part in the pressure solve as a dynamic one and is reset here; its neighbours' remaining
// compression is corrected in the next step. Costs nothing in a scene where no particle
// was ever flagged (the field does not exist), one pass over the flags otherwise.
void Pipeline::constrainFixed(World& world) { zeroFixedVelocities(world.particles); }

std::string Pipeline::describe() const {
  std::ostringstream out;
  out << "pipeline (in execution order):\n";
  out << "  1. neighbors            cell grid + Z-order, CSR lists\n";
  out << "  2. " << solver_->name() << ".begin         densities and solver factors\n";
  int k = 3;
  for (const auto& e : effects_)
    if (e->kind() == Effect::Kind::kExplicit) out << "  " << k++ << ". " << e->name() << "\n";
  out << "  " << k++ << ". integrate            v* = v + dt a\n";
  for (const auto& e : effects_)
    if (e->kind() == Effect::Kind::kImplicit) out << "  " << k++ << ". " << e->name() << "\n";
  out << "  " << k++ << ". " << solver_->name() << ".solve         pressure correction\n";
  out << "  " << k++ << ". constrain            fixed (anchored) particles keep v = 0\n";
  out << "  " << k++ << ". integrate            "
      << (hasStage("background_pressure") ? "x += dt (v + dv), dv the transport correction"
                                          : "x += dt v")
      << "\n";
  out << "stage decisions:\n";
  for (const auto& d : decisions_)
    out << "  " << (d.active ? "[on]  " : "[off] ") << d.name << (d.forced ? " (forced)" : "")
        << ": " << d.reason << "\n";
  return out.str();
}

}  // namespace sim
