// The registration lists of pressure solvers and effects (docs/developer-guide.md code rule 3: one
// explicit list per kind of plug-in, no self-registering statics) and the assembly of a Pipeline
// from a scene.
//
// Each effect entry has a name, a one-line description, a rule saying whether the scene needs it
// (and why), and a factory. A protocol may force an effect on or off; the decision and its reason
// are kept for `tamponade plan` and the run record.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sim/effects/interfacial_tension_hu_adams2006.h"
#include "sim/effects/viscosity_weiler2018.h"
#include "sim/fluid/dfsph_bender2017.h"
#include "sim/fluid/iisph_ihmsen2013.h"
#include "sim/fluid/indsph_wang2023.h"
#include "sim/fluid/number_density_solenthaler2008.h"
#include "sim/fluid/vslsph_li2023.h"
#include "sim/fluid/wcsph_becker2007.h"
#include "sim/solid/elasticity_peer2018.h"
#include "sim/world/pipeline.h"

namespace sim {

// A protocol's (or a test's) override of a stage's own rule: kAuto lets the rule decide.
enum class StageOverride { kAuto, kOn, kOff };

// Everything a pipeline can be configured with. Stages read the parts they need.
struct PipelineOptions {
  std::string solver = "dfsph";
  DfsphParameters dfsph;
  WcsphParameters wcsph;    // also the number_density solver's speed of sound, and VSLSPH's
  VslsphParameters vslsph;  // speedOfSound 0: wcsph.speedOfSound
  IndsphParameters indsph;
  IisphParameters iisph;
  ImplicitViscosityParameters implicitViscosity;  // wallFriction below overrides its own
  ElasticityParameters elasticity;
  bool wallFriction = true;       // no-slip viscous walls
  Real velocitySmoothing = 0.05;  // [1] XSPH strength for incompressible solvers (0 = off)
  // Discretisation of the interfacial surface stress
  // (sim/effects/interfacial_tension_hu_adams2006.h): corrected (first-order consistent on any
  // particle order), symmetric (momentum-exact), or auto (by the solver: resolveSurfaceStressForm).
  SurfaceStressForm surfaceStress = SurfaceStressForm::kAuto;
  // [Pa] background_pressure stage's p_bg; < 0: automatic, kBackgroundPressurePerTension sigma / d
  // (sim/effects/background_pressure.h)
  Real backgroundPressure = -1;
  // Whether the fluid fills a closed container (no free surface), which the background_pressure
  // stage needs: kOn / kOff as the scene knows it (the eye's filled cavity), kAuto: detected
  // from the number densities at assembly (countFreeSurfaceParticles; a jittered lattice can
  // read as a free surface there).
  StageOverride closedDomain = StageOverride::kAuto;
  std::map<std::string, StageOverride> forced;  // effect name -> forced on/off
};

struct SolverEntry {
  std::string name;
  std::string description;
  std::function<std::unique_ptr<PressureSolver>(const World&, const PipelineOptions&)> create;
  // Iterative solvers only: sets the relative density error their solve stops at (explicit
  // solvers have no solve to stop and leave it empty).
  std::function<void(PipelineOptions&, Real)> setTolerance;
  // Iterative solvers with a relaxed Jacobi update only: sets its relaxation omega in (0, 1].
  std::function<void(PipelineOptions&, Real)> setRelaxation;
  bool iterative() const { return static_cast<bool>(setTolerance); }
};

struct EffectEntry {
  std::string name;
  std::string description;
  // When the rule turns the effect on, in a few words. An effect that has it may be forced on or
  // off by whoever assembles the pipeline (PipelineOptions::forced; a protocol's [effects] table
  // lists exactly these, with this text in its reference); "" for stages that are not switched
  // by hand (gravity, velocity smoothing).
  std::string inferredWhen;
  bool forceable() const { return !inferredWhen.empty(); }
  // Whether the scene calls for the effect, with the reason in words.
  std::function<StageDecision(const World&, const PipelineOptions&)> needed;
  std::function<std::unique_ptr<Effect>(const World&, const PipelineOptions&)> create;
};

const std::vector<SolverEntry>& solverRegistry();
const std::vector<EffectEntry>& effectRegistry();

// Builds the pipeline the scene calls for. Throws SimError for an unknown solver or effect name.
Pipeline assemblePipeline(const World& world, const PipelineOptions& options);

}  // namespace sim
