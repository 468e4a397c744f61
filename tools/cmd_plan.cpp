// `tamponade plan PROTOCOL`: assembles the scenario and prints what a run would do: particles per
// material, the pipeline stages and why each is there, memory, and run-time estimates per
// accuracy preset from a cost model calibrated on this machine. Writes nothing.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "anatomy/anatomy_error.h"
#include "meshing/mesh_error.h"
#include "protocols/assembly/assemble_scenario.h"
#include "protocols/assembly/pipeline_options.h"
#include "protocols/equilibrium/posture_equilibrium.h"
#include "protocols/equilibrium/start_from_equilibrium.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/report/report_format.h"
#include "protocols/run/plan_scenario.h"
#include "sim/core/error.h"
#include "tools/accuracy_option.h"
#include "tools/cli.h"
#include "tools/cli_values.h"
#include "tools/commands.h"
#include "tools/phase_printer.h"
#include "tools/protocol_error_print.h"

namespace tools {
namespace {

constexpr const char* kUsage =
    "usage: tamponade plan PROTOCOL.toml [--accuracy draft|standard|fine] [--max-memory SIZE]\n";

constexpr const char* kDescription =
    "Assembles the scenario without running it and prints the particle counts per material, the\n"
    "pipeline stages and why each is there, the memory, and an estimated run time per accuracy\n"
    "preset (cost model calibrated by a few steps of this scene on this machine). Writes "
    "nothing.\n";

constexpr const char* kFooter = "Bad protocols: every problem as file:line:column, exit code 2.\n";

// "182 MiB", "1.06 GiB": three significant digits without an exponent.
std::string megabytes(std::size_t bytes) {
  const double mib = static_cast<double>(bytes) / (1024.0 * 1024.0);
  if (mib >= 1000.0) return protocols::formatNumber(mib / 1024.0, 3) + " GiB";
  return protocols::formatNumber(mib, 3) + " MiB";
}

std::string duration(double seconds) {
  if (seconds < 120) return protocols::formatNumber(seconds, 3) + " s";
  if (seconds < 7200) return protocols::formatNumber(seconds / 60, 3) + " min";
  return protocols::formatNumber(seconds / 3600, 3) + " h";
}

// One posture's equilibrium solved here and timed; the other presets are scaled from it (voxels
// ~ h^-3, iterations ~ h^-1).
struct TimedEquilibrium {
  double voxel = 0.0;  // [m]
  protocols::CavityVoxels cavity;
  protocols::PostureEquilibrium solve;
  double secondsAt(const char* preset) const {
    return solve.seconds * std::pow(voxel / protocols::equilibriumVoxelSpacing(preset), 4.0);
  }
  std::string described(const std::string& label) const {
    return fmt::format("'{}' solved here in {} s ({} iterations, {} x {} x {} voxels of {} mm)",
                       label, protocols::formatNumber(solve.seconds, 3), solve.solution.iterations,
                       cavity.grid.nx, cavity.grid.ny, cavity.grid.nz,
                       protocols::formatNumber(voxel * 1e3, 2));
  }
};

TimedEquilibrium solveTimed(const protocols::Protocol& protocol,
                            const protocols::Scenario& scenario, std::size_t posture) {
  TimedEquilibrium t;
  t.voxel = protocols::equilibriumVoxelSpacing(scenario.accuracy.preset);
  t.cavity = protocols::voxelizeCavity(scenario, t.voxel);
  t.solve = protocols::solvePostureEquilibrium(scenario, t.cavity, protocol.tamponade.fill.value,
                                               scenario.schedule[posture].gravity);
  return t;
}

// An equilibrium schedule: one posture solved here and timed, beside what simulating a posture
// would cost instead.
void printEquilibriumPlan(const protocols::Protocol& protocol, const protocols::Scenario& scenario,
                          const protocols::ScenarioPlan& plan) {
  const TimedEquilibrium t = solveTimed(protocol, scenario, 0);
  const std::size_t postures = scenario.schedule.size();
  std::printf(
      "\nevery posture asks for its static equilibrium (docs/methods/equilibrium.md): the "
      "estimate above is what simulating %s of nominal hold would cost; %s\n",
      duration(plan.simulatedDuration).c_str(),
      t.described(scenario.schedule.front().label).c_str());
  std::printf("  %-9s %8s %16s %22s\n", "preset", "voxel", "per posture", "schedule (postures)");
  for (const char* preset : {"draft", "standard", "fine"}) {
    const double seconds = t.secondsAt(preset);
    std::printf(
        "  %-9s %5s mm %16s %16s (%zu)\n", preset,
        protocols::formatNumber(protocols::equilibriumVoxelSpacing(preset) * 1e3, 2).c_str(),
        duration(seconds).c_str(), duration(seconds * static_cast<double>(postures)).c_str(),
        postures);
  }
}

// A mixed schedule: its postures at equilibrium (the last one solved here and timed) and the
// simulation after them, per preset side by side.
void printMixedPlan(const protocols::Protocol& protocol, const protocols::Scenario& scenario,
                    const protocols::ScenarioPlan& plan, std::size_t leading) {
  const TimedEquilibrium t = solveTimed(protocol, scenario, leading - 1);
  std::printf(
      "\nthe schedule begins with %zu posture%s at equilibrium (docs/methods/equilibrium.md), "
      "then simulates %s starting from the %s equilibrium (the estimate above); %s\n",
      leading, leading == 1 ? "" : "s", duration(plan.simulatedDuration).c_str(),
      scenario.schedule[leading - 1].label.c_str(),
      t.described(scenario.schedule[leading - 1].label).c_str());
  std::printf("  %-9s %8s %16s %8s %12s %12s\n", "preset", "voxel", "equilibria", "d [mm]",
              "simulation", "total");
  for (const protocols::PresetEstimate& e : plan.presets) {
    const double equilibria = t.secondsAt(e.preset.c_str()) * static_cast<double>(leading);
    std::printf(
        "  %-9s %5s mm %16s %8s %12s %12s\n", e.preset.c_str(),
        protocols::formatNumber(protocols::equilibriumVoxelSpacing(e.preset) * 1e3, 2).c_str(),
        duration(equilibria).c_str(), protocols::formatNumber(e.particleSpacing * 1e3, 3).c_str(),
        duration(e.seconds).c_str(), duration(equilibria + e.seconds).c_str());
  }
}

}  // namespace

int runPlan(Args args) {
  CLI::App app("", "tamponade plan");
  describeCommand(app, kUsage, kDescription, kFooter);
  std::string file, accuracy;
  double memoryLimit = 0;  // [B] 0: what the machine has available
  app.add_option("PROTOCOL.toml", file, "the protocol to plan")->required();
  addAccuracyOption(app, accuracy);
  app.add_option("--max-memory", memoryLimit,
                 "refuse a scene whose estimated memory exceeds SIZE (e.g. 4 GiB) before\n"
                 "anything is allocated, naming the spacing that would fit (default: what the\n"
                 "machine has available)")
      ->type_name("SIZE")
      ->transform(memorySize());
  if (const std::optional<int> exit = parseCommandLine(app, args)) return *exit;
  protocols::ScenarioOptions options;
  options.accuracy = accuracyPreset(accuracy);
  if (memoryLimit > 0) options.memoryLimit = memoryLimit;
  if (!options.memoryLimit) options.memoryLimit = protocols::machineMemoryLimit();
  const PhasePrinter phases("plan");
  options.progress = phases;
  try {
    const protocols::Protocol protocol = protocols::parseProtocol(file);
    protocols::Scenario scenario = protocols::assembleStartingScenario(protocol, options);
    phases("calibrating the cost model (a few steps of this scene)");
    const protocols::ScenarioPlan plan = protocols::planScenario(scenario);

    std::printf("plan for %s: %s\n\n", file.c_str(), scenario.title.c_str());
    std::printf("cavity: %s mL, wall area %s cm^2\n",
                protocols::formatNumber(scenario.cavityVolume * 1e6, 4).c_str(),
                protocols::formatNumber(scenario.cavityArea * 1e4, 4).c_str());
    std::printf("accuracy: %s, particle spacing %s mm, solver tolerance %s %% (%s)\n\n",
                scenario.accuracy.preset.c_str(),
                protocols::formatNumber(scenario.accuracy.particleSpacing * 1e3, 3).c_str(),
                protocols::formatNumber(scenario.accuracy.solverTolerance * 100, 3).c_str(),
                protocols::isImplicitSolver(scenario.pipelineOptions.solver)
                    ? "mean density error where the pressure solve stops"
                    : "not used by the explicit solver");
    std::printf("particles per material:\n");
    for (const protocols::FluidPhase& ph : scenario.phases)
      std::printf("  %-20s %9zu  (%s mL, %s kg each)\n", ph.material.c_str(), ph.count,
                  protocols::formatNumber(ph.volume * 1e6, 4).c_str(),
                  protocols::formatNumber(ph.particleMass, 4).c_str());
    std::printf("  %-20s %9zu  (rigid wall: %s)\n", "wall", plan.wallParticles,
                scenario.layeredWalls ? "three lattice layers of volume d^3, accuracy.wall_model"
                                      : "one Akinci layer, accuracy.wall_model");
    std::printf("  retinal breaks: %zu\n", scenario.breaks.size());
    std::printf("  initial mean density: %s x rest density (see the fluid fill note)\n",
                protocols::formatNumber(scenario.fillCompression, 3).c_str());
    for (const std::string& note : scenario.notes) std::printf("  note: %s\n", note.c_str());
    if (!scenario.tissues.empty()) std::printf("\ntissues (elastic only when it matters):\n");
    for (const protocols::TissueBody& t : scenario.tissues)
      std::printf("  %s\n", t.describe().c_str());
    for (const auto& [stage, limit] : plan.stageTimeStepLimits)
      if (stage == "elasticity")
        std::printf("  elastic stage time-step limit %s s\n",
                    protocols::formatNumber(limit, 3).c_str());
    std::printf("\nfluid properties used:\n");
    for (const protocols::FluidPhase& ph : scenario.phases) {
      const double nu = ph.dynamicViscosity / ph.density;  // [m^2/s]
      std::printf("  %-20s density %s kg/m^3, viscosity %s Pa s (%s cSt)\n", ph.material.c_str(),
                  protocols::formatNumber(ph.density, 4).c_str(),
                  protocols::formatNumber(ph.dynamicViscosity, 3).c_str(),
                  protocols::formatNumber(nu * 1e6, 4).c_str());
    }
    const protocols::FluidPhase& tamponade = scenario.phases[1];
    if (tamponade.interfacialTension)
      std::printf("  interfacial tension %s mN/m (tamponade against aqueous)\n",
                  protocols::formatNumber(*tamponade.interfacialTension * 1e3, 3).c_str());
    if (tamponade.contactAngleThroughAqueous)
      std::printf(
          "  contact angle on the retina %s deg through the aqueous (%s deg through the "
          "tamponade)\n",
          protocols::formatNumber(*tamponade.contactAngleThroughAqueous, 3).c_str(),
          protocols::formatNumber(180.0 - *tamponade.contactAngleThroughAqueous, 3).c_str());
    std::printf("\n%s\n", plan.pipeline.c_str());
    // The measured peak covers everything assembly and stepping allocate; the estimate is what
    // was checked against the memory limit before anything was allocated.
    const double peak = plan.peakResidentBytes > 0 ? plan.peakResidentBytes : scenario.memory.bytes;
    std::printf(
        "memory: %s, the peak of assembling and stepping this scene (a run peaks up to ~10 %% "
        "higher);"
        " estimated before assembly %s for %s fluid particles; at the start: particle fields %s, "
        "wall fields %s, neighbour lists %s\n\n",
        megabytes(static_cast<std::size_t>(peak)).c_str(),
        megabytes(static_cast<std::size_t>(scenario.memory.bytes)).c_str(),
        protocols::formatNumber(scenario.memory.fluidParticles, 3).c_str(),
        megabytes(plan.particleFieldBytes).c_str(), megabytes(plan.wallFieldBytes).c_str(),
        megabytes(plan.neighborListBytes).c_str());
    std::printf(
        "cost model: calibrated by %d steps of this scene (%zu dynamic particles) on %d "
        "thread%s after one warm-up step, %s s in all; the fastest step gives %s s per "
        "particle-step%s\n",
        plan.calibrationSteps, plan.dynamicParticles, plan.threads, plan.threads == 1 ? "" : "s",
        protocols::formatNumber(plan.calibrationSeconds, 3).c_str(),
        protocols::formatNumber(plan.secondsPerParticleStep, 3).c_str(),
        plan.rejectedSteps > 0 ? " (rejected steps included)" : "");
    std::printf("time-step limits of the stages at the start:");
    for (const auto& [stage, limit] : plan.stageTimeStepLimits)
      std::printf(" %s %s s;", stage.c_str(), protocols::formatNumber(limit, 3).c_str());
    std::printf("%s\n", plan.stageTimeStepLimits.empty() ? " none" : "");
    std::printf("first time step %s s, limited by %s; simulated time %s s\n",
                protocols::formatNumber(plan.firstTimeStep, 3).c_str(),
                plan.timeStepLimitedBy.c_str(),
                protocols::formatNumber(plan.simulatedDuration, 4).c_str());
    std::printf(
        "estimated run time (a lower bound: flows shorten the step, finer presets need "
        "more solver iterations):\n");
    std::printf("  %-9s %8s %11s %11s %10s %10s\n", "preset", "d [mm]", "particles", "dt [s]",
                "steps", "time");
    for (const protocols::PresetEstimate& e : plan.presets)
      std::printf("  %-9s %8s %11.0f %11s %10.0f %10s\n", e.preset.c_str(),
                  protocols::formatNumber(e.particleSpacing * 1e3, 3).c_str(), e.particles,
                  protocols::formatNumber(e.timeStep, 3).c_str(), e.steps,
                  duration(e.seconds).c_str());
    if (protocols::isEquilibriumSchedule(scenario))
      printEquilibriumPlan(protocol, scenario, plan);
    else if (const std::size_t leading = protocols::leadingEquilibria(scenario); leading > 0)
      printMixedPlan(protocol, scenario, plan, leading);
    return 0;
  } catch (const protocols::ProtocolError& e) {
    return printProtocolError(e);
  }
}

}  // namespace tools
