#include "sim/fluid/indsph_wang2023.h"

#include <algorithm>

#include "sim/boundary/wall_layers.h"
#include "sim/fluid/density.h"
#include "sim/solid/fixed_particles.h"
#include "sim/world/pair_loop.h"

namespace sim {

void computeNumberDensities(const World& world, std::vector<Real>& delta) {
  kernelSums(
      world, delta, [](Index) { return Real(1); },
      [&](Index i, Real fluid, Real wall) { return fluid + wall / world.restVolumeOf(i); });
}

IndsphWang2023::IndsphWang2023(const IndsphParameters& parameters) : params_(parameters) {
  require(params_.tolerance > 0, "INDSPH tolerance eta must be > 0");
  require(params_.maxIterations >= params_.minIterations && params_.minIterations >= 1,
          "INDSPH needs 1 <= minIterations <= maxIterations");
  require(params_.relaxation > 0 && params_.relaxation <= 1, "INDSPH relaxation must be in (0, 1]");
}

void IndsphWang2023::attach(World& world) {
  auto& f = world.particles.fields;
  numberDensity_ = &f.addOrGet<Real>({"number_density", "1/m^3", false, true});
  pressure_ = &f.addOrGet<Real>({"pressure", "Pa", false, true});
  kappa_ = &f.addOrGet<Real>({"indsph_kappa", "Pa m^3", true, false});
  staticWalls_ = hasLayeredWalls(world.walls);
  if (!staticWalls_) return;
  auto& wf = world.walls.fields;
  wallKappa_ = &wf.addOrGet<Real>({"indsph_wall_kappa", "Pa m^3", true, false});
  wallPressure_ = &wf.addOrGet<Real>({"wall_pressure", "Pa", false, true});
  // The wall-wall part of delta_b never changes (walls do not move): computed once.
  const auto& walls = world.walls;
  const NeighborList& ss = world.search().staticStatic();
  const Index nb = static_cast<Index>(walls.size());
  wallStaticDensity_.assign(nb, 0.0);
  const Real w0 = world.kernel.W0();
#pragma omp parallel for schedule(static)
  for (Index b = 0; b < nb; ++b) {
    Real sum = walls.volume[b] * w0;
    for (const Index* c = ss.begin(b); c != ss.end(b); ++c)
      sum += walls.volume[*c] * world.kernel.W(walls.x[b] - walls.x[*c]);
    wallStaticDensity_[b] = sum / walls.volume[b];
  }
  wallDensity_.assign(nb, 0.0);
  wallDiagonal_.assign(nb, 0.0);
  wallPredicted_.assign(nb, 0.0);
  wallIncrement_.assign(nb, 0.0);
}

void IndsphWang2023::prepareStaticWalls(const World& world) {
  const auto& walls = world.walls;
  const auto& p = world.particles;
  const NeighborList& nw = world.wallNeighbors();
  const PairLoop wall = wallPairs(world);
  const Index nb = static_cast<Index>(walls.size());
  const Index n = static_cast<Index>(p.size());
  // Transpose of the dynamic -> wall lists, filled in dynamic-index order (deterministic).
  auto& t = wallPairs_;
  t.offsets.assign(nb + 1, 0);
  for (Index k = 0; k < static_cast<Index>(nw.indices.size()); ++k) ++t.offsets[nw.indices[k] + 1];
  for (Index b = 0; b < nb; ++b) t.offsets[b + 1] += t.offsets[b];
  t.dynamic.resize(nw.indices.size());
  t.pair.resize(nw.indices.size());
  std::vector<Index>& cursor = t.walls;  // reused as the fill cursor, then as the active list
  cursor.assign(t.offsets.begin(), t.offsets.end() - 1);
  for (Index i = 0; i < n; ++i)
    for (Index k = nw.offsets[i]; k < nw.offsets[i + 1]; ++k) {
      const Index slot = cursor[nw.indices[k]]++;
      t.dynamic[slot] = i;
      t.pair[slot] = k;
    }
  t.walls.clear();
#pragma omp parallel for schedule(static)
  for (Index b = 0; b < nb; ++b) {
    Real delta = 0, diagonal = 0;
    for (Index s = t.offsets[b]; s < t.offsets[b + 1]; ++s) {
      const Index j = t.dynamic[s];
      const Real c = world.restVolumeOf(j) / walls.volume[b];  // V0_j / V_b
      delta += c * world.kernel.W(p.x[j] - walls.x[b]);
      diagonal += c * c * wall.gradient(t.pair[s], j, b).squaredNorm() / p.mass[j];
    }
    wallDensity_[b] = wallStaticDensity_[b] + delta;
    // Small-diagonal guard (IndsphParameters::minWallDynamicFraction): not an unknown.
    wallDiagonal_[b] = delta >= params_.minWallDynamicFraction * wallDensity_[b] ? diagonal : 0.0;
  }
  for (Index b = 0; b < nb; ++b)
    if (wallDiagonal_[b] > 0) t.walls.push_back(b);
}

Real IndsphWang2023::predictWallNumberDensity(const World& world, Real dt) {
  const auto& walls = world.walls;
  const auto& p = world.particles;
  const PairLoop wall = wallPairs(world);
  const auto& t = wallPairs_;
  const Index active = static_cast<Index>(t.walls.size());
#pragma omp parallel for schedule(static)
  for (Index a = 0; a < active; ++a) {
    const Index b = t.walls[a];
    Real rate = 0;  // eq. 14 with v_b = 0: sum_j (V0_j/V_b) (0 - v_j).gradW_bj, gradW_bj = -gradB
    for (Index s = t.offsets[b]; s < t.offsets[b + 1]; ++s) {
      const Index j = t.dynamic[s];
      rate += world.restVolumeOf(j) * p.v[j].dot(wall.gradient(t.pair[s], j, b));
    }
    wallPredicted_[b] =
        std::max(wallDensity_[b] + dt * rate / walls.volume[b], 1.0 / walls.volume[b]);
  }
  return reducer_.sum(t.walls.size(), [&](std::size_t a) {
    const Index b = t.walls[a];
    return wallPredicted_[b] * walls.volume[b] - 1.0;
  });
}

void IndsphWang2023::beginStep(World& world, const StepContext& context) {
  auto& p = world.particles;
  const auto& walls = world.walls;
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const Index n = static_cast<Index>(p.size());
  computeNumberDensities(world, *numberDensity_);
  // Effects (viscosity, XSPH) read p.density: give them the adapted density m delta (eq. 7),
  // consistent with the volumes 1/delta of the number-density discretisation (eq. 8).
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) p.density[i] = p.mass[i] * (*numberDensity_)[i];
  diagonal_.resize(n);
  predicted_.resize(n);
  increment_.resize(n);
  wallGradient_.resize(n);
  warmStart_ = *kappa_;  // a rejected attempt must restart from the accepted step
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Vec3 g = Vec3::Zero();
    Real neighbours = 0;
    fluid.forEach(i, [&](Index j, const Vec3& gradW) {
      g += gradW;
      neighbours += gradW.squaredNorm() / p.mass[j];
    });
    Vec3 gw = Vec3::Zero();
    wall.forEach(i, [&](Index b, const Vec3& gradW) { gw += walls.volume[b] * gradW; });
    wallGradient_[i] = gw / world.restVolumeOf(i);
    g += wallGradient_[i];
    diagonal_[i] = g.squaredNorm() / p.mass[i] + neighbours;
  }
  if (staticWalls_) {
    prepareStaticWalls(world);
    wallWarmStart_ = *wallKappa_;
  }
  stats_.divergenceIterations = 0;
  if (params_.divergenceSolve && context.dt > 0) solveDivergence(world, context.dt);
}

