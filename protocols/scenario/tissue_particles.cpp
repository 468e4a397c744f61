#include "protocols/scenario/tissue_particles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "anatomy/anatomy_error.h"
#include "anatomy/material_library.h"
#include "anatomy/orbital_fat.h"
#include "anatomy/sclera_shell.h"
#include "meshing/mesh_error.h"
#include "meshing/mesh_query.h"
#include "meshing/sample_shell.h"
#include "meshing/sample_volume.h"
#include "protocols/format/protocol_error.h"
#include "protocols/report/report_format.h"
#include "protocols/scenario/point_grid.h"
#include "protocols/scenario/scenario.h"
#include "sim/boundary/wetted_surface.h"
#include "sim/core/error.h"
#include "sim/solid/elasticity_peer2018.h"
#include "sim/solid/fixed_particles.h"

namespace protocols {
namespace {

[[noreturn]] void fail(const SourceLocation& where, const std::string& what,
                       const std::string& fix) {
  throw ProtocolError({Diagnostic{where, what, fix}});
}

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
  const PointGrid wallGrid(std::vector<sim::Vec3>(walls.x.begin(), walls.x.end()), 2.0 * d);
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

}  // namespace

std::string TissueBody::describe() const {
  std::ostringstream s;
  s << name << " (E " << formatNumber(youngsModulus * 1e-3, 4) << " kPa, t " << mm(thickness)
    << ", load " << formatNumber(loadPressure, 3)
    << " Pa): " << (decision.elastic ? "elastic" : "rigid") << ", " << decision.reason;
  if (decision.elastic && count > 0) {
    s << "; " << count << " particles, " << anchored << " anchored";
    if (simulatedModulus != youngsModulus)
      s << "; layer thickened to " << mm(layerThickness) << " (2 particle layers), E scaled to "
        << formatNumber(simulatedModulus * 1e-3, 4) << " kPa to keep the membrane stiffness E t";
  }
  return s.str();
}

bool RetinaSamples::moves() const {
  return std::any_of(followsId.begin(), followsId.end(), [](std::int32_t id) { return id >= 0; });
}

double tissueDomainPadding(const Protocol& p, double d) {
  double pad = 0.0;  // [m]
  if (p.eye.sclera || p.eye.orbitalFat)
    pad += std::max(1.5e-3, kMinTissueLayerSpacings * d) + (kBackstopGapSpacings + 1.0) * d;
  // The fat, and the bony orbit up to (kOrbitGapSpacings + 1) d beyond its outermost particles.
  if (p.eye.orbitalFat)
    pad += anatomy::OrbitalFatParameters{}.thickness + (kOrbitGapSpacings + 1.0) * d;
  return pad;
}

void recordRetinaSamples(Scenario& s, const std::vector<sim::Vec3>& points,
                         const std::vector<sim::Vec3>& normals) {
  s.retinaSamples.restPositions = points;
  s.retinaSamples.normals = normals;
  s.retinaSamples.followsId.assign(points.size(), -1);
}

namespace {

// The lens/IOL cap's rim, where the collar starts: a cap wall particle within 1.5 d of a sclera
// particle, or within kCapRimSpacings d of a wall sample over the sclera (the cap's edge on the
// cavity surface). The first alone followed the sclera lattice's staircase and left stretches of
// the rim 1.7 d long without a collar (a hole 2.5 d wide at the anterior-inferior limbus).
bool onCapRim(const sim::Vec3& x, const PointGrid& scleraGrid, const PointGrid& coveredGrid,
              double d) {
  return scleraGrid.anyWithin(x, 1.5 * d) || coveredGrid.anyWithin(x, kCapRimSpacings * d);
}

// Wall particles in the fan from the collar's end to the backstop point: at most d/2 apart along
// the arc (angle x depth) and along the chord between the ends (the collar's foot and the
// backstop's sample are up to 4 d apart on the surface, which the arc alone did not count).
int fanPieces(const sim::Vec3& collarEnd, const sim::Vec3& backstopPoint, double angle,
              double depth, double d) {
  const double length = std::max(angle * depth, (backstopPoint - collarEnd).norm());  // [m]
  return static_cast<int>(std::ceil(length / (0.5 * d)));
}

// [1] fillShellGaps adds a lattice point when no shell wall lies within this many spacings.
// Measured on the paper eye (d = 1.2 mm, widest opening by enclosure.h): 0.5 left 0.61 d (734
// walls), 0.4 leaves 0.58 d (1861), 0.3 also 0.58 d (3424): the rest is the backstop's own
// spacing. The rigid cavity wall's widest is 0.50 d.
constexpr double kShellFillSpacings = 0.4;

// What fillShellGaps needs of the assembly.
struct ShellGapInput {
  const std::vector<sim::Vec3>& covered;    // cavity wall samples over the sclera
  const std::vector<double>& coveredLayer;  // [m] their sampled sclera layer
  const std::vector<int>& coveredTag;
  const std::vector<sim::Vec3>& freeSclera;  // free sclera particles at rest
  const std::vector<sim::Vec3>& fat;         // elastic fat particles (empty: none)
  double d;                                  // [m]
};

// Fills the openings of the wall shell behind the sclera (backstop, collar, fan in `added`): the
// shell is the surface at depth t_layer + kBackstopGapSpacings d from the cavity wall, over the
// sclera and over the cap within 4 d of it (there the offset of the cap/sclera crease, the wedge
// the fan approximates). Points of a d/2 lattice within d/4 of that surface get a wall particle
// when no wall of the shell lies within kShellFillSpacings d of them; like the backstop, none
// within 2 d of a free sclera or a fat particle (the fat holds the globe there, the orbit encloses
// it). Normals point away from the cavity. Returns how many it added.
std::size_t fillShellGaps(const meshing::TriangleMesh& cavityMesh, const ShellGapInput& in,
                          std::vector<sim::Vec3>& added, std::vector<sim::Vec3>& addedNormal,
                          std::vector<int>& addedTag) {
  const double d = in.d, h = 0.5 * d;
  const meshing::MeshQuery cavity(cavityMesh);
  const PointGrid coveredGrid(in.covered, 4.0 * d);
  const PointGrid shellGrid(added, d);
  const PointGrid freeGrid(in.freeSclera, 2.0 * d);
  const PointGrid fatGrid(in.fat, 2.0 * d);
  double deepest = 0.0;  // [m]
  Eigen::AlignedBox3d box;
  for (std::size_t k = 0; k < in.covered.size(); ++k) {
    box.extend(in.covered[k]);
    deepest = std::max(deepest, in.coveredLayer[k]);
  }
  const double reach = deepest + (kBackstopGapSpacings + 1.0) * d;  // [m]
  const sim::Vec3 lo = box.min() - sim::Vec3::Constant(reach),
                  hi = box.max() + sim::Vec3::Constant(reach);
  std::vector<sim::Vec3> points, normals;
  std::vector<int> tags;
  for (double x = lo.x(); x <= hi.x(); x += h)
    for (double y = lo.y(); y <= hi.y(); y += h)
      for (double z = lo.z(); z <= hi.z(); z += h) {
        const sim::Vec3 q(x, y, z);
        // Cheap rejections first: far from the sclera, or a shell wall already close.
        if (!coveredGrid.anyWithin(q, reach) || shellGrid.anyWithin(q, kShellFillSpacings * d))
          continue;
        const sim::Vec3 foot = cavity.closestPoint(q);
        const long c = coveredGrid.nearest(foot, 4.0 * d);
        if (c < 0) continue;
        const double depth =
            in.coveredLayer[static_cast<std::size_t>(c)] + kBackstopGapSpacings * d;  // [m]
        const double r = (q - foot).norm();
        if (std::abs(r - depth) > 0.25 * d || cavity.isInside(q)) continue;
        if (freeGrid.anyWithin(q, 2.0 * d) || fatGrid.anyWithin(q, 2.0 * d)) continue;
        points.push_back(q);
        normals.push_back((q - foot) / r);
        tags.push_back(in.coveredTag[static_cast<std::size_t>(c)]);
      }
  added.insert(added.end(), points.begin(), points.end());
  addedNormal.insert(addedNormal.end(), normals.begin(), normals.end());
  addedTag.insert(addedTag.end(), tags.begin(), tags.end());
  return points.size();
}

// The limbus clamp band's interior (docs/methods/elasticity.md "The limbus band, watertight"):
// anchored sclera particles farther than the elastic stage's reference support (2.5 d) from every
// free one. They never move and enter no free particle's elastic stencil, so they act on the scene
// only as a wall does, but on the lattice at d, whose openings let fluid in (10 kPa, 0.6 s: 10
// fluid particles in the band, 0.5-1.3 d from its anchored particles, none within 1.5 d of a free
// one). `freeSclera`: the rest positions of the sclera's free (not anchored) particles.
std::vector<char> clampBandInterior(const TissueBody& sclera,
                                    const sim::DynamicParticles& particles,
                                    const std::vector<sim::Vec3>& freeSclera, double d) {
  const double support = sim::ElasticityParameters{}.supportRadiusFactor * d;  // [m]
  const PointGrid freeGrid(freeSclera, support);
  std::vector<char> interior(sclera.count, 0);
  for (std::size_t k = 0; k < sclera.count; ++k)
    interior[k] = sim::isFixed(particles, static_cast<std::size_t>(sclera.firstId) + k) &&
                  !freeGrid.anyWithin(sclera.restPositions[k], support);
  return interior;
}

// [1] the band is walled within this many spacings of the cavity surface: its face, where fluid
// enters (the sclera's innermost lattice layer lies d/2 to 1.37 d deep). Walling its whole
// interior (1948 walls instead of 328 at d = 1.2 mm) kept the fluid out of the band too but the
// 10 kPa run gave way at the posterior sclera/fat interface at 0.4 s (docs/methods/elasticity.md).
constexpr double kBandFaceSpacings = 1.5;

// Walls the band's face like the cavity wall: wall particles on a d/2 lattice at the points
// within kBandFaceSpacings d of the cavity surface (outside it) whose nearest sclera particle
// (within d) is a band particle. The anchored particles stay (the walls lie among them); the
// walls keep 2 d (the kernel's support) from every free sclera particle and from every other
// anchored one that has a free particle within 2 d: INDSPH gives an anchored particle its own
// stiffness, so a wall inside its support raises its number density and it pushes its free
// neighbours (measured on the 2 MPa sclera test, 10 ms: 0.43 mm without this second rule, bound
// 4 um). Normals point away from the cavity. Returns how many it added.
std::size_t wallClampBand(const meshing::TriangleMesh& cavityMesh, const ShellGapInput& in,
                          const std::vector<sim::Vec3>& scleraRest,
                          const std::vector<char>& interior, std::vector<sim::Vec3>& added,
                          std::vector<sim::Vec3>& addedNormal, std::vector<int>& addedTag) {
  const double d = in.d, h = 0.5 * d;
  Eigen::AlignedBox3d box;
  for (std::size_t k = 0; k < scleraRest.size(); ++k)
    if (interior[k]) box.extend(scleraRest[k]);
  if (box.isEmpty()) return 0;
  const meshing::MeshQuery cavity(cavityMesh);
  const PointGrid scleraGrid(scleraRest, d);
  const PointGrid freeGrid(in.freeSclera, 2.0 * d);
  const PointGrid coveredGrid(in.covered, 4.0 * d);
  std::vector<sim::Vec3> touching;  // kept sclera particles with a free one within 2 d
  for (std::size_t k = 0; k < scleraRest.size(); ++k)
    if (!interior[k] && freeGrid.anyWithin(scleraRest[k], 2.0 * d))
      touching.push_back(scleraRest[k]);
  const PointGrid touchingGrid(touching, 2.0 * d);
  const sim::Vec3 lo = box.min() - sim::Vec3::Constant(d), hi = box.max() + sim::Vec3::Constant(d);
  std::size_t count = 0;
  for (double x = lo.x(); x <= hi.x(); x += h)
    for (double y = lo.y(); y <= hi.y(); y += h)
      for (double z = lo.z(); z <= hi.z(); z += h) {
        const sim::Vec3 q(x, y, z);
        const long k = scleraGrid.nearest(q, d);
        if (k < 0 || !interior[static_cast<std::size_t>(k)] || freeGrid.anyWithin(q, 2.0 * d) ||
            cavity.isInside(q))
          continue;
        if (touchingGrid.anyWithin(q, 2.0 * d)) continue;
        const sim::Vec3 foot = cavity.closestPoint(q);
        if ((q - foot).norm() > kBandFaceSpacings * d) continue;
        const sim::Vec3 out =
            (q - foot).norm() > 0.0 ? sim::Vec3((q - foot).normalized()) : sim::Vec3::UnitZ();
        const long c = coveredGrid.nearest(foot, 4.0 * d);
        added.push_back(q);
        addedNormal.push_back(out);
        addedTag.push_back(c >= 0 ? in.coveredTag[static_cast<std::size_t>(c)] : 0);
        ++count;
      }
  return count;
}

}  // namespace

void addTissues(const Protocol& p, Scenario& s) {
  const EyeSpec& e = p.eye;
  if (!e.sclera && !e.orbitalFat) return;
  const double d = s.accuracy.particleSpacing;                                       // [m]
  const double radius = std::cbrt(3.0 * s.cavityVolume / (4.0 * std::numbers::pi));  // [m]
  const double load = sceneLoadPressure(p, s, radius);                               // [Pa]

  // Imported meshes have no anatomy to place a sclera or a fat pad on.
  if (!s.eye) {
    for (const std::optional<TissueSpec>* spec : {&e.sclera, &e.orbitalFat}) {
      if (!*spec) continue;
      const TissueSpec& t = **spec;
      const std::string name = spec == &e.sclera ? "sclera" : "orbital fat";
      if (t.mode.value == TissueMode::kElastic)
        fail(t.mode.where,
             "mode = \"elastic\" for the " + name +
                 ", but an imported mesh cavity has "
                 "no anatomy to sample the " +
                 name + " from",
             "use a parametric eye (kind = \"emmetropic\", \"myopic\" or \"staphyloma\") or set "
             "mode = \"rigid\"");
      s.notes.push_back(name + ": not sampled on an imported mesh cavity (no anatomy); rigid wall");
    }
    return;
  }

  // The sclera's anatomy (also the fat's inner face).
  anatomy::ScleraThicknessProfile profile;
  if (e.sclera && e.sclera->thickness) {
    const double t = e.sclera->thickness->value;
    profile = {t, t, t, t, t};
  }
  std::optional<anatomy::ScleraShell> shell;
  try {
    shell.emplace(*s.eye, profile);
  } catch (const anatomy::AnatomyError& error) {
    fail(e.sclera->thickness->where, error.what(), "give a scleral thickness of at most 1.5 mm");
  }
  const double thinnest = std::min({profile.limbus, profile.oraSerrata, profile.equator,
                                    profile.midEquatorPole, profile.posteriorPole});  // [m]
  const anatomy::OrbitalFatParameters fatParameters;
  const auto decide = [&](TissueBody& t, const TissueSpec& spec) {
    t.loadPressure = load;
    try {
      // An anchored far face (the sclera's outer surface, the fat's back face) leaves the layer
      // only its compression; a free one lets it stretch as a membrane around the cavity.
      const bool anchoredFarFace = spec.anchoring.value != Anchoring::kNone;
      t.estimatedDisplacement =
          anchoredFarFace
              ? sim::estimateAnchoredLayerCompression(load, t.thickness, t.youngsModulus)
              : sim::estimateTissueDeformation(load, radius, t.thickness, t.youngsModulus);
      t.decision = sim::decideElastic(t.estimatedDisplacement, d, choiceOf(spec.mode.value));
      t.decision.reason = (anchoredFarFace ? "anchored layer compressed, u = p t / E; "
                                           : "free membrane, u = p R^2 / (2 E t); ") +
                          t.decision.reason;
    } catch (const sim::SimError& error) {
      fail(spec.youngsModulus ? spec.youngsModulus->where : spec.where, error.what(),
           "give a positive Young's modulus");
    }
  };

  std::optional<std::size_t> scleraIndex;
  // An elastic sclera held at its outer surface gets a rigid backstop wall behind it (below).
  bool scleraBackstop = false;
  std::vector<double> scleraLayer;  // [m] sampled thickness per retina sample (0 on the cap)
  // Sampled sclera layer at the wall point nearest q: anatomical, at least
  // kMinTissueLayerSpacings d (see the header); 0 on the lens/IOL cap.
  const auto layerAt = [&](const sim::Vec3& q) {
    const double anatomical = shell->thicknessAt(q);
    return anatomical > 0.0 ? std::max(anatomical, kMinTissueLayerSpacings * d) : 0.0;
  };
  if (e.sclera) {
    TissueBody t = tissueFromSpec(*e.sclera, "sclera");
    t.thickness = thinnest;
    decide(t, *e.sclera);
    if (t.decision.elastic) {
      const double minLayer = kMinTissueLayerSpacings * d;  // [m]
      double area = 0.0, tArea = 0.0, layerArea = 0.0;
      for (std::size_t w = 0; w < s.retinaSamples.restPositions.size(); ++w) {
        const double anatomical = shell->thicknessAt(s.retinaSamples.restPositions[w]);
        if (anatomical <= 0.0) continue;
        area += s.retina.areas[w];
        tArea += s.retina.areas[w] * anatomical;
        layerArea += s.retina.areas[w] * std::max(anatomical, minLayer);
      }
      t.layerThickness = area > 0.0 ? layerArea / area : minLayer;
      t.simulatedModulus = area > 0.0 ? t.youngsModulus * tArea / layerArea : t.youngsModulus;
      meshing::ShellSamplingOptions o;
      o.spacing = d;
      o.thickness = layerAt;
      meshing::ShellSamples samples;
      try {
        samples = meshing::sampleShell(s.cavity, o);
      } catch (const meshing::MeshError& error) {
        fail(e.sclera->where, error.what(), "check the sclera's thickness");
      }
      if (samples.points.empty())
        fail(e.sclera->where, "the sclera gets no particle at spacing " + mm(d),
             "use a finer accuracy preset or mode = \"rigid\"");
      std::vector<char> anchored(samples.points.size(), 0);
      if (e.sclera->anchoring.value == Anchoring::kOuterSurface) {
        anchored = samples.isOuter;
        scleraBackstop = true;
      }
      addParticles(s, t, samples.points, anchored, d);
      const std::size_t wetted = tagWettedRetina(s, t, samples, d);
      if (s.phases[1].contactAngleThroughAqueous)
        s.notes.push_back(
            "the retina over the elastic sclera is the sclera's fluid-facing layer: its " +
            std::to_string(wetted) +
            " particles within 1.5 particle spacings of the cavity wall carry the contact angle, "
            "as the wall particles they replace did");
      if (t.simulatedModulus != t.youngsModulus)
        s.notes.push_back("sclera thinner than " + formatNumber(kMinTissueLayerSpacings, 2) +
                          " particle spacings: sampled as a " + mm(t.layerThickness) +
                          " layer with E scaled to keep E t (bending stiffness and mass per area "
                          "over-estimated)");
      if (t.anchored == 0)
        s.notes.push_back(
            "sclera: no particle anchored (anchoring = \"none\"): only the fluid and "
            "the fat hold it");
      scleraLayer.resize(s.retinaSamples.restPositions.size());
      for (std::size_t w = 0; w < scleraLayer.size(); ++w)
        scleraLayer[w] = layerAt(s.retinaSamples.restPositions[w]);
    }
    scleraIndex = s.tissues.size();
    s.tissues.push_back(std::move(t));
  }

  if (e.orbitalFat) {
    TissueBody t = tissueFromSpec(*e.orbitalFat, "orbital fat");
    t.thickness = fatParameters.thickness;
    decide(t, *e.orbitalFat);
    // The fat touches the fluid only through the sclera: behind a rigid (or absent) sclera it
    // cannot change the cavity, so "auto" keeps it rigid whatever its own estimate.
    const bool scleraElastic = scleraIndex && s.tissues[*scleraIndex].decision.elastic;
    if (!scleraElastic && e.orbitalFat->mode.value == TissueMode::kAuto && t.decision.elastic) {
      t.decision.elastic = false;
      t.decision.reason =
          "behind a rigid sclera the fat cannot change the cavity, treated as "
          "rigid (alone: " +
          t.decision.reason + ")";
    }
    if (t.decision.elastic) {
      t.layerThickness = t.thickness;
      t.simulatedModulus = t.youngsModulus;
      const anatomy::OrbitalFat fat = anatomy::makeOrbitalFat(*shell, fatParameters);
      meshing::VolumeSamplingOptions o;
      o.spacing = d;
      o.wallGap = 0.5 * d;
      const std::vector<sim::Vec3> lattice = meshing::sampleVolume(fat.mesh, o);
      // Keep the points outside the sampled sclera layer; anchor the back-face layer.
      const meshing::MeshQuery cavity(s.cavity);
      const bool scleraSampled = !scleraLayer.empty();
      const double minLayer = kMinTissueLayerSpacings * d;
      std::vector<sim::Vec3> points;
      std::vector<char> anchored;
      for (const sim::Vec3& x : lattice) {
        const sim::Vec3 q = cavity.closestPoint(x);
        const double r = (x - q).norm();  // [m] from the cavity wall
        const double anatomical = shell->thicknessAt(q);
        // From the sclera's outer surface on, without a gap: both are points of the one lattice, so
        // the fat's front continues the sclera's outer layer at rest spacing (a gap there is a p =
        // 0 free surface inside the pressurised globe, which drew fluid through the sclera).
        if (scleraSampled && r <= std::max(anatomical, minLayer)) continue;
        points.push_back(x);
        anchored.push_back(e.orbitalFat->anchoring.value == Anchoring::kBackFace &&
                           r > anatomical + fatParameters.thickness - d);
      }
      if (points.empty())
        fail(e.orbitalFat->where, "the orbital fat gets no particle at spacing " + mm(d),
             "use a finer accuracy preset or mode = \"rigid\"");
      addParticles(s, t, points, anchored, d);
      if (!scleraSampled)
        s.notes.push_back("orbital fat elastic behind a rigid sclera: it cannot change the cavity");
    }
    s.tissues.push_back(std::move(t));
  }

  // Walls over elastic sclera are replaced by it; their retina samples follow the nearest sclera
  // particle (brute force: W x N_sclera distance checks, ~1e8 at the standard preset, < 1 s).
  if (scleraIndex && s.tissues[*scleraIndex].decision.elastic) {
    TissueBody& sclera = s.tissues[*scleraIndex];
    RetinaSamples& r = s.retinaSamples;
    r.scleraLayer = scleraLayer;
    const long n = static_cast<long>(r.restPositions.size());
#pragma omp parallel for schedule(static)
    for (long w = 0; w < n; ++w) {
      const auto k = static_cast<std::size_t>(w);
      if (scleraLayer[k] <= 0.0) continue;
      double best = 1e300;
      std::size_t nearest = 0;
      for (std::size_t j = 0; j < sclera.count; ++j) {
        const double dist = (sclera.restPositions[j] - r.restPositions[k]).squaredNorm();
        if (dist < best) best = dist, nearest = j;
      }
      r.followsId[k] = sclera.firstId + static_cast<std::int32_t>(nearest);
    }
    // The lens/IOL cap keeps its wall; the wall over an anchored sclera moves behind it (backstop),
    // kBackstopGapSpacings d beyond the layer's outer surface: within the kernel's support of the
    // outer (anchored) layer, outside that of every free particle.
    sim::WallParticles& walls = s.world->walls;
    // Where elastic fat lies behind the sclera, it holds the globe: no backstop there.
    std::vector<sim::Vec3> fat;
    for (const TissueBody& t : s.tissues)
      if (t.name == "orbital fat" && t.decision.elastic)
        fat.insert(fat.end(), t.restPositions.begin(), t.restPositions.end());
    const PointGrid fatGrid(fat, 2.0 * d);
    const auto nearFat = [&](const sim::Vec3& x) { return fatGrid.anyWithin(x, 2.0 * d); };
    std::vector<sim::Index> keep;
    std::vector<sim::Vec3> added, addedNormal;  // backstop, then collar, then orbit
    std::vector<int> addedTag;
    std::vector<sim::Vec3> covered;  // wall points over the sclera (for the rim's layer and tags)
    std::vector<double> coveredLayer;
    std::vector<sim::Vec3> coveredNormal;
    std::vector<int> coveredTag;
    for (std::size_t w = 0; w < walls.size(); ++w) {
      const double layer = layerAt(walls.x[w]);  // [m]
      if (layer <= 0.0) {
        keep.push_back(static_cast<sim::Index>(w));
        continue;
      }
      covered.push_back(walls.x[w]);
      coveredLayer.push_back(layer);
      coveredNormal.push_back(walls.normal[w]);
      coveredTag.push_back(walls.tag[w]);
      if (!scleraBackstop) continue;
      const sim::Vec3 x = walls.x[w] + (layer + kBackstopGapSpacings * d) * walls.normal[w];
      if (nearFat(x)) continue;
      added.push_back(x);
      addedNormal.push_back(walls.normal[w]);
      addedTag.push_back(walls.tag[w]);
    }
    const std::size_t backstopCount = added.size();
    // The limbus: the cap's rim walls (within 1.5 d of a sclera particle) get a collar of wall
    // particles along their normal, every d/2 from d/2 out to the backstop's depth, closing the
    // seam between the cap and the sclera layer where fluid left the globe
    // (docs/methods/elasticity.md), and a fan at that depth over to the nearest sclera column's
    // backstop point. Then every sclera particle within kLimbusClampSpacings d of a cap or collar
    // wall is anchored.
    std::size_t collarCount = 0;
    if (scleraBackstop) {
      const PointGrid scleraGrid(sclera.restPositions, 1.5 * d);
      const PointGrid coveredGrid(covered, d);
      std::vector<sim::Vec3> clamp;  // cap and collar walls
      for (const sim::Index w : keep) {
        const sim::Vec3& x = walls.x[w];
        clamp.push_back(x);
        if (!onCapRim(x, scleraGrid, coveredGrid, d)) continue;
        const long c = coveredGrid.nearest(x, 4.0 * d);
        const double layer =
            c >= 0 ? coveredLayer[static_cast<std::size_t>(c)] : kMinTissueLayerSpacings * d;
        const double depth = layer + kBackstopGapSpacings * d;  // [m]
        const auto put = [&](const sim::Vec3& at, const sim::Vec3& normal) {
          added.push_back(at);
          addedNormal.push_back(normal);
          addedTag.push_back(walls.tag[w]);
          clamp.push_back(at);
          ++collarCount;
        };
        for (double step = 0.5 * d; step <= depth + 1e-6 * d; step += 0.5 * d)
          put(x + step * walls.normal[w], walls.normal[w]);
        // The cap meets the globe at a crease (the lens surface and the sclera's normals differ
        // by tens of degrees), so the collar's end and the backstop's first column diverge: a fan
        // of wall particles at the backstop's depth, spacing <= d/2, closes that wedge.
        if (c < 0) continue;
        const sim::Vec3& xc = covered[static_cast<std::size_t>(c)];
        const sim::Vec3& nc = coveredNormal[static_cast<std::size_t>(c)];
        const double angle = std::acos(std::clamp(walls.normal[w].dot(nc), -1.0, 1.0));  // [rad]
        const int pieces = fanPieces(x + depth * walls.normal[w], xc + depth * nc, angle, depth, d);
        for (int k = 1; k < pieces; ++k) {
          const double f = static_cast<double>(k) / pieces;
          const sim::Vec3 normal = ((1.0 - f) * walls.normal[w] + f * nc).normalized();
          put((1.0 - f) * x + f * xc + depth * normal, normal);
        }
      }
      const PointGrid clampGrid(clamp, kLimbusClampSpacings * d);
      sim::DynamicParticles& particles = s.world->particles;
      for (std::size_t k = 0; k < sclera.count; ++k) {
        const std::size_t i = static_cast<std::size_t>(sclera.firstId) + k;  // not yet re-sorted
        if (sim::isFixed(particles, i) ||
            !clampGrid.anyWithin(sclera.restPositions[k], kLimbusClampSpacings * d))
          continue;
        sim::setFixed(particles, i);
        ++sclera.anchored;
        ++sclera.limbusClamped;
      }
    }
    // The backstop, collar and fan are samples moved off the cavity wall; where they spread (the
    // backstop's samples drift apart by (R + depth) / R outward, the fans are lines from single
    // rim particles) openings up to 0.9 d wide were left, fluid left the globe through one at
    // the anterior-inferior limbus (docs/methods/elasticity.md "The limbus band, watertight").
    std::size_t seamCount = 0, bandCount = 0;
    if (scleraBackstop) {
      std::vector<sim::Vec3> freeSclera;
      for (std::size_t k = 0; k < sclera.count; ++k)
        if (!sim::isFixed(s.world->particles, static_cast<std::size_t>(sclera.firstId) + k))
          freeSclera.push_back(sclera.restPositions[k]);
      const ShellGapInput in{covered, coveredLayer, coveredTag, freeSclera, fat, d};
      seamCount = fillShellGaps(s.cavity, in, added, addedNormal, addedTag);
      const std::vector<char> interior =
          clampBandInterior(sclera, s.world->particles, freeSclera, d);
      bandCount =
          wallClampBand(s.cavity, in, sclera.restPositions, interior, added, addedNormal, addedTag);
    }
    // The bony orbit around the fat: lattice points (spacing d/2) at [kOrbitGapSpacings,
    // kOrbitGapSpacings + 1) d from the nearest fat particle and at least 2 d from every sclera
    // particle (no wall inside a tissue particle's support), normals pointing away from the fat.
    std::size_t orbitCount = 0;
    if (!fat.empty() && scleraBackstop) {
      Eigen::AlignedBox3d box;
      for (const sim::Vec3& f : fat) box.extend(f);
      const double reach = (kOrbitGapSpacings + 1.0) * d;  // [m]
      const double h = 0.5 * d;
      const PointGrid scleraGrid(sclera.restPositions, 2.0 * d);
      const PointGrid fatReach(fat, reach);
      const PointGrid coveredGrid(covered, 4.0 * d);
      const sim::Vec3 lo = box.min() - sim::Vec3::Constant(reach),
                      hi = box.max() + sim::Vec3::Constant(reach);
      for (double x = lo.x(); x <= hi.x(); x += h)
        for (double y = lo.y(); y <= hi.y(); y += h)
          for (double z = lo.z(); z <= hi.z(); z += h) {
            const sim::Vec3 q(x, y, z);
            const long f = fatReach.nearest(q, reach);
            if (f < 0) continue;
            const sim::Vec3 away = q - fat[static_cast<std::size_t>(f)];
            if (away.norm() < kOrbitGapSpacings * d || scleraGrid.anyWithin(q, 2.0 * d)) continue;
            long c = -1;
            for (double around = 4.0 * d; c < 0 && around < 64.0 * d; around *= 2.0)
              c = coveredGrid.nearest(q, around);
            added.push_back(q);
            addedNormal.push_back(away.normalized());
            addedTag.push_back(c >= 0 ? coveredTag[static_cast<std::size_t>(c)] : 0);
            ++orbitCount;
          }
    }
    walls.fields.permute(keep);
    walls.fields.resize(keep.size());
    for (std::size_t b = 0; b < added.size(); ++b) walls.add(added[b], addedNormal[b], addedTag[b]);
    if (backstopCount > 0)
      s.notes.push_back("sclera held at its outer surface: a rigid backstop wall " +
                        formatNumber(kBackstopGapSpacings, 2) +
                        " particle spacing behind it where no orbital fat is, so no empty gap "
                        "lies behind the globe (docs/methods/elasticity.md)");
    if (bandCount > 0)
      s.notes.push_back(
          "the limbus clamp band's face walled: " + std::to_string(bandCount) +
          " wall particles at half the spacing within " + formatNumber(kBandFaceSpacings, 2) +
          " spacings of the cavity keep the fluid out of the band (docs/methods/elasticity.md)");
    if (seamCount > 0)
      s.notes.push_back("the wall shell behind the sclera closed: " + std::to_string(seamCount) +
                        " wall particles where the backstop's, collar's and fan's samples left "
                        "openings wider than the cavity wall's");
    if (collarCount > 0)
      s.notes.push_back("sclera clamped at the limbus (the rigid lens/IOL cap): " +
                        std::to_string(sclera.limbusClamped) + " sclera particles within " +
                        formatNumber(kLimbusClampSpacings, 2) +
                        " spacings of the cap or its collar (" + std::to_string(collarCount) +
                        " wall particles) anchored");
    if (orbitCount > 0)
      s.notes.push_back(
          "the bony orbit: " + std::to_string(orbitCount) + " rigid wall particles " +
          formatNumber(kOrbitGapSpacings, 2) + "-" + formatNumber(kOrbitGapSpacings + 1.0, 2) +
          " spacings around the orbital fat, so the tissue assembly is enclosed by walls");
  }
}

namespace {

// TissueMeasures::fluidInTissue / fluidThroughTissue / deepestFluid (criteria in the header).
void countFluidInTissue(const Scenario& s, const std::vector<sim::Vec3>& x,
                        const std::vector<std::int32_t>& ids, TissueMeasures& m) {
  const RetinaSamples& r = s.retinaSamples;
  const TissueBody* sclera = nullptr;
  for (const TissueBody& t : s.tissues)
    if (t.name == "sclera" && t.count > 0) sclera = &t;
  if (!sclera || r.scleraLayer.size() != r.restPositions.size()) return;
  const double d = s.accuracy.particleSpacing;  // [m]
  const auto inBody = [](const TissueBody& t, std::int32_t id) {
    return id >= t.firstId && id < t.firstId + static_cast<std::int32_t>(t.count);
  };
  std::vector<char> tissue(x.size(), 0);
  std::vector<sim::Vec3> scleraNow;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (const TissueBody& t : s.tissues)
      if (t.count > 0 && inBody(t, ids[i])) {
        tissue[i] = 1;
        if (&t == sclera) scleraNow.push_back(x[i]);
      }
  const meshing::MeshQuery cavity(s.cavity);
  const PointGrid scleraGrid(scleraNow, 1.5 * d);
  const PointGrid samples(r.restPositions, d);
  std::vector<double> depth(scleraNow.size(), std::numeric_limits<double>::quiet_NaN());
  const auto depthOf = [&](std::size_t j) {  // [m] signed: > 0 outside the rest cavity surface
    if (std::isnan(depth[j])) {
      const double dist = std::sqrt(cavity.squaredDistance(scleraNow[j]));
      depth[j] = cavity.isInside(scleraNow[j]) ? -dist : dist;
    }
    return depth[j];
  };
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (tissue[i] || cavity.isInside(x[i])) continue;
    const double depthHere = std::sqrt(cavity.squaredDistance(x[i]));  // [m]
    m.deepestFluid = std::max(m.deepestFluid, depthHere);
    const std::vector<std::size_t> near = scleraGrid.within(x[i], 1.5 * d);
    bool in = near.empty() ? depthHere > d
                           : std::any_of(near.begin(), near.end(),
                                         [&](std::size_t j) { return depthOf(j) < depthHere - d; });
    const long w = samples.nearest(cavity.closestPoint(x[i]), 2.0 * d);
    const double layer = w >= 0 ? r.scleraLayer[static_cast<std::size_t>(w)] : 0.0;  // [m]
    const bool through = depthHere > std::max(layer, d);
    in = in || through;
    m.fluidInTissue += in ? 1 : 0;
    m.fluidThroughTissue += through ? 1 : 0;
  }
}

}  // namespace

