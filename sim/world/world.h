// The World: everything a step reads and writes. Passed explicitly (no singletons).
#pragma once

#include <memory>
#include <optional>

#include "sim/core/material.h"
#include "sim/core/particle_set.h"
#include "sim/core/types.h"
#include "sim/kernels/kernel.h"
#include "sim/neighbors/neighbor_search.h"

namespace sim {

struct WorldParameters {
  Real particleSpacing = 0.0;      // [m] initial lattice spacing d of dynamic particles
  Real supportRadiusFactor = 2.0;  // [1] kernel support radius h = factor * d
  KernelKind kernel = KernelKind::kCubicSpline;
  Vec3 gravity = Vec3(0, -9.81, 0);  // [m/s^2] in the simulation (eye) frame; may change in time
  Box domain;                        // [m] every particle stays inside for the whole run
  Real cflNumber = 0.15;             // [1] dt <= cfl * d / v_max
  // [1] a step whose pressure-corrected velocities move a particle further than this many
  // spacings is redone with a shorter step (Pipeline::step)
  Real maxDisplacement = 0.3;
  Real minTimeStep = 1e-6;  // [s]
  // What a step does when its stages need less than minTimeStep: false takes minTimeStep anyway
  // (the engine's tests bound the step so); true throws SimError, the run stopping as unstable.
  bool stopBelowMinTimeStep = false;
  Real maxTimeStep = 5e-3;  // [s]
  int zSortInterval = 16;   // [steps] how often particle data are re-sorted in Z-order
  // Keep each neighbour pair's kernel value and gradient with the lists (16 bytes per pair in
  // single precision, about 0.4 KiB per particle): the stages then read them instead of
  // evaluating the kernel. false
  // trades that memory for time; results are the same bit for bit (sim/world/pair_loop.h,
  // docs/benchmarks.md).
  bool cachePairKernels = true;

  void validate() const;
};

class World {
 public:
  explicit World(const WorldParameters& parameters);
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Call after all particles and walls are added: validates, bins the walls, computes wall
  // volumes (Akinci et al. 2012) and the first neighbour lists. Throws SimError on bad input.
  void initialize();
  bool initialized() const { return initialized_; }

  // Rebuilds neighbour lists; every zSortInterval calls it first reorders the dynamic particles
  // by Z-order so that neighbours are close in memory.
  void updateNeighbors();

  // Variable support (the VSLSPH solver): from now on the neighbour lists keep a pair when
  // r < max(h, h_i, h_j), h_i = support[i] [m] (a registered, sorted field), on a grid of cells
  // maxSupport wide (sim/neighbors/neighbor_search.h). Rebuilds the grid and the lists; the kernel,
  // its cached values and gradients and the wall volumes keep the fixed support h, so other
  // stages see a superset of their pairs whose extra ones carry W = 0. Call from attach().
  void useVariableSupport(const std::vector<Real>& support, Real maxSupport);
  const std::vector<Real>* variableSupport() const { return variableSupport_; }

  Real restDensityOf(Index i) const { return materials[particles.material[i]].restDensity; }
  // Rest volume V0 of a dynamic particle [m^3] (= mass / rest density).
  Real restVolumeOf(Index i) const { return particles.mass[i] / restDensityOf(i); }

  const WorldParameters& parameters() const { return parameters_; }
  Real particleSpacing() const { return parameters_.particleSpacing; }
  Real supportRadius() const { return kernel.supportRadius(); }

  MaterialTable materials;
  DynamicParticles particles;
  WallParticles walls;
  Kernel kernel;
  Vec3 gravity;  // [m/s^2] current gravity (the runner turns it with posture)
  // [kg/m^3] 0 = off. Otherwise gravity acts on each particle as g (1 - rho_ref / rho_i), rho_i its
  // material's rest density: the exact rewrite -grad p / rho + g = -grad p' / rho + g (1 - rho_ref
  // / rho) with p' = p - rho_ref g.x, which takes the hydrostatic background out of the pressure
  // the solver carries. Why: under a background pressure p the SPH pressure force on an imperfect
  // particle arrangement errs by ~ p epsilon / d, which pins slow buoyant motion
  // (docs/methods/interface.md, validation 6). Exact only for a closed domain filled with fluid (at
  // a free surface p = 0 would become p' = -rho_ref g.x), and walls and tissue then feel p', not p.
  Real gravityReferenceDensity = 0.0;
  Real time = 0.0;  // [s]
  long stepCount = 0;
  Real lastTimeStep = 0;  // [s]

  const NeighborList& fluidNeighbors() const { return search_->dynamicDynamic(); }
  const NeighborList& wallNeighbors() const { return search_->dynamicStatic(); }
  // Kernel gradients gradW(x_i - x_j) aligned with the neighbour lists: entry k belongs to the
  // pair (i, indices[k]). Computed once per neighbour update, they save the iterative solvers a
  // square root and a division per pair and iteration (positions do not change during a solve).
  const std::vector<PairGradient>& fluidGradients() const {
    return search_->dynamicDynamicGradients();
  }
  const std::vector<PairGradient>& wallGradients() const {
    return search_->dynamicStaticGradients();
  }
  // Kernel values W(x_i - x_j), same alignment (density sums; empty if no kernel pass ran).
  const std::vector<PairValue>& fluidKernelValues() const {
    return search_->dynamicDynamicKernelValues();
  }
  const std::vector<PairValue>& wallKernelValues() const {
    return search_->dynamicStaticKernelValues();
  }
  const NeighborSearch& search() const { return *search_; }

 private:
  // The message for a particle outside the domain: which material, when, what it usually means.
  std::string describeEscape(const std::string& fallback) const;
  void rebuildLists();
  void computeWallVolumes();

  WorldParameters parameters_;
  std::unique_ptr<NeighborSearch> search_;
  const std::vector<Real>* variableSupport_ = nullptr;  // [m] per-particle support, or none
  std::vector<Index> permutation_;
  long updatesSinceSort_ = 0;
  bool initialized_ = false;
};

}  // namespace sim
