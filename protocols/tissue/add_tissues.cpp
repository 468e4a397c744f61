#include "protocols/tissue/add_tissues.h"

#include <cmath>
#include <numbers>

#include "anatomy/anatomy_error.h"
#include "anatomy/orbital_fat.h"
#include "meshing/mesh_error.h"
#include "meshing/mesh_query.h"
#include "meshing/sample_shell.h"
#include "meshing/sample_volume.h"
#include "protocols/report/report_format.h"
#include "protocols/scenario/scenario_error.h"
#include "protocols/tissue/sclera_walls.h"
#include "protocols/tissue/tissue_context.h"
#include "protocols/tissue/tissue_sampling.h"
#include "sim/core/error.h"

namespace protocols {

namespace {

// Imported meshes have no anatomy to place a sclera or a fat pad on: "auto" and "rigid" keep the
// wall (with a note), "elastic" is an error.
void keepRigidOnImportedMesh(const Protocol& p, Scenario& s) {
  const EyeSpec& e = p.eye;
  for (const std::optional<TissueSpec>* spec : {&e.sclera, &e.orbitalFat}) {
    if (!*spec) continue;
    const TissueSpec& t = **spec;
    const std::string name = spec == &e.sclera ? "sclera" : "orbital fat";
    if (t.mode.value == TissueMode::kElastic)
      failAt(t.mode.where,
             "mode = \"elastic\" for the " + name +
                 ", but an imported mesh cavity has "
                 "no anatomy to sample the " +
                 name + " from",
             "use a parametric eye (kind = \"emmetropic\", \"myopic\" or \"staphyloma\") or set "
             "mode = \"rigid\"");
    s.notes.push_back(name + ": not sampled on an imported mesh cavity (no anatomy); rigid wall");
  }
}

// The sclera's anatomy: the profile of the anatomy library, or the protocol's uniform thickness.
void makeScleraShell(const Protocol& p, const Scenario& s, TissueContext& c) {
  const EyeSpec& e = p.eye;
  anatomy::ScleraThicknessProfile profile;
  if (e.sclera && e.sclera->thickness) {
    const double t = e.sclera->thickness->value;
    profile = {t, t, t, t, t};
  }
  try {
    c.shell.emplace(*s.eye, profile);
  } catch (const anatomy::AnatomyError& error) {
    failAt(e.sclera->thickness->where, error.what(), "give a scleral thickness of at most 1.5 mm");
  }
  c.thinnest = std::min({profile.limbus, profile.oraSerrata, profile.equator,
                         profile.midEquatorPole, profile.posteriorPole});  // [m]
}

// Elastic or rigid, by the estimate under the scene's load unless the protocol forces it.
void decide(TissueBody& t, const TissueSpec& spec, const TissueContext& c) {
  t.loadPressure = c.load;
  try {
    // An anchored far face (the sclera's outer surface, the fat's back face) leaves the layer
    // only its compression; a free one lets it stretch as a membrane around the cavity.
    const bool anchoredFarFace = spec.anchoring.value != Anchoring::kNone;
    t.estimatedDisplacement =
        anchoredFarFace
            ? sim::estimateAnchoredLayerCompression(c.load, t.thickness, t.youngsModulus)
            : sim::estimateTissueDeformation(c.load, c.radius, t.thickness, t.youngsModulus);
    t.decision = sim::decideElastic(t.estimatedDisplacement, c.d, choiceOf(spec.mode.value));
    t.decision.reason = (anchoredFarFace ? "anchored layer compressed, u = p t / E; "
                                         : "free membrane, u = p R^2 / (2 E t); ") +
                        t.decision.reason;
  } catch (const sim::SimError& error) {
    failAt(spec.youngsModulus ? spec.youngsModulus->where : spec.where, error.what(),
           "give a positive Young's modulus");
  }
}

// The sampled layer's mean thickness and the modulus that keeps E t (tissue_body.h).
void setScleraLayer(const Scenario& s, const TissueContext& c, TissueBody& t) {
  const double minLayer = kMinTissueLayerSpacings * c.d;  // [m]
  double area = 0.0, tArea = 0.0, layerArea = 0.0;
  for (std::size_t w = 0; w < s.retinaSamples.restPositions.size(); ++w) {
    const double anatomical = c.shell->thicknessAt(s.retinaSamples.restPositions[w]);
    if (anatomical <= 0.0) continue;
    area += s.retina.areas[w];
    tArea += s.retina.areas[w] * anatomical;
    layerArea += s.retina.areas[w] * std::max(anatomical, minLayer);
  }
  t.layerThickness = area > 0.0 ? layerArea / area : minLayer;
  t.simulatedModulus = area > 0.0 ? t.youngsModulus * tArea / layerArea : t.youngsModulus;
}

// The elastic sclera's particles on the fluid's lattice, anchored as the protocol says, with the
// notes of its wetted retina, a thickened layer and a free outer face.
void sampleSclera(const Protocol& p, Scenario& s, TissueContext& c, TissueBody& t) {
  const TissueSpec& spec = *p.eye.sclera;
  const double d = c.d;
  setScleraLayer(s, c, t);
  meshing::ShellSamplingOptions o;
  o.spacing = d;
  o.thickness = [&](const sim::Vec3& q) { return c.layerAt(q); };
  meshing::ShellSamples samples;
  try {
    samples = meshing::sampleShell(s.cavity, o);
  } catch (const meshing::MeshError& error) {
    failAt(spec.where, error.what(), "check the sclera's thickness");
  }
  if (samples.points.empty())
    failAt(spec.where, "the sclera gets no particle at spacing " + mm(d),
           "use a finer accuracy preset or mode = \"rigid\"");
  std::vector<char> anchored(samples.points.size(), 0);
  if (spec.anchoring.value == Anchoring::kOuterSurface) {
    anchored = samples.isOuter;
    c.scleraBackstop = true;
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
  c.scleraLayer.resize(s.retinaSamples.restPositions.size());
  for (std::size_t w = 0; w < c.scleraLayer.size(); ++w)
    c.scleraLayer[w] = c.layerAt(s.retinaSamples.restPositions[w]);
}

void addSclera(const Protocol& p, Scenario& s, TissueContext& c) {
  TissueBody t = tissueFromSpec(*p.eye.sclera, "sclera");
  t.thickness = c.thinnest;
  decide(t, *p.eye.sclera, c);
  if (t.decision.elastic) sampleSclera(p, s, c, t);
  c.scleraIndex = s.tissues.size();
  s.tissues.push_back(std::move(t));
}

// The fat's lattice points outside the sampled sclera layer; the back-face layer anchored.
void sampleOrbitalFat(const Protocol& p, Scenario& s, const TissueContext& c, TissueBody& t,
                      const anatomy::OrbitalFatParameters& fatParameters) {
  const TissueSpec& spec = *p.eye.orbitalFat;
  const double d = c.d;
  t.layerThickness = t.thickness;
  t.simulatedModulus = t.youngsModulus;
  const anatomy::OrbitalFat fat = anatomy::makeOrbitalFat(*c.shell, fatParameters);
  meshing::VolumeSamplingOptions o;
  o.spacing = d;
  o.wallGap = 0.5 * d;
  const std::vector<sim::Vec3> lattice = meshing::sampleVolume(fat.mesh, o);
  const meshing::MeshQuery cavity(s.cavity);
  const bool scleraSampled = !c.scleraLayer.empty();
  const double minLayer = kMinTissueLayerSpacings * d;
  std::vector<sim::Vec3> points;
  std::vector<char> anchored;
  for (const sim::Vec3& x : lattice) {
    const sim::Vec3 q = cavity.closestPoint(x);
    const double r = (x - q).norm();  // [m] from the cavity wall
    const double anatomical = c.shell->thicknessAt(q);
    // From the sclera's outer surface on, without a gap: both are points of the one lattice, so
    // the fat's front continues the sclera's outer layer at rest spacing (a gap there is a p =
    // 0 free surface inside the pressurised globe, which drew fluid through the sclera).
    if (scleraSampled && r <= std::max(anatomical, minLayer)) continue;
    points.push_back(x);
    anchored.push_back(spec.anchoring.value == Anchoring::kBackFace &&
                       r > anatomical + fatParameters.thickness - d);
  }
  if (points.empty())
    failAt(spec.where, "the orbital fat gets no particle at spacing " + mm(d),
           "use a finer accuracy preset or mode = \"rigid\"");
  addParticles(s, t, points, anchored, d);
  if (!scleraSampled)
    s.notes.push_back("orbital fat elastic behind a rigid sclera: it cannot change the cavity");
}

void addOrbitalFat(const Protocol& p, Scenario& s, const TissueContext& c) {
  const anatomy::OrbitalFatParameters fatParameters;
  TissueBody t = tissueFromSpec(*p.eye.orbitalFat, "orbital fat");
  t.thickness = fatParameters.thickness;
  decide(t, *p.eye.orbitalFat, c);
  // The fat touches the fluid only through the sclera: behind a rigid (or absent) sclera it
  // cannot change the cavity, so "auto" keeps it rigid whatever its own estimate.
  const bool scleraElastic = c.scleraIndex && s.tissues[*c.scleraIndex].decision.elastic;
  if (!scleraElastic && p.eye.orbitalFat->mode.value == TissueMode::kAuto && t.decision.elastic) {
    t.decision.elastic = false;
    t.decision.reason =
        "behind a rigid sclera the fat cannot change the cavity, treated as "
        "rigid (alone: " +
        t.decision.reason + ")";
  }
  if (t.decision.elastic) sampleOrbitalFat(p, s, c, t, fatParameters);
  s.tissues.push_back(std::move(t));
}

}  // namespace

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

void addTissues(const Protocol& p, Scenario& s) {
  const EyeSpec& e = p.eye;
  if (!e.sclera && !e.orbitalFat) return;
  if (!s.eye) {
    keepRigidOnImportedMesh(p, s);
    return;
  }
  TissueContext c;
  c.d = s.accuracy.particleSpacing;
  c.radius = std::cbrt(3.0 * s.cavityVolume / (4.0 * std::numbers::pi));
  c.load = sceneLoadPressure(p, s, c.radius);
  makeScleraShell(p, s, c);
  if (e.sclera) addSclera(p, s, c);
  if (e.orbitalFat) addOrbitalFat(p, s, c);
  if (c.scleraIndex && s.tissues[*c.scleraIndex].decision.elastic) replaceWallsOverSclera(s, c);
}

}  // namespace protocols