std::vector<sim::Vec3> retinaPositions(const Scenario& s, const std::vector<sim::Vec3>& x,
                                       const std::vector<std::int32_t>& ids) {
  const RetinaSamples& r = s.retinaSamples;
  std::vector<sim::Vec3> out = r.restPositions;
  if (!r.moves()) return out;
  std::vector<std::size_t> indexOfId(x.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] >= 0 && static_cast<std::size_t>(ids[i]) < indexOfId.size())
      indexOfId[static_cast<std::size_t>(ids[i])] = i;
  for (const TissueBody& t : s.tissues) {
    if (t.count == 0) continue;
    for (std::size_t w = 0; w < out.size(); ++w) {
      const std::int32_t id = r.followsId[w];
      if (id < t.firstId || id >= t.firstId + static_cast<std::int32_t>(t.count)) continue;
      const sim::Vec3 u = x[indexOfId[static_cast<std::size_t>(id)]] -
                          t.restPositions[static_cast<std::size_t>(id - t.firstId)];
      out[w] += u;
    }
  }
  return out;
}

void updateTissueDisplacement(const Scenario& s, const std::vector<sim::Vec3>& x,
                              const std::vector<std::int32_t>& ids, std::vector<sim::Vec3>& out) {
  out.assign(x.size(), sim::Vec3::Zero());
  for (const TissueBody& t : s.tissues)
    for (std::size_t i = 0; i < x.size(); ++i)
      if (ids[i] >= t.firstId && ids[i] < t.firstId + static_cast<std::int32_t>(t.count))
        out[i] = x[i] - t.restPositions[static_cast<std::size_t>(ids[i] - t.firstId)];
}

