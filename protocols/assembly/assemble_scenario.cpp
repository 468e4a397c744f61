#include "protocols/assembly/assemble_scenario.h"

#include "meshing/mesh_error.h"
#include "protocols/assembly/cavity.h"
#include "protocols/assembly/cavity_walls.h"
#include "protocols/assembly/fluid_fill.h"
#include "protocols/assembly/fluid_phases.h"
#include "protocols/assembly/interface_physics.h"
#include "protocols/assembly/pipeline_options.h"
#include "protocols/assembly/scenario_setup.h"
#include "protocols/report/report_format.h"
#include "protocols/scenario/scenario.h"
#include "protocols/scenario/scenario_error.h"
#include "protocols/tissue/add_tissues.h"
#include "sim/core/error.h"

namespace protocols {

namespace {

void announce(const ScenarioOptions& options, std::string_view phase) {
  if (options.progress) options.progress(phase);
}

// The phases of assembly, in order (scenario.h describes each; the notes keep this order).
Scenario assemble(const Protocol& p, const ScenarioOptions& options) {
  Scenario s;
  setUpScenario(p, options, s);
  const double d = s.accuracy.particleSpacing;  // [m]
  announce(options, "building the cavity");
  buildCavity(p, s);
  checkMemory(p, options, s, d);
  createWorld(p, s);
  announce(options, "sampling the cavity wall");
  const meshing::SurfaceSamples retinaSamples = buildWalls(p, s, options.wallSpacingFactor * d);
  recordRetinaSamples(s, retinaSamples.points, retinaSamples.normals);
  announce(options, "adding the tissues");
  addTissues(p, s);  // elastic sclera / orbital fat replace the wall they cover
  s.layeredWalls = chooseLayeredWalls(p, options, s);
  if (s.layeredWalls) {
    announce(options, "layering the cavity wall");
    replaceWithLayeredWalls(s, d);
  }
  setInterfacePhysics(s);
  announce(options, "filling the cavity");
  fillFluid(p, options, s);
  chooseGravityReference(options, s);
  choosePipelineOptions(p, options, s);
  announce(options, "initialising the simulation (neighbour lists, stages)");
  try {
    s.world->initialize();
  } catch (const sim::SimError& error) {
    failAt(p.accuracy.particleSpacing.where, error.what(), "check the accuracy settings");
  }
  startFluidFill(options, s);
  resolveOutputFields(p, s);
  return s;
}

}  // namespace

Scenario assembleScenario(const Protocol& p, const ScenarioOptions& options) {
  // Sampling and the engine refuse what they cannot build (a domain with no fluid, a spacing the
  // sampler cannot resolve) without knowing the protocol: name the line that chose the spacing,
  // the setting such failures depend on.
  const std::string fix =
      "check the eye's size and accuracy.particle_spacing (an eye needs a spacing well below its "
      "size)";
  try {
    return assemble(p, options);
  } catch (const meshing::MeshError& error) {
    failAt(spacingSource(p), std::string("the scene cannot be assembled: ") + error.what(), fix);
  } catch (const sim::SimError& error) {
    failAt(spacingSource(p), std::string("the scene cannot be assembled: ") + error.what(), fix);
  }
}

void requireStartTimeStep(const Scenario& s, const sim::TimeStepInfo& first) {
  if (first.limitedBy != "min") return;
  failAt(s.accuracy.minTimeStepWhere,
         "accuracy.min_time_step = " + formatNumber(s.accuracy.minTimeStep, 3) +
             " s is longer than the time step this scene needs at its start (" +
             formatNumber(first.wanted, 3) + " s, the " + first.wantedBy +
             " limit): every step would be too long to be stable",
         "lower accuracy.min_time_step below " + formatNumber(first.wanted, 3) +
             " s (the presets use 1e-7 s), or remove it");
}

}  // namespace protocols
