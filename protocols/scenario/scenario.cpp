#include "protocols/scenario/scenario.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "anatomy/anatomy_error.h"
#include "anatomy/material_library.h"
#include "anatomy/posture.h"
#include "anatomy/retinal_regions.h"
#include "anatomy/vitreous_cavity.h"
#include "meshing/find_fill_plane.h"
#include "meshing/load_mesh.h"
#include "meshing/mesh_error.h"
#include "meshing/mesh_measures.h"
#include "meshing/sample_surface.h"
#include "meshing/sample_volume.h"
#include "protocols/format/edit_distance.h"
#include "protocols/format/protocol_error.h"
#include "protocols/report/report_format.h"
#include "protocols/scenario/layered_cavity_walls.h"
#include "protocols/scenario/point_grid.h"
#include "protocols/scenario/relax_fill.h"
#include "sim/boundary/wall_layers.h"
#include "sim/boundary/wetted_surface.h"
#include "sim/core/error.h"

namespace protocols {
namespace {

const AccuracyPresetValues& draftPreset() {
  return kAccuracyPresets[static_cast<std::size_t>(AccuracyPreset::kDraft)];
}

// Coarser than the draft preset the coverage is a trial figure: measured on tiny.toml
// (docs/accuracy.md, "Spacing against tolerance"), 1.2 mm read the whole-retina
// coverage 3.5 points above 0.6 mm and 0.8 mm 0.4 points.
std::string coarseSpacingNote(double spacing) {
  const std::string draft = formatNumber(draftPreset().particleSpacing * 1e3, 3);
  return "particle spacing " + formatNumber(spacing * 1e3, 3) +
         " mm is coarser than the draft preset's " + draft +
         " mm: a trial run, not a figure to publish (tiny.toml: 1.2 mm reads the coverage 3.5 "
         "points above 0.6 mm; docs/accuracy.md)";
}

[[noreturn]] void fail(const SourceLocation& where, const std::string& what,
                       const std::string& fix) {
  throw ProtocolError({Diagnostic{where, what, fix}});
}

// The cavity and, for parametric kinds, the eye.
void buildCavity(const Protocol& p, Scenario& s) {
  const EyeSpec& e = p.eye;
  try {
    if (e.kind.value == EyeKind::kMesh) {
      const MeshSource& m = *e.mesh;
      const meshing::LengthUnit unit = meshing::parseLengthUnit(m.units.value);
      meshing::LoadedMesh loaded = meshing::loadMesh(m.path.value.string(), unit);
      s.cavity = std::move(loaded.mesh);
      s.notes.push_back(
          "imported cavity mesh: it carries no clinical landmarks, so the whole wall counts as "
          "retina (no quadrants, macula or periphery) and breaks cannot be placed");
      if (!e.breaks.empty())
        fail(e.breaks.front().where,
             "retinal break '" + e.breaks.front().name.value + "' on an imported mesh cavity",
             "breaks are placed by clinical coordinates, which need a parametric eye (kind = "
             "\"emmetropic\", \"myopic\" or \"staphyloma\"); remove the breaks or use one");
    } else {
      auto make = [&]() {
        if (e.kind.value == EyeKind::kEmmetropic) {
          anatomy::EmmetropicCavityParameters q;
          if (e.axialLength) q.axialLength = e.axialLength->value;
          return anatomy::makeEmmetropicCavity(q);
        }
        if (e.kind.value == EyeKind::kMyopic) {
          anatomy::MyopicCavityParameters q;
          if (e.axialLength) q.axialLength = e.axialLength->value;
          return anatomy::makeMyopicCavity(q);
        }
        anatomy::StaphylomaCavityParameters q;
        if (e.axialLength) q.axialLength = e.axialLength->value;
        if (e.staphylomaDepth) q.staphylomaDepth = e.staphylomaDepth->value;
        if (e.staphylomaWidth) q.staphylomaWidth = e.staphylomaWidth->value;
        return anatomy::makeStaphylomaCavity(q);
      };
      anatomy::VitreousCavity cavity = make();
      s.cavity = std::move(cavity.mesh);
      s.eye.emplace(
          e.side.value == EyeSide::kOd ? anatomy::Laterality::kRight : anatomy::Laterality::kLeft,
          cavity.shape);
    }
  } catch (const anatomy::AnatomyError& error) {
    fail(e.axialLength ? e.axialLength->where : e.kind.where, error.what(),
         "change the eye's parameters to the range named above");
  } catch (const meshing::MeshError& error) {
    fail(e.mesh->path.where, error.what(), "repair the mesh or give its units");
  }
  const meshing::MeshMeasures measures = meshing::measureMesh(s.cavity);
  s.cavityVolume = measures.signedVolume;
  s.cavityArea = measures.area;
}

// Where the spacing came from: the explicit particle_spacing, else the preset line, else the file.
SourceLocation spacingSource(const Protocol& p) {
  if (p.accuracy.particleSpacing.where.isInFile()) return p.accuracy.particleSpacing.where;
  if (p.accuracy.preset.where.isInFile()) return p.accuracy.preset.where;
  return SourceLocation{p.file.string(), 0, 0};
}

std::string gibibytes(double bytes) { return formatNumber(bytes / 1073741824.0, 3) + " GiB"; }

// Refuses, before anything is allocated, a spacing whose scene would not fit in memory.
void checkMemory(const Protocol& p, const ScenarioOptions& options, Scenario& s, double d) {
  const bool tissue = p.eye.sclera.has_value() || p.eye.orbitalFat.has_value();
  s.memory = estimateMemory(s.cavityVolume, s.cavityArea, d, tissue);
  if (!options.memoryLimit || s.memory.bytes <= *options.memoryLimit) return;
  const double fits =
      smallestSpacingWithin(s.cavityVolume, s.cavityArea, *options.memoryLimit, tissue);
  fail(spacingSource(p),
       "particle spacing " + formatNumber(d * 1e3, 3) + " mm needs about " +
           gibibytes(s.memory.bytes) + " (" + formatNumber(s.memory.fluidParticles, 3) +
           " fluid particles in " + formatNumber(s.cavityVolume * 1e6, 3) + " mL), more than the " +
           gibibytes(*options.memoryLimit) + " available",
       "use accuracy.particle_spacing = \"" + formatNumber(fits * 1e3, 3) +
           " mm\" or coarser, which fits, or allow more with --max-memory");
}

// "42" for 0.42: the fill notes' percentages.
std::string percent(double fraction) {
  return std::to_string(static_cast<int>(std::lround(100.0 * fraction)));
}
// "100.8" for 1.008: a fraction in percent with one decimal.
std::string percentOneDecimal(double fraction) {
  const long v = std::lround(1000.0 * fraction);
  return std::to_string(v / 10) + "." + std::to_string(v % 10);
}

// Layers of a layered cavity wall (sim/boundary/wall_layers.h: 3 fill the kernel support).
constexpr int kCavityWallLayers = 3;

// Retina samples (the mesh's Poisson-disk samples at `spacing`, with their regions and areas),
// breaks, and the one-layer wall on them. A layered wall replaces that wall later
// (replaceWithLayeredWalls) and keeps the samples: they only say where the coverage is measured.
meshing::SurfaceSamples buildWalls(const Protocol& p, Scenario& s, double spacing) {
  meshing::SurfaceSamples samples = meshing::sampleSurface(s.cavity, spacing);
  s.retina.areas = samples.areas;
  s.retina.regions = s.eye ? anatomy::assignRegions(*s.eye, samples.points, samples.normals)
                           : std::vector<anatomy::RegionSet>(samples.size(), anatomy::kRetina);
  for (std::size_t w = 0; w < samples.size(); ++w)
    s.world->walls.add(samples.points[w], samples.normals[w],
                       static_cast<int>(s.retina.regions[w]));
  for (const RetinalBreak& b : p.eye.breaks) {
    anatomy::RetinalBreakSpec spec;
    spec.name = b.name.value;
    spec.position.clockHour = b.clockHour.value;
    spec.position.distance = b.distance.value;
    spec.position.from = b.reference == DistanceReference::kLimbus
                             ? anatomy::DistanceReference::kLimbus
                             : anatomy::DistanceReference::kOraSerrata;
    spec.diameter = b.diameter.value;
    try {
      s.breaks.emplace_back(*s.eye, spec);
    } catch (const anatomy::AnatomyError& error) {
      fail(b.where, error.what(), "move the break onto the retina (posterior to the ora serrata)");
    }
    const anatomy::RetinalBreak& placed = s.breaks.back();
    std::vector<std::size_t> inside;
    for (std::size_t w = 0; w < samples.size(); ++w)
      if (placed.isInBreak(samples.points[w])) inside.push_back(w);
    if (inside.empty()) {
      // A break smaller than the wall spacing: the wall particle nearest to its centre stands
      // for it (its area is then larger than the break's; noted).
      std::size_t nearest = 0;
      double best = 1e300;
      for (std::size_t w = 0; w < samples.size(); ++w) {
        const double r = (samples.points[w] - placed.centre().position).squaredNorm();
        if (r < best) best = r, nearest = w;
      }
      inside.push_back(nearest);
      s.notes.push_back("break '" + spec.name +
                        "' is smaller than the particle spacing: the "
                        "nearest wall particle stands for it");
    }
    s.retina.breakNames.push_back(spec.name);
    s.retina.breakWalls.push_back(std::move(inside));
  }
  return samples;
}

// Whether the cavity wall is layered (accuracy.wall_model): "auto" takes it unless an elastic
// tissue replaced part of the one-layer wall (tissue_particles.cpp builds on that wall) or the
// fill is one of the comparison mass rules, which are defined against the one-layer wall.
bool chooseLayeredWalls(const Protocol& p, const ScenarioOptions& options, Scenario& s) {
  const Located<WallModelName>& model = p.accuracy.wallModel;
  if (model.value == WallModelName::kSingleLayer) return false;
  const auto elastic = std::find_if(s.tissues.begin(), s.tissues.end(),
                                    [](const TissueBody& t) { return t.decision.elastic; });
  if (elastic != s.tissues.end()) {
    if (model.value == WallModelName::kLayered)
      fail(model.where,
           "wall_model = \"layered\", but the elastic " + elastic->name +
               " replaces part of the cavity wall, and layered walls are not built "
               "next to elastic tissue yet",
           "use wall_model = \"auto\" or \"single_layer\", or make the tissue rigid");
    return false;
  }
  if (options.massRule != MassRule::kRelaxedFill) {
    if (model.value == WallModelName::kLayered)
      s.notes.push_back(
          "wall_model = \"layered\" ignored: the comparison fill rule chosen on the "
          "command line is defined for the one-layer wall");
    return false;
  }
  return true;
}

// The one-layer wall replaced by three lattice layers behind the mesh (layered_cavity_walls.h).
// Each wall particle carries the regions of its nearest retina sample as its tag: the wall stages
// key the contact angle by tag.
void replaceWithLayeredWalls(Scenario& s, double d) {
  const LayeredCavityWalls lw = sampleLayeredCavityWalls(s.cavity, d, kCavityWallLayers);
  sim::WallParticles& walls = s.world->walls;
  walls.fields.resize(0);
  const PointGrid samples(s.retinaSamples.restPositions, d);
  for (std::size_t b = 0; b < lw.positions.size(); ++b) {
    const long owner = samples.nearest(lw.positions[b], (kCavityWallLayers + 2) * d);
    const int tag =
        owner >= 0 ? static_cast<int>(s.retina.regions[static_cast<std::size_t>(owner)]) : 0;
    sim::addLayeredWallParticle(walls, lw.positions[b], lw.normals[b], tag, d * d * d, lw.layer[b]);
  }
}

FluidPhase phaseFromLibrary(const std::string& name, bool isTamponade) {
  const anatomy::MaterialRecord& r = anatomy::MaterialLibrary::builtin().find(name);
  FluidPhase f;
  f.material = name;
  f.isTamponade = isTamponade;
  f.density = r.density->value;
  f.dynamicViscosity = r.dynamicViscosity->value;
  if (r.interfacialTension) f.interfacialTension = r.interfacialTension->value;
  if (r.contactAngle) f.contactAngleThroughAqueous = r.contactAngle->value;
  return f;
}

FluidPhase tamponadePhase(const TamponadeSpec& t) {
  FluidPhase f;
  if (!t.isCustom()) {
    f = phaseFromLibrary(t.agent.value, true);
  } else {
    f.material = "custom";
    f.isTamponade = true;
  }
  if (t.density) f.density = t.density->value;
  if (t.viscosity) {
    const Viscosity& v = t.viscosity->value;
    f.dynamicViscosity = v.kind == ViscosityKind::kDynamic ? v.value : v.value * f.density;
  }
  if (t.interfacialTension) f.interfacialTension = t.interfacialTension->value;
  if (t.contactAngle)
    f.contactAngleThroughAqueous = t.contactAngle->value * 180.0 / std::numbers::pi;
  return f;
}

// The hydrostatic background out of the pressure (ScenarioOptions::removeHydrostaticBackground):
// exact because the cavity is closed and the fill holds it (no free surface). Not with an elastic
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

sim::Vec3 gravityOf(const Posture& posture, double magnitude) {
  if (posture.name.value == PostureName::kCustom) {
    const auto& g = posture.gravityDirection.value;
    return magnitude * sim::Vec3(g[0], g[1], g[2]).normalized();
  }
  return magnitude * anatomy::gravityDirection(anatomy::parsePosture(toString(posture.name.value)));
}

// outputs.fields against the particle fields the run will have: the World's own and those the
// pipeline's stages register (attach uses addOrGet, so attaching here and again in the run adds
// nothing twice). Every unknown name is reported at its place in the file.
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

}  // namespace

std::string contactAngleRangeNote(double throughTamponadeDeg) {
  if (throughTamponadeDeg >= kTestedContactAngleMin &&
      throughTamponadeDeg <= kTestedContactAngleMax)
    return "";
  const std::string angle =
      std::to_string(std::lround(throughTamponadeDeg)) + " deg through the tamponade";
  const std::string tested = "outside the " + std::to_string(std::lround(kTestedContactAngleMin)) +
                             "-" + std::to_string(std::lround(kTestedContactAngleMax)) +
                             " deg that the wall model holds within 5 deg on a flat wall";
  if (throughTamponadeDeg > kTestedContactAngleMax)
    return "contact angle " + angle + " is " + tested +
           ": 150 deg settles up to 8 deg flatter than asked, so the oil's edge is uncertain by "
           "several degrees (docs/validation.md)";
  return "contact angle " + angle + " is " + tested +
         ": 18 deg reads 25.7-27.6 deg, so a thin film may spread less than asked "
         "(docs/validation.md)";
}

std::string contactAngleWallModelNote(RetinaWall wall) {
  if (wall == RetinaWall::kLayered)
    return "layered eye wall (accuracy.wall_model): in a spherical cavity a 150 deg lens reads "
           "155-157 deg; the oil's edge on the retina is uncertain by about 5 deg "
           "(docs/validation.md)";
  const std::string surface =
      wall == RetinaWall::kElasticSclera
          ? "retina over the elastic sclera: 18 deg through the aqueous reads 28.9 deg on a tissue "
            "floor, so the oil's edge there is uncertain by about 10 deg; the lens cap is one "
            "layer of wall particles"
          : "single-layer eye wall (accuracy.wall_model = \"single_layer\"): 18 deg through "
            "the aqueous reads 34.4 deg, 150 deg 127-151 deg, so the oil's edge is uncertain by "
            "10-20 deg";
  return surface + " (docs/validation.md)";
}

std::vector<std::uint8_t> Scenario::tamponadeFlags() const {
  std::vector<std::uint8_t> flags(world->particles.size());
  const int tamponade = phases[1].materialIndex;
  for (std::size_t i = 0; i < flags.size(); ++i)
    flags[i] = world->particles.material[i] == tamponade ? 1 : 0;
  return flags;
}

double Scenario::totalDuration() const {
  double t = 0.0;
  for (const auto& p : schedule) t += p.duration;
  return t;
}

void requireStartTimeStep(const Scenario& s, const sim::TimeStepInfo& first) {
  if (first.limitedBy != "min") return;
  fail(s.accuracy.minTimeStepWhere,
       "accuracy.min_time_step = " + formatNumber(s.accuracy.minTimeStep, 3) +
           " s is longer than the time step this scene needs at its start (" +
           formatNumber(first.wanted, 3) + " s, the " + first.wantedBy +
           " limit): every step would be too long to be stable",
       "lower accuracy.min_time_step below " + formatNumber(first.wanted, 3) +
           " s (the presets use 1e-7 s), or remove it");
}

bool isImplicitSolver(const std::string& solver) {
  return solver == "dfsph" || solver == "indsph" || solver == "iisph";
}

namespace {

Scenario assemble(const Protocol& p, const ScenarioOptions& options) {
  Scenario s;
  s.title = p.title ? p.title->value : p.file.filename().string();

  // Accuracy: the protocol's values, or a preset chosen on the command line.
  const AccuracySpec& a = p.accuracy;
  if (options.accuracy) {
    const AccuracyPresetValues& v = kAccuracyPresets[static_cast<std::size_t>(*options.accuracy)];
    s.accuracy = {std::string(v.name), v.particleSpacing, v.solverTolerance,
                  v.minTimeStep,       v.maxTimeStep,     {}};
  } else {
    s.accuracy = {std::string(toString(a.preset.value)),
                  a.particleSpacing.value,
                  a.solverTolerance.value,
                  a.minTimeStep.value,
                  a.maxTimeStep.value,
                  {}};
  }
  s.accuracy.minTimeStepWhere =
      a.minTimeStep.where.isInFile() ? a.minTimeStep.where : spacingSource(p);
  const double d = s.accuracy.particleSpacing;  // [m]
  if (d > 1.001 * draftPreset().particleSpacing) s.notes.push_back(coarseSpacingNote(d));

  // Schedule.
  for (const Posture& posture : p.schedule.postures)
    s.schedule.push_back({posture.label.value,
                          gravityOf(posture, p.schedule.gravity.value),
                          posture.duration.value,
                          posture.untilSteady,
                          {},
                          posture.equilibrium});
  if (s.schedule.empty())
    fail(p.file.empty() ? SourceLocation{} : SourceLocation{p.file.string(), 0, 0},
         "the schedule has no postures", "add at least one [[schedule.postures]]");

  buildCavity(p, s);
  checkMemory(p, options, s, d);

  // Phases: [0] aqueous, [1] tamponade.
  s.phases.push_back(phaseFromLibrary("aqueous", false));
  s.phases.push_back(tamponadePhase(p.tamponade));
  FluidPhase& aqueous = s.phases[0];
  FluidPhase& oil = s.phases[1];

  // World.
  sim::WorldParameters wp;
  wp.particleSpacing = d;
  wp.gravity = s.schedule.front().gravity;
  wp.minTimeStep = s.accuracy.minTimeStep;
  wp.maxTimeStep = s.accuracy.maxTimeStep;
  wp.stopBelowMinTimeStep = true;  // accuracy.min_time_step: "the run stops as unstable"
  Eigen::AlignedBox3d bounds;
  for (const auto& v : s.cavity.vertices) bounds.extend(v);
  const double pad = 4.0 * wp.supportRadiusFactor * d + tissueDomainPadding(p, d);  // [m]
  wp.domain =
      sim::Box(bounds.min() - sim::Vec3::Constant(pad), bounds.max() + sim::Vec3::Constant(pad));
  s.world = std::make_unique<sim::World>(wp);
  s.world->gravity = wp.gravity;
  try {
    for (FluidPhase* phase : {&aqueous, &oil}) {
      sim::Material m;
      m.name = phase->material;
      m.restDensity = phase->density;
      m.dynamicViscosity = phase->dynamicViscosity;
      phase->materialIndex = s.world->materials.add(m);
    }
  } catch (const sim::SimError& error) {
    fail(p.tamponade.agent.where, error.what(), "check the tamponade's properties");
  }

  const meshing::SurfaceSamples retinaSamples = buildWalls(p, s, options.wallSpacingFactor * d);
  recordRetinaSamples(s, retinaSamples.points, retinaSamples.normals);  // tissue_particles.h
  addTissues(p, s);  // elastic sclera / orbital fat replace the wall they cover
  s.layeredWalls = chooseLayeredWalls(p, options, s);
  if (s.layeredWalls) replaceWithLayeredWalls(s, d);
  const bool layered = s.layeredWalls;

  // Interface physics data: the stage rules switch interfacial tension and wall
  // adhesion on when both phases are present (sim::effectRegistry()).
  if (oil.interfacialTension && *oil.interfacialTension > 0.0) {
    s.world->materials.setInterfacialTension(aqueous.materialIndex, oil.materialIndex,
                                             *oil.interfacialTension);
    if (oil.contactAngleThroughAqueous) {
      std::vector<int> tags(s.world->walls.tag.begin(), s.world->walls.tag.end());
      std::sort(tags.begin(), tags.end());
      tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
      for (const int tag : tags)
        s.world->materials.setContactAngle(aqueous.materialIndex, tag,
                                           *oil.contactAngleThroughAqueous);
      if (const std::string note = contactAngleRangeNote(180.0 - *oil.contactAngleThroughAqueous);
          !note.empty())
        s.notes.push_back(note);
      // Tagged tissue (tissue_particles.cpp) is the retina over an elastic sclera.
      s.notes.push_back(contactAngleWallModelNote(
          sim::findWettedSurfaceField(s.world->particles) != nullptr ? RetinaWall::kElasticSclera
          : layered                                                  ? RetinaWall::kLayered
                                                                     : RetinaWall::kSingleLayer));
    }
  }

  // Fluids: fill plane under the first posture's gravity; a lighter tamponade floats.
  const sim::Vec3 down = s.schedule.front().gravity.normalized();
  const sim::Vec3 oilSide = oil.density < aqueous.density ? sim::Vec3(-down) : down;
  const meshing::FillPlane plane =
      meshing::findFillPlane(s.cavity, p.tamponade.fill.value, oilSide);
  meshing::VolumeSamplingOptions vo;
  vo.spacing = d;
  const bool relaxed = options.massRule == MassRule::kRelaxedFill;
  vo.wallGap = layered ? 0.0 : options.wallGapFactor.value_or(relaxed ? 0.65 : 1.2) * d;
  oil.volume = plane.volumeAbove;
  aqueous.volume = plane.volumeBelow;
  std::vector<sim::Vec3> oilPoints, aqueousPoints;
  if (options.massRule != MassRule::kTrueMass) {
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
      (k < nOil ? oilPoints : aqueousPoints).push_back(lattice[order[k]]);
  } else {
    meshing::PhaseSamples samples = meshing::sampleFillPhases(s.cavity, plane, vo);
    oilPoints = std::move(samples.above);
    aqueousPoints = std::move(samples.below);
  }
  oil.count = oilPoints.size();
  aqueous.count = aqueousPoints.size();
  if (oil.count == 0)
    fail(p.tamponade.fill.where,
         "the fill " + std::to_string(p.tamponade.fill.value) +
             " leaves the tamponade without "
             "particles at spacing " +
             std::to_string(d * 1e3) + " mm",
         "raise the fill or use a finer accuracy preset");
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
  for (const auto& x : aqueousPoints)
    s.world->particles.add(x, sim::Vec3::Zero(), aqueous.particleMass, aqueous.materialIndex);
  for (const auto& x : oilPoints)
    s.world->particles.add(x, sim::Vec3::Zero(), oil.particleMass, oil.materialIndex);
  if (aqueous.count == 0 || oil.count == 0)
    s.notes.push_back("one fluid only: no oil/aqueous interface");
  chooseGravityReference(options, s);

  // Pipeline options: solver by name, effects forced by the protocol.
  s.pipelineOptions.solver = std::string(toString(p.solver.value));
  bool known = false;
  for (const auto& entry : sim::solverRegistry())
    known = known || entry.name == s.pipelineOptions.solver;
  // A protocol that names no solver gets the format's default, INDSPH (the paper's method). It
  // needs the fill at rest density (MassRule::kRelaxedFill); with the older, compressed fill
  // rules only WCSPH starts the scene, so they fall back to it with a note.
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
    fail(p.solver.where, "solver '" + s.pipelineOptions.solver + "' is not in this build",
         "use one of: " + names);
  }
  // The cavity is filled with oil and aqueous: no free surface (background_pressure's rule).
  s.pipelineOptions.closedDomain = sim::Force::kOn;
  switch (p.accuracy.surfaceStress.value) {
    case SurfaceStressName::kAuto:
      s.pipelineOptions.surfaceStress = sim::SurfaceStressForm::kAuto;
      break;
    case SurfaceStressName::kCorrected:
      s.pipelineOptions.surfaceStress = sim::SurfaceStressForm::kCorrected;
      break;
    case SurfaceStressName::kSymmetric:
      s.pipelineOptions.surfaceStress = sim::SurfaceStressForm::kSymmetric;
      break;
  }
  // accuracy.solver_tolerance is the mean relative density error every implicit pressure solve
  // stops at (each within its own iteration cap); the explicit solvers have no solve to stop.
  s.pipelineOptions.dfsph.densityTolerance = s.accuracy.solverTolerance;
  s.pipelineOptions.dfsph.divergenceTolerance = s.accuracy.solverTolerance;
  s.pipelineOptions.indsph.tolerance = s.accuracy.solverTolerance;
  s.pipelineOptions.iisph.tolerance = s.accuracy.solverTolerance;
  // INDSPH's Jacobi relaxation. The engine's 0.5 (IISPH's choice) under-relaxes the eye's closed,
  // layered cavity: on tiny.toml (docs/methods/solvers.md) it took 30.8 iterations per step
  // at 0.1 % and stalled at 0.022 % when asked for 0.01 % (every step at the 100-iteration cap);
  // 0.8 takes 18.9 and reaches 0.0102 % (2 % of steps at the cap) in the same 603 steps. 0.9 and
  // 1.0 iterate less still, but 0.9 needed 4 % more steps at 0.01 % and a full warm start (1.0)
  // blew up: 0.8 keeps a margin. Tested: tests/protocols/test_solver_tolerance.cpp.
  s.pipelineOptions.indsph.relaxation = kEyeIndsphRelaxation;
  // WCSPH: c = 10 x the free-fall speed over the cavity, sqrt(2 g L), bounds density errors near
  // 1 % (Becker & Teschner 2007, sec. 4); flows in the eye are far slower than free fall.
  const double extent = (bounds.max() - bounds.min()).maxCoeff();  // [m]
  s.pipelineOptions.wcsph.speedOfSound = 10.0 * std::sqrt(2.0 * p.schedule.gravity.value * extent);
  for (std::size_t k = 0; k < kEffectNames.size(); ++k) {
    const Located<EffectSetting>& setting = p.effects.settings[k];
    if (setting.value == EffectSetting::kAuto) continue;
    const std::string name(kEffectNames[k]);
    bool registered = false;
    for (const auto& entry : sim::effectRegistry()) registered = registered || entry.name == name;
    if (!registered) {
      if (setting.value == EffectSetting::kOn)
        fail(setting.where,
             "effect '" + name + "' is forced on but this build does not have it yet",
             "remove the line or set it to \"auto\"");
      s.notes.push_back("effect '" + name + "' forced off: this build does not have it anyway");
      continue;
    }
    s.pipelineOptions.forced[name] =
        setting.value == EffectSetting::kOn ? sim::Force::kOn : sim::Force::kOff;
  }