TissueMeasures measureTissues(const Scenario& s, const std::vector<sim::Vec3>& x,
                              const std::vector<std::int32_t>& ids) {
  TissueMeasures m;
  m.maxDisplacement.assign(s.tissues.size(), 0.0);
  std::vector<sim::Vec3> u;
  updateTissueDisplacement(s, x, ids, u);
  for (std::size_t k = 0; k < s.tissues.size(); ++k) {
    const TissueBody& t = s.tissues[k];
    for (std::size_t i = 0; i < x.size(); ++i)
      if (ids[i] >= t.firstId && ids[i] < t.firstId + static_cast<std::int32_t>(t.count))
        m.maxDisplacement[k] = std::max(m.maxDisplacement[k], u[i].norm());
  }
  const std::vector<sim::Vec3> now = retinaPositions(s, x, ids);
  const RetinaSamples& r = s.retinaSamples;
  std::vector<double> area(kReportedRegions.size(), 0.0), outward(kReportedRegions.size(), 0.0);
  for (std::size_t w = 0; w < now.size(); ++w) {
    const sim::Vec3 uw = now[w] - r.restPositions[w];
    const double normal = r.normals[w].dot(uw);  // [m] outward
    m.retinaMaxDisplacement = std::max(m.retinaMaxDisplacement, uw.norm());
    m.cavityVolumeChange += s.retina.areas[w] * normal;
    for (std::size_t k = 0; k < kReportedRegions.size(); ++k)
      if ((s.retina.regions[w] & kReportedRegions[k].bit) != 0) {
        area[k] += s.retina.areas[w];
        outward[k] += s.retina.areas[w] * normal;
      }
  }
  m.regionMeanOutward.resize(kReportedRegions.size());
  for (std::size_t k = 0; k < area.size(); ++k)
    m.regionMeanOutward[k] = area[k] > 0.0 ? outward[k] / area[k] : 0.0;
  countFluidInTissue(s, x, ids, m);
  return m;
}

