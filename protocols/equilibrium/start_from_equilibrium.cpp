#include "protocols/equilibrium/start_from_equilibrium.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <vector>

#include <fmt/format.h>

#include "protocols/assembly/assemble_scenario.h"
#include "protocols/equilibrium/posture_equilibrium.h"
#include "protocols/report/report_format.h"

namespace protocols {
namespace {

// The equilibrium's oil share at `x`: trilinear interpolation between voxel centres, each
// weighted by its fluid fraction (voxels outside the cavity have no oil share to give).
double oilShareAt(const sim::equilibrium::EquilibriumSolution& e, const sim::Vec3& x) {
  const auto& g = e.grid;
  const sim::Vec3 local = (x - g.origin) / g.spacing - sim::Vec3::Constant(0.5);
  const int i0 = static_cast<int>(std::floor(local.x()));
  const int j0 = static_cast<int>(std::floor(local.y()));
  const int k0 = static_cast<int>(std::floor(local.z()));
  const sim::Vec3 t = local - sim::Vec3(i0, j0, k0);
  double weighted = 0.0, weights = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int i = i0 + (c & 1), j = j0 + ((c >> 1) & 1), k = k0 + ((c >> 2) & 1);
    if (i < 0 || j < 0 || k < 0 || i >= g.nx || j >= g.ny || k >= g.nz) continue;
    const double w = ((c & 1) ? t.x() : 1 - t.x()) * (((c >> 1) & 1) ? t.y() : 1 - t.y()) *
                     (((c >> 2) & 1) ? t.z() : 1 - t.z());
    const std::size_t v = g.index(i, j, k);
    weighted += w * e.fluidFraction[v] * e.oil[v];
    weights += w * e.fluidFraction[v];
  }
  return weights > 0.0 ? weighted / weights : 0.0;
}

// Fluid particles (aqueous and oil, not tissue) ranked from most to least oil-like.
// `gravity` [m/s^2] is the equilibrium posture's.
std::vector<std::size_t> rankByOilShare(const Scenario& s,
                                        const sim::equilibrium::EquilibriumSolution& e,
                                        const sim::Vec3& gravity) {
  const sim::DynamicParticles& particles = s.world->particles;
  const FluidPhase& aqueous = s.phases[0];
  const FluidPhase& oil = s.phases[1];
  const sim::Vec3 down = gravity.normalized();
  const sim::Vec3 oilSide = oil.density < aqueous.density ? sim::Vec3(-down) : down;
  std::vector<std::size_t> fluid;
  std::vector<double> score(particles.size(), 0.0);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const int m = particles.material[i];
    if (m != aqueous.materialIndex && m != oil.materialIndex) continue;
    fluid.push_back(i);
    score[i] = oilShareAt(e, particles.x[i]);
  }
  std::stable_sort(fluid.begin(), fluid.end(), [&](std::size_t a, std::size_t b) {
    if (score[a] != score[b]) return score[a] > score[b];
    return oilSide.dot(particles.x[a]) > oilSide.dot(particles.x[b]);
  });
  return fluid;
}

// The first `oilCount` ranked positions go to oil particles: every oil particle outside them
// changes place with an aqueous particle inside them. Returns the number of exchanges.
std::size_t exchangePlaces(Scenario& s, const std::vector<std::size_t>& ranked,
                           std::size_t oilCount) {
  sim::DynamicParticles& particles = s.world->particles;
  const int oilMaterial = s.phases[1].materialIndex;
  std::vector<std::size_t> aqueousInOilPlace, oilInAqueousPlace;
  for (std::size_t r = 0; r < ranked.size(); ++r) {
    const bool isOil = particles.material[ranked[r]] == oilMaterial;
    if (r < oilCount && !isOil) aqueousInOilPlace.push_back(ranked[r]);
    if (r >= oilCount && isOil) oilInAqueousPlace.push_back(ranked[r]);
  }
  for (std::size_t k = 0; k < aqueousInOilPlace.size() && k < oilInAqueousPlace.size(); ++k)
    std::swap(particles.x[aqueousInOilPlace[k]], particles.x[oilInAqueousPlace[k]]);
  return std::min(aqueousInOilPlace.size(), oilInAqueousPlace.size());
}

// The note of an applied start: which equilibrium, and what it moved.
std::string startNote(const Scenario& s, std::size_t posture, const EquilibriumStart& start) {
  const std::string moved = fmt::format("{} oil particles changed place with aqueous ones ({} s)",
                                        start.moved, formatNumber(start.seconds, 2));
  if (!s.schedule[posture].equilibrium)  // schedule.start = "equilibrium"
    return fmt::format(
        "fluid start: the {} posture's static equilibrium (schedule.start), not a flat fill "
        "plane: {}",
        s.schedule[posture].label, moved);
  return fmt::format(
      "fluid start: {} is simulated from the {} posture's static equilibrium, not a flat fill "
      "plane: {}",
      s.schedule[posture + 1].label, s.schedule[posture].label, moved);
}

}  // namespace

std::optional<std::size_t> startingEquilibrium(const Protocol& p, const Scenario& s) {
  if (s.phases[0].count == 0 || s.phases[1].count == 0 || isEquilibriumSchedule(s))
    return std::nullopt;
  if (const std::size_t leading = leadingEquilibria(s); leading > 0) return leading - 1;
  if (p.schedule.start.value == StartName::kEquilibrium) return 0;
  return std::nullopt;
}

EquilibriumStart startFromEquilibrium(const Protocol& p, Scenario& s) {
  EquilibriumStart result;
  const std::optional<std::size_t> posture = startingEquilibrium(p, s);
  if (!posture) return result;
  const auto start = std::chrono::steady_clock::now();
  const sim::Vec3 gravity = s.schedule[*posture].gravity;
  const CavityVoxels cavity = voxelizeCavity(s, equilibriumVoxelSpacing(s.accuracy.preset));
  const PostureEquilibrium e = solvePostureEquilibrium(s, cavity, p.tamponade.fill.value, gravity);
  result.moved = exchangePlaces(s, rankByOilShare(s, e.solution, gravity), s.phases[1].count);
  s.world->updateNeighbors();
  result.applied = true;
  result.iterations = e.solution.iterations;
  result.converged = e.solution.converged;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.notes.push_back(startNote(s, *posture, result));
  return result;
}

Scenario assembleStartingScenario(const Protocol& p, const ScenarioOptions& options) {
  Scenario s = assembleScenario(p, options);
  if (const std::optional<std::size_t> posture = startingEquilibrium(p, s);
      options.progress && posture)
    options.progress(fmt::format("placing the fluid at the {} posture's equilibrium",
                                 s.schedule[*posture].label));
  startFromEquilibrium(p, s);
  return s;
}

}  // namespace protocols