Real IndsphWang2023::numberDensityRate(const World& world, Index i) const {
  const auto& p = world.particles;
  Real rate = 0;  // eq. 14
  fluidPairs(world).forEach(
      i, [&](Index j, const Vec3& gradW) { rate += (p.v[i] - p.v[j]).dot(gradW); });
  return rate + p.v[i].dot(wallGradient_[i]);
}

// Divergence-free pass in number-density form (the DFSPH divergence solve, Bender & Koschier 2017
// Algorithm 2, written with eqs. 14 and 17): find kappa^v so that D(delta)/Dt = 0 for the current
// velocities. From eq. 17 a stiffness kappa acting for dt changes the rate by
// -dt kappa/delta_i * diagonal_i, so kappa^v_i = delta_i rate_i / (dt diagonal_i). Only
// compressing particles are corrected (a free surface may expand).
void IndsphWang2023::solveDivergence(World& world, Real dt) {
  // Anchors hold v = 0 through the solve: v* may carry gravity or the elastic update, which the
  // pipeline's constrain step discards anyway.
  zeroFixedVelocities(world.particles);
  const Index n = static_cast<Index>(world.particles.size());
  const auto& delta = *numberDensity_;
  auto computeRates = [&] {
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
      const bool full = world.fluidNeighbors().end(i) - world.fluidNeighbors().begin(i) >=
                        params_.minNeighborsForDivergence;
      const Real rate = numberDensityRate(world, i);
      predicted_[i] = !full ? 0.0 : (twoSided(world, i) ? rate : std::max(rate, Real(0)));
    }
    return reducer_.sum(n,
                        [&](std::size_t i) {
                          return std::abs(predicted_[i]) *
                                 world.restVolumeOf(static_cast<Index>(i));
                        }) *
           dt / n;
  };
  Real error = computeRates();
  int iteration = 0;
  while ((iteration < 1 || error > params_.divergenceTolerance) &&
         iteration < params_.maxIterations) {
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i)
      increment_[i] = diagonal_[i] > 0
                          ? params_.relaxation * delta[i] * predicted_[i] / (dt * diagonal_[i])
                          : 0.0;
    applyPressureVelocity(world, increment_, dt);
    error = computeRates();
    ++iteration;
  }
  stats_.divergenceIterations = iteration;
}