std::vector<std::string> tissueReportLines(const Scenario& s, const TissueMeasures& last,
                                           double lastTime, double meanTimeStep) {
  std::vector<std::string> lines;
  const double d = s.accuracy.particleSpacing;
  if (s.tissues.empty()) return {"no tissue in the protocol: rigid cavity wall"};
  const bool anyElastic = std::any_of(s.tissues.begin(), s.tissues.end(),
                                      [](const TissueBody& t) { return t.decision.elastic; });
  if (!anyElastic) {
    // Each tissue with why it is rigid: below the threshold, forced, or behind a rigid sclera.
    std::ostringstream line;
    line << "tissue rigid (";
    for (std::size_t k = 0; k < s.tissues.size(); ++k) {
      const TissueBody& t = s.tissues[k];
      const double ratio = t.estimatedDisplacement / d;  // [1]
      line << (k ? "; " : "") << t.name << " estimate " << mm(t.estimatedDisplacement) << " = "
           << formatNumber(ratio, 3) << " d";
      if (t.decision.forced)
        line << ", forced rigid";
      else if (ratio < sim::kElasticDisplacementFraction)
        line << " < " << formatNumber(sim::kElasticDisplacementFraction, 2) << " d";
      else
        line << ", behind the rigid sclera";
    }
    line << ")";
    return {line.str()};
  }
  const std::string at = " at t = " + formatNumber(lastTime, 4) + " s";
  for (std::size_t k = 0; k < s.tissues.size(); ++k) {
    const TissueBody& t = s.tissues[k];
    if (!t.decision.elastic) {
      lines.push_back(t.name + ": rigid (estimate " + mm(t.estimatedDisplacement) + " = " +
                      formatNumber(t.estimatedDisplacement / d, 3) + " d)");
      continue;
    }
    const double u = k < last.maxDisplacement.size() ? last.maxDisplacement[k] : 0.0;
    lines.push_back(t.name + ": elastic, maximum displacement " + mm(u) + " = " +
                    formatNumber(u / d, 3) + " d" + at + " (estimate " +
                    mm(t.estimatedDisplacement) + ")");
    const double wdt = t.thicknessModeFrequency * meanTimeStep;  // [1]
    if (wdt > 1.0)
      lines.push_back(t.name + ": its displacement is an upper bound, up to " +
                      formatNumber(1.0 + wdt * wdt, 2) + "x the physical one: the mean step " +
                      formatNumber(meanTimeStep * 1e3, 3) +
                      " ms does not resolve the layer's thickness mode (" +
                      formatNumber(t.thicknessModeFrequency, 3) +
                      " rad/s); the coverage does not depend on it (docs/methods/elasticity.md)");
  }
  if (!s.retinaSamples.scleraLayer.empty()) {
    // Fluid that entered or passed the tissue (TissueMeasures): a leaking run says so.
    std::string line =
        "fluid in the tissue: " + std::to_string(last.fluidInTissue) +
        " particles more than d behind a sclera particle near them, " +
        std::to_string(last.fluidThroughTissue) + " beyond the sampled layer (deepest fluid " +
        formatNumber(last.deepestFluid / d, 3) + " d outside the cavity surface)" + at;
    if (last.fluidInTissue > 0)
      line = "warning: " + line + "; the tissue leaks, its numbers are suspect";
    lines.push_back(line);
  }
  lines.push_back("retina maximum displacement " + mm(last.retinaMaxDisplacement) + at);
  lines.push_back("cavity volume change " + formatNumber(last.cavityVolumeChange * 1e9, 3) +
                  " uL = " + formatNumber(100.0 * last.cavityVolumeChange / s.cavityVolume, 3) +
                  " %" + at);
  std::ostringstream regions;
  regions << "mean outward retina displacement by region:";
  for (std::size_t k = 0; k < kReportedRegions.size() && k < last.regionMeanOutward.size(); ++k)
    regions << (k ? ";" : "") << " " << kReportedRegions[k].name << " "
            << formatNumber(last.regionMeanOutward[k] * 1e6, 3) << " um";
  lines.push_back(regions.str());
  return lines;
}

}  // namespace protocols
