#include "protocols/tissue/tissue_sampling.h"

#include <algorithm>
#include <numbers>

#include "anatomy/material_library.h"
#include "meshing/point_index.h"
#include "protocols/report/report_format.h"
#include "protocols/tissue/tissue_measures.h"
#include "sim/boundary/wetted_surface.h"
#include "sim/solid/elasticity_peer2018.h"
#include "sim/solid/fixed_particles.h"

namespace protocols {

std::string mm(double metres) { return formatNumber(metres * 1e3, 3) + " mm"; }

// The tissue's material values: library, then the protocol's overrides.
TissueBody tissueFromSpec(const TissueSpec& spec, const std::string& name) {
  const anatomy::MaterialRecord& r = anatomy::MaterialLibrary::builtin().find(spec.material.value);
  TissueBody t;
  t.name = name;
  t.material = spec.material.value;
  t.youngsModulus = spec.youngsModulus ? spec.youngsModulus->value : r.youngsModulus->value;
  t.poissonRatio = spec.poissonRatio ? spec.poissonRatio->value : r.poissonRatio->value;
  t.density = spec.density ? spec.density->value : r.density->value;
  return t;
}

sim::TissueChoice choiceOf(TissueMode mode) {
  switch (mode) {
    case TissueMode::kElastic: return sim::TissueChoice::kElastic;
    case TissueMode::kRigid: return sim::TissueChoice::kRigid;
    case TissueMode::kAuto: break;
  }
  return sim::TissueChoice::kAuto;
}

// The largest pressure the scene can put on its wall [Pa]: hydrostatic over the cavity's largest
// extent with the heavier phase, plus the interface's capillary pressure 2 sigma / R.
double sceneLoadPressure(const Protocol& p, const Scenario& s, double radius) {
  Eigen::AlignedBox3d bounds;
  for (const auto& v : s.cavity.vertices) bounds.extend(v);
  const double height = (bounds.max() - bounds.min()).maxCoeff();  // [m]
  const double rho = std::max(s.phases[0].density, s.phases[1].density);
  const double sigma = s.phases[1].interfacialTension.value_or(0.0);
  return rho * p.schedule.gravity.value * height + 2.0 * sigma / radius;
}

sim::Material elasticMaterial(const TissueBody& t) {
  sim::Material m;
  m.name = t.material;
  m.kind = sim::MaterialKind::kElastic;
  m.restDensity = t.density;
  m.youngsModulus = t.simulatedModulus;
  m.poissonRatio = t.poissonRatio;
  return m;
}

void addParticles(Scenario& s, TissueBody& t, const std::vector<sim::Vec3>& points,
                  const std::vector<char>& anchored, double d) {
  sim::DynamicParticles& particles = s.world->particles;
  // Written to the frames (the per-particle displacement map), recomputed before each frame.
  particles.fields.addOrGet<sim::Vec3>({kTissueDisplacementField, "m", false, true});
  t.materialIndex = s.world->materials.add(elasticMaterial(t));
  t.thicknessModeFrequency = std::numbers::pi *
                             sim::ElasticityPeer2018::waveSpeed(elasticMaterial(t)) /
                             (2.0 * t.layerThickness);
  t.firstId = static_cast<std::int32_t>(particles.size());
  t.count = points.size();
  t.restPositions = points;
  const double mass = t.density * d * d * d;  // [kg] one lattice cube
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::size_t i = particles.size();
    particles.add(points[k], sim::Vec3::Zero(), mass, t.materialIndex);
    if (anchored[k]) {
      sim::setFixed(particles, i);
      ++t.anchored;
    }
  }
}

// The retina over an elastic sclera is the sclera's fluid-facing layer: its particles within
// 1.5 d of the cavity surface (one lattice layer, about one particle per d^2 of wall, as the wall
// sample had) carry the tag of the wall particle they replace, so wall_adhesion wets them with that
// tag's contact angle (sim/boundary/wetted_surface.h; tests/sim/interface_units.cpp, "Over a
// wetted tissue floor ..."). Before, the angle acted only on wall particles, and over the sclera
// the oil met a surface without one.
// Returns the number of particles tagged.
std::size_t tagWettedRetina(Scenario& s, const TissueBody& t, const meshing::ShellSamples& samples,
                            double d) {
  std::size_t tagged = 0;
  const sim::WallParticles& walls = s.world->walls;
  const meshing::PointIndex wallGrid(std::vector<sim::Vec3>(walls.x.begin(), walls.x.end()),
                                     2.0 * d);
  for (std::size_t k = 0; k < samples.points.size(); ++k) {
    if (samples.depth[k] >= 1.5 * d) continue;
    const long w = wallGrid.nearest(samples.points[k], 2.0 * d);
    if (w < 0) continue;
    sim::setWettedSurfaceTag(s.world->particles,
                             static_cast<sim::Index>(t.firstId) + static_cast<sim::Index>(k),
                             walls.tag[static_cast<std::size_t>(w)]);
    ++tagged;
  }
  return tagged;
}

}  // namespace protocols
