#include "protocols/assembly/cavity_walls.h"

#include <algorithm>

#include "anatomy/anatomy_error.h"
#include "anatomy/retinal_regions.h"
#include "meshing/point_index.h"
#include "protocols/assembly/layered_cavity_walls.h"
#include "protocols/scenario/scenario_error.h"
#include "sim/boundary/wall_layers.h"

namespace protocols {

namespace {

// Layers of a layered cavity wall (sim/boundary/wall_layers.h: 3 fill the kernel support).
constexpr int kCavityWallLayers = 3;

}  // namespace

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
      failAt(b.where, error.what(),
             "move the break onto the retina (posterior to the ora serrata)");
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
      failAt(model.where,
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
  const meshing::PointIndex samples(s.retinaSamples.restPositions, d);
  for (std::size_t b = 0; b < lw.positions.size(); ++b) {
    const long owner = samples.nearest(lw.positions[b], (kCavityWallLayers + 2) * d);
    const int tag =
        owner >= 0 ? static_cast<int>(s.retina.regions[static_cast<std::size_t>(owner)]) : 0;
    sim::addLayeredWallParticle(walls, lw.positions[b], lw.normals[b], tag, d * d * d, lw.layer[b]);
  }
}

}  // namespace protocols
