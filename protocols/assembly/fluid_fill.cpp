#include "protocols/assembly/fluid_fill.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "meshing/find_fill_plane.h"
#include "meshing/sample_volume.h"
#include "protocols/assembly/relax_fill.h"
#include "protocols/scenario/scenario_error.h"

namespace protocols {

namespace {

// "42" for 0.42: the fill notes' percentages.
std::string percent(double fraction) {
  return std::to_string(static_cast<int>(std::lround(100.0 * fraction)));
}
// "100.8" for 1.008: a fraction in percent with one decimal.
std::string percentOneDecimal(double fraction) {
  const long v = std::lround(1000.0 * fraction);
  return std::to_string(v / 10) + "." + std::to_string(v % 10);
}

struct PhasePoints {
  std::vector<sim::Vec3> oil, aqueous;
};

// Fill plane under the first posture's gravity; a lighter tamponade floats.
PhasePoints placePhases(const Protocol& p, const ScenarioOptions& options, Scenario& s) {
  FluidPhase& aqueous = s.phases[0];
  FluidPhase& oil = s.phases[1];
  const double d = s.accuracy.particleSpacing;
  const sim::Vec3 down = s.schedule.front().gravity.normalized();
  const sim::Vec3 oilSide = oil.density < aqueous.density ? sim::Vec3(-down) : down;
  const meshing::FillPlane plane =
      meshing::findFillPlane(s.cavity, p.tamponade.fill.value, oilSide);
  meshing::VolumeSamplingOptions vo;
  vo.spacing = d;
  const bool relaxed = options.massRule == MassRule::kRelaxedFill;
  vo.wallGap = s.layeredWalls ? 0.0 : options.wallGapFactor.value_or(relaxed ? 0.65 : 1.2) * d;
  oil.volume = plane.volumeAbove;
  aqueous.volume = plane.volumeBelow;
  PhasePoints points;
  if (options.massRule == MassRule::kTrueMass) {
    meshing::PhaseSamples samples = meshing::sampleFillPhases(s.cavity, plane, vo);
    return {std::move(samples.above), std::move(samples.below)};
  }
  // By count: the round(fill N) lattice points furthest along the fill direction are oil.
  std::vector<sim::Vec3> lattice = meshing::sampleVolume(s.cavity, vo);
  std::vector<std::size_t> order(lattice.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t lhs, std::size_t rhs) {
    return oilSide.dot(lattice[lhs]) > oilSide.dot(lattice[rhs]);
  });
  const auto nOil = static_cast<std::size_t>(
      std::llround(p.tamponade.fill.value * static_cast<double>(lattice.size())));
  for (std::size_t k = 0; k < order.size(); ++k)
    (k < nOil ? points.oil : points.aqueous).push_back(lattice[order[k]]);
  return points;
}

// Particle masses by the mass rule, with the notes of phases left out and of kRestDensity.
void setParticleMasses(const ScenarioOptions& options, Scenario& s) {
  FluidPhase& aqueous = s.phases[0];
  FluidPhase& oil = s.phases[1];
  const double d = s.accuracy.particleSpacing;
  for (FluidPhase* phase : {&aqueous, &oil}) {
    if (phase->count == 0) {
      if (phase->volume > 0.5 * d * d * d)
        s.notes.push_back(phase->material + ": " + std::to_string(phase->volume * 1e9) +
                          " uL is thinner than the particle layer and is left out");
      continue;
    }
    phase->particleMass = options.massRule == MassRule::kTrueMass
                              ? phase->density * phase->volume / static_cast<double>(phase->count)
                              : phase->density * d * d * d;
  }
  if (options.massRule == MassRule::kFillCavity) {
    const double factor = (s.cavityVolume - 0.5 * d * s.cavityArea) /
                          (static_cast<double>(oil.count + aqueous.count) * d * d * d);
    for (FluidPhase* phase : {&aqueous, &oil}) phase->particleMass *= factor;
    s.fillCompression = factor;
  }
  if (options.massRule == MassRule::kRestDensity) {
    const double represented =
        static_cast<double>(oil.count + aqueous.count) * d * d * d / s.cavityVolume;
    s.notes.push_back("the fluid particles stand for " +
                      std::to_string(static_cast<int>(100 * represented + 0.5)) +
                      " % of the cavity volume at rest density (the rest is the wall layer)");
  }
}

// Layered walls: fluid and wall are one lattice, so no shifting pass is needed; the start's
// density is measured.
void measureLayeredStart(Scenario& s) {
  const FluidPhase& aqueous = s.phases[0];
  const FluidPhase& oil = s.phases[1];
  const double d = s.accuracy.particleSpacing;
  const std::vector<double> c = volumeFractions(*s.world);
  double sum = 0.0, most = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const int m = s.world->particles.material[i];
    if (m != aqueous.materialIndex && m != oil.materialIndex) continue;
    sum += c[i], most = std::max(most, c[i]), ++n;
  }
  s.startMeanFraction = sum / static_cast<double>(n);
  s.startMaxFraction = most;
  s.fillCompression = s.startMeanFraction;
  s.heldVolumeRatio = static_cast<double>(n) * d * d * d / s.cavityVolume;
  s.notes.push_back("fluid fill: the lattice points inside the cavity at rest mass rho d^3 hold " +
                    percent(s.heldVolumeRatio) +
                    " % of the cavity, one lattice with the layered "
                    "wall behind them: density at t = 0 is " +
                    percentOneDecimal(s.startMeanFraction) + " % of rest on average, " +
                    percentOneDecimal(s.startMaxFraction) + " % at most");
}