Real IndsphWang2023::predictNumberDensity(World& world, Real dt) {
  const auto& delta = *numberDensity_;
  const Index n = static_cast<Index>(world.particles.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real delta0 = 1.0 / world.restVolumeOf(i);
    // Eq. 15 written with the continuity equation (14); only compression is corrected so that a
    // free surface may expand (as in DFSPH).
    const Real unclamped = delta[i] + dt * numberDensityRate(world, i);
    predicted_[i] = twoSided(world, i) ? unclamped : std::max(unclamped, delta0);
  }
  if (params_.correctBulkExpansion)
    return reducer_.sum(n, [&](std::size_t i) {
      return std::abs(predicted_[i] * world.restVolumeOf(static_cast<Index>(i)) - 1.0);
    }) / n;
  return reducer_.sum(n, [&](std::size_t i) {
    return predicted_[i] * world.restVolumeOf(static_cast<Index>(i)) - 1.0;
  }) / n;
}

void IndsphWang2023::applyPressureVelocity(World& world, const std::vector<Real>& kappa, Real dt,
                                           const std::vector<Real>* wallKappa) {
  auto& p = world.particles;
  const auto& walls = world.walls;
  const PairLoop fluid = fluidPairs(world), wall = wallPairs(world);
  const auto& delta = *numberDensity_;
  const Index n = static_cast<Index>(p.size());
  // Anchored particles (sim/solid/fixed_particles.h) do not move: the pipeline resets their
  // velocity after the solve, so a solve that moved them would predict the neighbours' number
  // density for a position the anchor never takes (a fixed lattice facing the fluid then lets it
  // in). They keep their own stiffness, acting on their neighbours as a static wall
  // particle's does (eq. 21).
  const std::vector<std::int32_t>* fixed =
      p.fields.has(field::kFixed) ? &p.fields.get<std::int32_t>(field::kFixed) : nullptr;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    if (fixed && (*fixed)[i] != 0) continue;
    const Real ki = kappa[i] / delta[i];
    Vec3 force = Vec3::Zero();  // eq. 19 without the common factor -1
    fluid.forEach(i,
                  [&](Index j, const Vec3& gradW) { force += (ki + kappa[j] / delta[j]) * gradW; });
    // The fluid particle's own stiffness acts on its wall neighbours through its own number
    // density (eq. 19's first term runs over all neighbours, static ones included). With layered
    // walls the wall particles' own stiffnesses kappa_b add the second term (eq. 19 with j = b):
    // the wall pushes back with the pressure its own compression demands instead of a pressure
    // copied ("mirrored") from the fluid particle, which is what makes a lattice wall impermeable.
    force += ki * wallGradient_[i];
    if (wallKappa) {
      const Real v0 = world.restVolumeOf(i);
      Vec3 g = Vec3::Zero();
      wall.forEach(i, [&](Index b, const Vec3& gradW) {
        if ((*wallKappa)[b] != 0.0)
          g += ((*wallKappa)[b] / (wallDensity_[b] * walls.volume[b])) * gradW;
      });
      force += v0 * g;
    }
    p.v[i] -= (dt / p.mass[i]) * force;  // eq. 20: the advection velocity is incremented
  }
}

void IndsphWang2023::correctVelocities(World& world, const StepContext& context) {
  zeroFixedVelocities(world.particles);
  const Index n = static_cast<Index>(world.particles.size());
  const Real dt = context.dt;
  const Index active = staticWalls_ ? static_cast<Index>(wallPairs_.walls.size()) : 0;
  std::vector<Real>* wallStep = staticWalls_ ? &wallIncrement_ : nullptr;
  // Mean compression over every unknown: fluid particles and active static wall particles.
  auto predictAll = [&] {
    const Real fluid = predictNumberDensity(world, dt);
    if (!staticWalls_) return fluid;  // single-layer walls: unchanged (bit-identical) path
    return (fluid * n + predictWallNumberDensity(world, dt)) / (n + active);
  };

  warmStartStiffness(world, dt);
  Real error = predictAll();
  int iteration = 0;
  while ((iteration < params_.minIterations || error > params_.tolerance) &&
         iteration < params_.maxIterations) {
    relaxStiffness(world, dt);
    applyPressureVelocity(world, increment_, dt, wallStep);
    error = predictAll();
    ++iteration;
  }
  stats_.densityIterations = iteration;
  stats_.densityIterationLimit = params_.maxIterations;
  stats_.averageCompression = error;
  stats_.maxCompression = DeterministicReducer::max(predicted_.size(), [&](std::size_t i) {
    return predicted_[i] * world.restVolumeOf(static_cast<Index>(i)) - 1.0;
  });
  storePressure(world);
}

