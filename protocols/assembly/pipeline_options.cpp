#include "protocols/assembly/pipeline_options.h"

#include <algorithm>
#include <cmath>

#include "protocols/format/edit_distance.h"
#include "protocols/format/protocol_error.h"
#include "protocols/format/stage_names.h"
#include "protocols/scenario/scenario_error.h"
#include "protocols/tissue/tissue_measures.h"

namespace protocols {

namespace {

// The solver by name. A protocol that names no solver gets the format's default, INDSPH (the
// paper's method). It needs the fill at rest density (MassRule::kRelaxedFill); with the older,
// compressed fill rules only WCSPH starts the scene, so they fall back to it with a note.
void chooseSolver(const Protocol& p, const ScenarioOptions& options, Scenario& s) {
  s.pipelineOptions.solver = p.solver.value;
  bool known = false;
  for (const auto& entry : sim::solverRegistry())
    known = known || entry.name == s.pipelineOptions.solver;
  if (!p.solver.where.isInFile() && options.massRule != MassRule::kRelaxedFill) {
    s.notes.push_back("no solver chosen: using 'wcsph' (the format's default '" +
                      s.pipelineOptions.solver +
                      "' needs the fill at rest density, which this mass rule does not give)");
    s.pipelineOptions.solver = "wcsph";
    known = true;
  }
  if (!known) {
    std::string names;
    for (const auto& entry : sim::solverRegistry())
      names += (names.empty() ? "" : ", ") + entry.name;
    failAt(p.solver.where, "solver '" + s.pipelineOptions.solver + "' is not in this build",
           "use one of: " + names);
  }
}

sim::SurfaceStressForm surfaceStressOf(SurfaceStressName name) {
  switch (name) {
    case SurfaceStressName::kCorrected: return sim::SurfaceStressForm::kCorrected;
    case SurfaceStressName::kSymmetric: return sim::SurfaceStressForm::kSymmetric;
    case SurfaceStressName::kAuto: break;
  }
  return sim::SurfaceStressForm::kAuto;
}

// The solvers' parameters in the eye's closed cavity.
void setSolverParameters(const Protocol& p, Scenario& s) {
  sim::PipelineOptions& o = s.pipelineOptions;
  // The cavity is filled with oil and aqueous: no free surface (background_pressure's rule).
  o.closedDomain = sim::StageOverride::kOn;
  o.surfaceStress = surfaceStressOf(p.accuracy.surfaceStress.value);
  // accuracy.solver_tolerance is the mean relative density error every implicit pressure solve
  // stops at (each within its own iteration cap); the explicit solvers have no solve to stop.
  for (const auto& entry : sim::solverRegistry())
    if (entry.iterative()) entry.setTolerance(o, s.accuracy.solverTolerance);
  // INDSPH's Jacobi relaxation. The engine's 0.5 (IISPH's choice) under-relaxes the eye's closed,
  // layered cavity: on tiny.toml (docs/methods/solvers.md) it took 30.8 iterations per step
  // at 0.1 % and stalled at 0.022 % when asked for 0.01 % (every step at the 100-iteration cap);
  // 0.8 takes 18.9 and reaches 0.0102 % (2 % of steps at the cap) in the same 603 steps. 0.9 and
  // 1.0 iterate less still, but 0.9 needed 4 % more steps at 0.01 % and a full warm start (1.0)
  // blew up: 0.8 keeps a margin. Tested: tests/protocols/test_solver_tolerance.cpp.
  o.indsph.relaxation = kEyeIndsphRelaxation;
  // WCSPH: c = 10 x the free-fall speed over the cavity, sqrt(2 g L), bounds density errors near
  // 1 % (Becker & Teschner 2007, sec. 4); flows in the eye are far slower than free fall.
  Eigen::AlignedBox3d bounds;
  for (const auto& v : s.cavity.vertices) bounds.extend(v);
  const double extent = (bounds.max() - bounds.min()).maxCoeff();  // [m]
  o.wcsph.speedOfSound = 10.0 * std::sqrt(2.0 * p.schedule.gravity.value * extent);
}

// [effects] forced on or off (the parser accepts only the registry's forceable effects).
void forceEffects(const Protocol& p, Scenario& s) {
  const std::span<const std::string_view> names = effectSwitchNames();
  for (std::size_t k = 0; k < names.size() && k < p.effects.settings.size(); ++k) {
    const Located<EffectSetting>& setting = p.effects.settings[k];
    if (setting.value == EffectSetting::kAuto) continue;
    s.pipelineOptions.forced[std::string(names[k])] =
        setting.value == EffectSetting::kOn ? sim::StageOverride::kOn : sim::StageOverride::kOff;
  }
}

}  // namespace

bool isImplicitSolver(const std::string& solver) {
  for (const auto& entry : sim::solverRegistry())
    if (entry.name == solver) return entry.iterative();
  return false;
}

void choosePipelineOptions(const Protocol& p, const ScenarioOptions& options, Scenario& s) {
  chooseSolver(p, options, s);
  setSolverParameters(p, s);
  forceEffects(p, s);
}

void resolveOutputFields(const Protocol& p, Scenario& s) {
  sim::Pipeline probe = sim::assemblePipeline(*s.world, s.pipelineOptions);
  probe.attach(*s.world);
  std::vector<std::string> names;
  for (const auto& field : s.world->particles.fields) names.push_back(field->info().name);
  const std::vector<std::string_view> candidates(names.begin(), names.end());
  std::vector<Diagnostic> problems;
  for (const Located<std::string>& f : p.outputs.fields) {
    if (std::find(names.begin(), names.end(), f.value) != names.end()) continue;
    const std::string hint = didYouMean(f.value, candidates);
    problems.push_back({f.where,
                        "outputs.fields: '" + f.value + "' is not a particle field of this scene",
                        (hint.empty() ? std::string() : hint + " ") +
                            "fields here: " + joinNames(candidates, true)});
  }
  if (!problems.empty()) throw ProtocolError(std::move(problems));
  for (const char* always : {sim::field::kPosition, sim::field::kMaterial})
    s.outputFields.push_back(always);
  if (s.retinaSamples.moves() || s.world->particles.fields.has(kTissueDisplacementField))
    for (const char* tissue : {sim::field::kId, kTissueDisplacementField})
      s.outputFields.push_back(tissue);
  for (const Located<std::string>& f : p.outputs.fields)
    if (std::find(s.outputFields.begin(), s.outputFields.end(), f.value) == s.outputFields.end())
      s.outputFields.push_back(f.value);
}

}  // namespace protocols