// One Akinci wall layer: the start-up shifting pass spreads the fill (relax_fill.h).
void relaxStart(const ScenarioOptions& options, Scenario& s) {
  const FluidPhase& aqueous = s.phases[0];
  const FluidPhase& oil = s.phases[1];
  const double d = s.accuracy.particleSpacing;
  FillRelaxation relaxation;
  relaxation.passes = options.relaxationPasses;
  relaxation.movable = {aqueous.materialIndex, oil.materialIndex};
  const FillRelaxationResult r = relaxFill(*s.world, relaxation);
  s.startMeanFraction = r.meanAfter;
  s.startMaxFraction = r.maxAfter;
  s.fillCompression = r.meanAfter;
  const double shell = s.cavityVolume - 0.5 * d * s.cavityArea;  // [m^3]
  s.heldVolumeRatio = static_cast<double>(oil.count + aqueous.count) * d * d * d / shell;
  s.notes.push_back(
      "fluid fill: particles at rest mass rho d^3 hold " + percent(s.heldVolumeRatio) +
      " % of the cavity minus the wall's d/2 shell (" +
      percent(static_cast<double>(oil.count + aqueous.count) * d * d * d / s.cavityVolume) +
      " % of the cavity); a start-up shifting pass (" + std::to_string(relaxation.passes) +
      " passes, not simulated time) spreads them: density at t = 0 is " +
      percentOneDecimal(r.meanAfter) + " % of rest on average, " + percentOneDecimal(r.maxAfter) +
      " % at most");
  s.world->updateNeighbors();
}

}  // namespace

void fillFluid(const Protocol& p, const ScenarioOptions& options, Scenario& s) {
  FluidPhase& aqueous = s.phases[0];
  FluidPhase& oil = s.phases[1];
  const double d = s.accuracy.particleSpacing;
  const PhasePoints points = placePhases(p, options, s);
  oil.count = points.oil.size();
  aqueous.count = points.aqueous.size();
  if (oil.count == 0)
    failAt(p.tamponade.fill.where,
           "the fill " + std::to_string(p.tamponade.fill.value) +
               " leaves the tamponade without "
               "particles at spacing " +
               std::to_string(d * 1e3) + " mm",
           "raise the fill or use a finer accuracy preset");
  setParticleMasses(options, s);
  for (const auto& x : points.aqueous)
    s.world->particles.add(x, sim::Vec3::Zero(), aqueous.particleMass, aqueous.materialIndex);
  for (const auto& x : points.oil)
    s.world->particles.add(x, sim::Vec3::Zero(), oil.particleMass, oil.materialIndex);
  if (aqueous.count == 0 || oil.count == 0)
    s.notes.push_back("one fluid only: no oil/aqueous interface");
}

// Exact because the cavity is closed and the fill holds it (no free surface). Not with an elastic
// tissue: its outer face carries no fluid pressure, so it would feel p' instead of p.
void chooseGravityReference(const ScenarioOptions& options, Scenario& s) {
  if (!options.removeHydrostaticBackground) return;
  for (const TissueBody& t : s.tissues)
    if (t.decision.elastic) {
      s.notes.push_back("gravity acts in full (an elastic " + t.name +
                        " must feel the full "
                        "hydrostatic pressure), so slow buoyant motion of the oil may stall "
                        "(docs/methods/interface.md, validation 6)");
      return;
    }
  const FluidPhase& reference = s.phases[0].count > 0 ? s.phases[0] : s.phases[1];
  // The frames' pressures are then p' = p - rho_ref g.x (the reference fluid's hydrostatic part
  // out).
  s.world->gravityReferenceDensity = reference.density;
  char line[256];
  std::snprintf(
      line, sizeof line,
      "gravity acts relative to %s (%.0f kg/m^3): the hydrostatic background is out of "
      "the pressure (exact in the closed, filled cavity); frames' pressures are p - rho g.x",
      reference.material.c_str(), reference.density);
  s.notes.push_back(line);
}

void startFluidFill(const ScenarioOptions& options, Scenario& s) {
  if (s.phases[0].count + s.phases[1].count == 0) return;
  if (s.layeredWalls)
    measureLayeredStart(s);
  else if (options.massRule == MassRule::kRelaxedFill)
    relaxStart(options, s);
}

}  // namespace protocols