// The first increments: the warm start where a particle is compressed (or corrected both ways),
// applied to the velocities. Allocates nothing.
void IndsphWang2023::warmStartStiffness(World& world, Real dt) {
  const Index n = static_cast<Index>(world.particles.size());
  auto& kappa = *kappa_;
  const auto& walls = world.walls;
  const Index active = staticWalls_ ? static_cast<Index>(wallPairs_.walls.size()) : 0;
  std::vector<Real>* wallStep = staticWalls_ ? &wallIncrement_ : nullptr;
  predictNumberDensity(world, dt);
  if (staticWalls_) predictWallNumberDensity(world, dt);
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    increment_[i] = predicted_[i] * world.restVolumeOf(i) > 1.0 || twoSided(world, i)
                        ? params_.warmStartFactor * warmStart_[i]
                        : 0.0;
    kappa[i] = increment_[i];
  }
  if (staticWalls_) {
    std::fill(wallKappa_->begin(), wallKappa_->end(), 0.0);
    std::fill(wallIncrement_.begin(), wallIncrement_.end(), 0.0);
#pragma omp parallel for schedule(static)
    for (Index a = 0; a < active; ++a) {
      const Index b = wallPairs_.walls[a];
      wallIncrement_[b] = wallPredicted_[b] * walls.volume[b] > 1.0
                              ? params_.warmStartFactor * wallWarmStart_[b]
                              : 0.0;
      (*wallKappa_)[b] = wallIncrement_[b];
    }
  }
  if (params_.warmStartFactor > 0) applyPressureVelocity(world, increment_, dt, wallStep);
}

// One relaxed Jacobi step of the stiffnesses (fluid, then active static walls). Allocates nothing.
void IndsphWang2023::relaxStiffness(const World& world, Real dt) {
  const Index n = static_cast<Index>(world.particles.size());
  auto& kappa = *kappa_;
  const auto& delta = *numberDensity_;
  const auto& walls = world.walls;
  const Index active = staticWalls_ ? static_cast<Index>(wallPairs_.walls.size()) : 0;
  const Real invDt2 = 1.0 / (dt * dt);
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real delta0 = 1.0 / world.restVolumeOf(i);
    // Eq. 18 with dt^2 (the paper's dt is a typesetting slip: the pressure acts for dt on a
    // velocity that acts for dt on the number density, eq. 17).
    increment_[i] = diagonal_[i] > 0 ? params_.relaxation * delta[i] * (predicted_[i] - delta0) *
                                           invDt2 / diagonal_[i]
                                     : 0.0;
    kappa[i] += increment_[i];
  }
  if (staticWalls_) {
#pragma omp parallel for schedule(static)
    for (Index a = 0; a < active; ++a) {
      const Index b = wallPairs_.walls[a];
      // Eq. 21: only the dynamic neighbours move, so the diagonal is d_j^{p_b} alone.
      wallIncrement_[b] = wallDiagonal_[b] > 0 ? params_.relaxation * wallDensity_[b] *
                                                     (wallPredicted_[b] - 1.0 / walls.volume[b]) *
                                                     invDt2 / wallDiagonal_[b]
                                               : 0.0;
      (*wallKappa_)[b] += wallIncrement_[b];
    }
  }
}

// p_i = kappa_i delta_i: eq. 19 is the symmetric SPH pressure force -sum (p_i/delta_i^2 +
// p_j/delta_j^2) gradW_ij written with kappa = p/delta. Allocates nothing.
void IndsphWang2023::storePressure(const World& world) {
  const Index n = static_cast<Index>(world.particles.size());
  const auto& kappa = *kappa_;
  const auto& delta = *numberDensity_;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) (*pressure_)[i] = kappa[i] * delta[i];
  if (staticWalls_) {
    const Index nb = static_cast<Index>(world.walls.size());
#pragma omp parallel for schedule(static)
    for (Index b = 0; b < nb; ++b) (*wallPressure_)[b] = (*wallKappa_)[b] * wallDensity_[b];
  }
}

}  // namespace sim