  try {
    s.world->initialize();
  } catch (const sim::SimError& error) {
    fail(p.accuracy.particleSpacing.where, error.what(), "check the accuracy settings");
  }
  if (layered && oil.count + aqueous.count > 0) {
    // Fluid and wall are one lattice: no shifting pass is needed; the start's density is measured.
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
    s.notes.push_back(
        "fluid fill: the lattice points inside the cavity at rest mass rho d^3 hold " +
        percent(s.heldVolumeRatio) +
        " % of the cavity, one lattice with the layered "
        "wall behind them: density at t = 0 is " +
        percentOneDecimal(s.startMeanFraction) + " % of rest on average, " +
        percentOneDecimal(s.startMaxFraction) + " % at most");
  } else if (relaxed && oil.count + aqueous.count > 0) {
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
  resolveOutputFields(p, s);
  return s;
}

}  // namespace

Scenario assembleScenario(const Protocol& p, const ScenarioOptions& options) {
  // Sampling and the engine refuse what they cannot build (a domain with no fluid, a spacing the
  // sampler cannot resolve) without knowing the protocol: name the line that chose the spacing,
  // the setting such failures depend on.
  try {
    return assemble(p, options);
  } catch (const meshing::MeshError& error) {
    fail(spacingSource(p), std::string("the scene cannot be assembled: ") + error.what(),
         "check the eye's size and accuracy.particle_spacing (an eye needs a spacing well below "
         "its size)");
  } catch (const sim::SimError& error) {
    fail(spacingSource(p), std::string("the scene cannot be assembled: ") + error.what(),
         "check the eye's size and accuracy.particle_spacing (an eye needs a spacing well below "
         "its size)");
  }
}

}  // namespace protocols
