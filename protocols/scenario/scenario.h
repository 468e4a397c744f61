// A Scenario is a Protocol made concrete (docs/developer-guide.md, names): the cavity, its wall
// particles with their retinal regions and breaks, the two fluid phases as particles, the
// sim::World and the PipelineOptions that a run steps, and the posture schedule as gravity vectors.
//
// Assembly (assembleScenario):
//  1. cavity: a parametric eye from anatomy (emmetropic / myopic / staphyloma) or an imported
//     mesh (meshing::loadMesh, units from the protocol);
//  2. retina samples: meshing::sampleSurface at d/2; outward normals; regions per sample
//     (anatomy::assignRegions) in RetinaMap, keyed by sample index. Walls: accuracy.wall_model
//     "layered" (the default of a rigid cavity) puts three layers of lattice particles behind the
//     mesh (layered_cavity_walls.h), each tagged with its nearest sample's regions; "single_layer"
//     (the default next to an elastic tissue) makes the samples themselves the wall particles,
//     Akinci volume 0 (World::initialize computes it), regions in the wall `tag`;
//  3. fluids: lattice particles of rest mass; with layered walls every lattice point inside the
//     mesh (one lattice with the wall, at rest density); with one wall layer from 0.65 d of the
//     wall, relaxed by a start-up particle-shifting pass (MassRule::kRelaxedFill, relax_fill.h);
//     split into the two phases
//     along the fill direction of the first posture's gravity (light oil floats: -g; heavy oil
//     sinks: +g) so the tamponade's share is the fill fraction (MassRule below);
//  4. materials from the anatomy material library (protocol overrides applied), the World and
//     PipelineOptions (solver by name, effects forced as the protocol says). A protocol that names
//     no solver runs with the format's default, "indsph" (with the older, compressed fill rules:
//     "wcsph", with a note); one that names a missing solver is an error.
// Tissues (sclera, orbital fat): decided elastic or rigid and, when elastic, sampled as elastic
// particles that replace the wall they cover (protocols/tissue/tissue_particles.h).
// Each step is a function of its own, called in this order by assembleScenario
// (assemble_scenario.cpp): scenario_setup.h, cavity.h, fluid_phases.h (the World), cavity_walls.h,
// the tissues, interface_physics.h, fluid_fill.h, pipeline_options.h.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "anatomy/eye.h"
#include "anatomy/retinal_break.h"
#include "meshing/triangle_mesh.h"
#include "protocols/coverage/frame_coverage.h"
#include "protocols/format/protocol.h"
#include "protocols/scenario/memory_estimate.h"
#include "protocols/scenario/tissue_body.h"
#include "sim/world/pipeline.h"
#include "sim/world/stage_registry.h"
#include "sim/world/world.h"

