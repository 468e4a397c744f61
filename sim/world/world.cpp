#include "sim/world/world.h"

#include <cmath>
#include <sstream>

namespace sim {

void WorldParameters::validate() const {
  require(std::isfinite(particleSpacing) && particleSpacing > 0.0,
          "particle spacing must be a positive length in metres (got " +
              std::to_string(particleSpacing) + ")");
  require(supportRadiusFactor >= 1.0 && supportRadiusFactor <= 4.0,
          "support radius factor must be in [1, 4] particle spacings (2 is the usual choice)");
  require(gravity.allFinite(), "gravity must be finite");
  require(!domain.isEmpty() && domain.volume() > 0.0, "simulation domain is empty");
  require(cflNumber > 0.0 && cflNumber <= 1.0, "CFL number must be in (0, 1]");
  require(maxDisplacement > 0.0 && maxDisplacement <= 1.0,
          "maximum displacement per step must be in (0, 1] particle spacings");
  require(minTimeStep > 0.0, "minimum time step must be > 0 s");
  require(maxTimeStep >= minTimeStep, "maximum time step must be >= the minimum time step");
  require(zSortInterval >= 1, "Z-order sort interval must be >= 1 step");
}

World::World(const WorldParameters& parameters)
    : kernel(parameters.kernel, parameters.particleSpacing > 0
                                    ? parameters.supportRadiusFactor * parameters.particleSpacing
                                    : 1.0),
      gravity(parameters.gravity),
      parameters_(parameters) {
  parameters_.validate();
}

void World::initialize() {
  parameters_.validate();
  require(particles.size() > 0, "the scene has no dynamic particles");
  for (Index i = 0; i < particles.size(); ++i) {
    const int m = particles.material[i];
    require(m >= 0 && m < materials.size(),
            "particle " + std::to_string(i) + " refers to material " + std::to_string(m) +
                " but only " + std::to_string(materials.size()) + " are defined");
    require(particles.mass[i] > 0.0 && std::isfinite(particles.mass[i]),
            "particle " + std::to_string(i) + " has a non-positive mass");
    require(particles.v[i].allFinite(),
            "particle " + std::to_string(i) + " has a non-finite velocity");
  }
  search_ = std::make_unique<NeighborSearch>(parameters_.domain, supportRadius());
  search_->setStatic(walls.x);  // throws, naming the wall particle, if one lies outside
  computeWallVolumes();
  updatesSinceSort_ = parameters_.zSortInterval;  // sort on the first update
  updateNeighbors();
  initialized_ = true;
}

void World::computeWallVolumes() {
  // Akinci et al. 2012, eq. 4: V_b = 1 / sum_k W_bk over wall neighbours k (including b itself),
  // so that a densely sampled wall does not over-contribute to the fluid density. Only walls whose
  // volume the scene left at 0 get it: a scene that samples walls as a full lattice of several
  // layers knows the exact volume d^3 (Akinci's estimate over-counts there, see
  // docs/methods/solvers.md).
  const NeighborList& ss = search_->staticStatic();
  const Real w0 = kernel.W0();
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < walls.size(); ++b) {
    if (walls.volume[b] > 0) continue;
    Real delta = w0;
    for (const Index* k = ss.begin(static_cast<Index>(b)); k != ss.end(static_cast<Index>(b)); ++k)
      delta += kernel.W(walls.x[b] - walls.x[*k]);
    walls.volume[b] = 1.0 / delta;
  }
}

void World::updateNeighbors() {
  try {
    if (++updatesSinceSort_ >= parameters_.zSortInterval) {
      search_->zOrder(particles.x, permutation_);
      particles.fields.permute(permutation_);
      updatesSinceSort_ = 0;
    }
    rebuildLists();
  } catch (const SimError& e) {
    throw SimError(describeEscape(e.what()));
  }
}

// The lists and, when kept, the per-pair kernel values and gradients, from one pass
// (NeighborSearch::update).
void World::rebuildLists() {
  if (parameters_.cachePairKernels)
    search_->update(particles.x, kernel, variableSupport_);
  else
    search_->update(particles.x, variableSupport_);
}

void World::useVariableSupport(const std::vector<Real>& support, Real maxSupport) {
  require(initialized_, "World::initialize() must run before useVariableSupport()");
  require(maxSupport >= supportRadius(),
          "the largest variable support radius must be at least the kernel's support radius");
  search_ = std::make_unique<NeighborSearch>(parameters_.domain, supportRadius(), maxSupport);
  search_->setStatic(walls.x);
  variableSupport_ = &support;
  try {
    rebuildLists();
  } catch (const SimError& e) {
    throw SimError(describeEscape(e.what()));
  }
}

std::string World::describeEscape(const std::string& fallback) const {
  // The search only knows positions; the user needs to know what left, when, and what it means
  // (a fluid leaking, a tissue sagging, or an instability), so name the material here.
  const Box& box = parameters_.domain;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Vec3& x = particles.x[i];
    if (x.allFinite() && box.contains(x)) continue;
    const Material& m = materials[particles.material[i]];
    std::ostringstream msg;
    msg.precision(4);
    const bool atStart = stepCount == 0;
    msg << m.name << " particle (id " << particles.id[i] << ") ";
    if (atStart)
      msg << "is outside the simulation domain at the start";
    else
      msg << "left the simulation domain at t = " << time << " s (step " << stepCount << ")";
    msg << ": position (" << x.transpose() << ") m, domain [" << box.min().transpose() << "] - ["
        << box.max().transpose() << "] m. ";
    if (atStart)
      msg << "Place every particle inside the domain, or enlarge the domain.";
    else if (!x.allFinite())
      msg << "Its position is not finite: the simulation became unstable (try a smaller time step "
             "or particle spacing).";
    else if (isFluid(m.kind))
      msg << "A fluid leaves the domain only through a wall: look for a hole in the wall or a wall "
             "thinner than the particle spacing, or an instability (velocities far above the "
             "flow's).";
    else
      msg << "An elastic tissue leaves the domain when it deforms further than the domain's "
             "margin: "
             "the tissue is too soft for its load or not held; anchor it or keep it rigid.";
    return msg.str();
  }
  return fallback;
}

}  // namespace sim