namespace protocols {

// How the two phases are put on the lattice and how heavy their particles are. In every rule
// but kTrueMass the interface is placed by count: lattice points ordered along the fill
// direction, the first round(fill N) are tamponade, so the phases' shares of the fluid are exact
// to one particle and the interface is flat to within one lattice layer.
enum class MassRule {
  // m = rho d^3 and a lattice from 0.65 d, then a start-up shifting pass (relax_fill.h, not
  // simulated time) that moves the over-dense outermost layer off the wall into the staircase
  // holes, so the fluid starts near rest density with no compression built into the masses. The
  // gap is where the single Akinci wall layer lets fluid at rest density end: measured on
  // tiny.toml (emmetropic, d = 1.2 mm, 100 passes, every particle moving), a lattice from d/2
  // holds 1.014 x (V - A d/2) and relaxes to a mean density of 1.049 rho0 (the wall pushes the
  // fluid ~0.6 d away, not d/2); from 0.65 d it holds 0.962 x (V - A d/2) = 80 % of V and
  // relaxes to 1.0015 rho0; from 0.7 d, 0.946 and 0.987 rho0. Since only over-dense particles
  // move (an elastic sclera one particle thick let the fill expand like a gas otherwise) tiny.toml
  // starts at mean 1.008, max 1.059 rho0; paper_sclera_10kpa.toml at 0.939, max 1.011 (the fluid
  // next to the one-layer tissue is under-dense). docs/methods/solvers.md "Fluid fill".
  kRelaxedFill,
  // m = rho d^3 (V - A d/2) / (N d^3): the fluid at rest density fills the cavity up to d/2 from
  // the wall (where the wall particles' Akinci volumes take over). The lattice sits 1.2 d from the
  // wall, plus up to sqrt(3)/2 d of staircase on a curved wall, so it starts ~30 % compressed at
  // d = 1.2 mm (less at finer d, the deficit scales with A d / V); the fluid expands to the wall
  // in the first ms (up to 2.6 m/s, tiny.toml) and is calm after 0.1 s (1 cm/s, density within
  // [0.98, 1.04] rho0, i.e. no free surface).
  kFillCavity,
  // m = rho d^3: no initial compression, but the fluid stands for only N d^3 (63 % of the cavity
  // at d = 1.2 mm): under gravity it settles and leaves the upper wall dry (tiny.toml upright:
  // 77 % of the superior quadrant dry after 0.5 s). For comparison.
  kRestDensity,
  // The geometric fill plane (findFillPlane) and m = rho V_phase / N_phase: each phase carries
  // its true mass, but a thin phase along a large wall (aqueous at 90 % fill) starts compressed
  // x1.3-2.3 at d = 1.2 mm, which throws particles through the wall. For comparison.
  kTrueMass,
};

struct ScenarioOptions {
  std::optional<AccuracyPreset> accuracy;  // overrides the protocol's preset (explicit values too)
  // [1] fluid lattice starts this many spacings from the wall; unset: 0.65 for kRelaxedFill,
  // 1.2 for the other rules (at d the Akinci wall term over-estimates density by 6 %).
  std::optional<double> wallGapFactor;
  // [1] wall particle spacing / d. One layer of Poisson-disk wall particles at d leaves holes up
  // to ~1.8 d wide (RSA, sample_surface.h) that fluid particles leak through under gravity (seen
  // at d = 1.2 mm after 0.04 s); at 0.5 d the holes are ~0.9 d, smaller than a particle.
  double wallSpacingFactor = 0.5;
  MassRule massRule = MassRule::kRelaxedFill;
  int relaxationPasses = 100;  // [1] shifting passes of kRelaxedFill (relax_fill.h)
  // Gravity relative to the aqueous density (sim::World::gravityReferenceDensity) when every
  // tissue is rigid: the closed cavity is filled with fluid, so p' = p - rho_aq g.x is an exact
  // rewrite, and without the hydrostatic background the 3 % oil/aqueous buoyancy is no longer
  // pinned by the particle arrangement (docs/methods/interface.md, validation 6). false: plain
  // gravity.
  bool removeHydrostaticBackground = true;
  // [B] refuse (ProtocolError at the spacing) a scene whose estimated memory exceeds this, before
  // any particle is allocated (memory_estimate.h); unset: no limit. The CLI passes the machine's
  // available memory or --max-memory.
  std::optional<double> memoryLimit;
  // Called as each assembly phase starts, with what it does ("sampling the cavity wall"); empty:
  // silent. The command line shows it once assembly has taken a while (at 0.1 mm an eye takes
  // minutes to assemble).
  std::function<void(std::string_view phase)> progress;
};

struct FluidPhase {
  std::string material;    // material library name ("aqueous", "silicone_oil_1000", ...)
  int materialIndex = -1;  // in world.materials
  bool isTamponade = false;
  double density = 0.0;           // [kg/m^3]
  double dynamicViscosity = 0.0;  // [Pa s]
  // Tamponade only: interfacial tension against aqueous [N/m] and contact angle on the retina
  // measured through the aqueous phase [deg] (docs/conventions.md), from the library or the
  // protocol.
  std::optional<double> interfacialTension;
  std::optional<double> contactAngleThroughAqueous;
  double volume = 0.0;        // [m^3] the phase's share of the cavity volume (geometric)
  std::size_t count = 0;      // particles
  double particleMass = 0.0;  // [kg] MassRule
};

struct ScheduledPosture {
  std::string label;
  sim::Vec3 gravity = sim::Vec3::Zero();  // [m/s^2] eye frame
  double duration = 0.0;                  // [s] (the upper bound when untilSteady; what was run
                                          //      once a run ended it steady)
  bool untilSteady = false;
  std::optional<bool> endedSteady =
      {};  // set by a run (or from its files): steady before the bound
  // duration = "equilibrium": computed by protocols/equilibrium/, not simulated; `duration` is
  // its weight in the schedule's means (kEquilibriumHold).
  bool equilibrium = false;
};

struct AccuracySettings {
  std::string preset;
  double particleSpacing = 0.0;     // [m]
  double solverTolerance = 0.0;     // [1]
  double minTimeStep = 0.0;         // [s]
  double maxTimeStep = 0.0;         // [s]
  SourceLocation minTimeStepWhere;  // where minTimeStep was set (the preset's line, or the file)
};

struct Scenario {
  std::string title;
  std::optional<anatomy::Eye> eye;  // parametric cavities only (an imported mesh has no landmarks)
  meshing::TriangleMesh cavity;     // [m] closed, outward, eye frame
  double cavityVolume = 0.0;        // [m^3]
  double cavityArea = 0.0;          // [m^2]
  MemoryEstimate memory;            // from the cavity and the spacing, before allocation
  std::vector<anatomy::RetinalBreak> breaks;
  RetinaMap retina;                 // per retina sample (the walls as first sampled)
  RetinaSamples retinaSamples;      // where the coverage is measured (may move with a tissue)
  std::vector<TissueBody> tissues;  // the protocol's sclera / orbital fat, decided
  std::vector<FluidPhase> phases;   // [0] aqueous, [1] tamponade (a phase may have 0 particles)
  std::vector<ScheduledPosture> schedule;
  AccuracySettings accuracy;
  std::unique_ptr<sim::World> world;  // initialized
  sim::PipelineOptions pipelineOptions;
  std::vector<std::string> notes;  // what was simplified or left out, in words
  // Fluid fields each frame holds: the protocol's outputs.fields, checked against the registry
  // once the pipeline's fields are registered, plus position and material, which the coverage
  // (report, `tamponade report DIR`, resume) is recomputed from.
  std::vector<std::string> outputFields;
  double fillCompression = 1.0;  // [1] initial mean density / rest density (MassRule)
  // kRelaxedFill: the kernel-summed volume fraction C (relax_fill.h) of the fluid particles at
  // t = 0, mean and max (1 = rest density); and the fluid volume the particles hold, N d^3, over
  // the cavity minus the wall's d/2 shell, V - A d/2. Layered walls (no shifting pass): the same
  // fractions at t = 0, and N d^3 over the whole cavity V.
  double startMeanFraction = 0.0;  // [1]
  double startMaxFraction = 0.0;   // [1]
  double heldVolumeRatio = 0.0;    // [1]
  // The cavity wall is three lattice layers (accuracy.wall_model, layered_cavity_walls.h); false:
  // one Akinci layer on the mesh. The retina samples are the mesh's Poisson-disk points either way.
  bool layeredWalls = false;

  // Tamponade flags of the world's dynamic particles in their current order, for the coverage
  // metric (1 = tamponade material).
  std::vector<std::uint8_t> tamponadeFlags() const;
  double totalDuration() const;  // [s] sum of the schedule's durations
};

}  // namespace protocols
