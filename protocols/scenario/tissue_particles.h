// Tissues of a scenario: the sclera around the cavity wall and the orbital fat behind
// the globe, each decided elastic or rigid before the run and, when elastic, sampled as dynamic
// particles of an elastic material that replace the rigid cavity wall they cover.
//
// Decision (docs/developer-guide.md principle 1, sim/solid/tissue_deformation.h): the thin-shell
// estimate u = p R^2 / (2 E t) under the largest load the scene can apply, p = rho_max g H + 2
// sigma / R (hydrostatic over the cavity's largest extent H, the heavier phase; capillary pressure
// of the oil/aqueous interface at the cavity's equivalent-sphere radius R), compared with 0.1 d,
// unless the protocol's `mode` forces elastic or rigid. The sclera is estimated at its thinnest
// anatomical thickness (or the protocol's uniform one), the fat at its layer thickness: both err
// towards "elastic".
//
// Rigid: nothing changes (the cavity wall particles stay, no tissue particles).
// Elastic sclera: meshing::sampleShell on the fluid's lattice (same origin and spacing d, so the
//   tissue's inner layer continues the fluid's lattice) between d/2 and the local thickness; its
//   outermost layer (ShellSamples::isOuter) anchored with sim::setFixed when anchoring is
//   "outer_surface". The cavity wall particles over the sclera (all but the lens/IOL cap, which
//   has no sclera) are removed: the fluid touches the tissue directly (the INDSPH paper's set-up).
//   When the outer surface is anchored they reappear kBackstopGapSpacings d behind the layer as a
//   rigid backstop (the orbit), except where elastic fat lies behind it (the fat then starts at the
//   layer's outer surface, on the same lattice: no empty gap behind the anchored layer either way).
//   The walls behind the sclera (backstop, the limbus collar and its fan) are closed where their
//   samples spread: a d/2 lattice on the same surface fills their openings, so that none is wider
//   than the cavity wall's by more than the check's resolution (docs/methods/elasticity.md "The
//   limbus band, watertight"; enclosure.h). The limbus clamp band (anchored, on the lattice at d,
//   which let fluid in) gets wall particles at d/2 on its face, away from every free sclera
//   particle. A sclera thinner than kMinTissueLayerSpacings d cannot be resolved (the elasticity
//   needs two layers for its quadratic gradients, docs/methods/elasticity.md), so the particle
//   layer is thickened to that and Young's modulus scaled by t / t_layer (area-weighted means over
//   the wall): the membrane stiffness E t, which sets a pressurised shell's displacement, is kept;
//   the bending stiffness and the areal mass are over-estimated (noted in Scenario::notes).
// Elastic fat: lattice points inside anatomy::makeOrbitalFat's cup at least d/2 from its faces
//   and outside the sampled sclera layer (r > t_layer: the lattice continues from the sclera);
//   the back-face layer (within d of the cup's outer face) anchored when anchoring is "back_face".
//
// Coverage on a moving retina: the retina samples (RetinaMap order, the cavity wall samples of
// assembly) stay the points the coverage is measured at. A sample over elastic sclera follows the
// sclera particle nearest to it at rest (x = X + u of that particle, by particle id, which
// survives the engine's re-sorting); the others stay put. So coverage is still reported on the
// retinal surface, now where the tissue has carried it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "protocols/format/protocol.h"
#include "sim/core/types.h"
#include "sim/solid/tissue_deformation.h"

namespace protocols {

struct Scenario;

// [1] thinnest sampled tissue layer in particle spacings: d/2 gap + two lattice layers.
inline constexpr double kMinTissueLayerSpacings = 2.5;
// [1] gap between an anchored sclera layer's outer surface (t_layer from the cavity) and the rigid
// backstop wall placed behind it (the orbit), in particle spacings. The outer, anchored lattice
// layer lies at depths (t_layer - d, t_layer], every free particle at most t_layer - d deep, so one
// spacing puts the wall 1-2 d from the anchored layer (inside its kernel support, as the cavity
// wall is for the fluid) and at least 2 d from every free particle (outside theirs: the wall can
// push no free particle). Two spacings left the anchored layer with no neighbour
// behind it: its number density deficient (mean 0.81 rest), INDSPH's pressure clamped at 0 there
// while the fluid next to the face read ~50 Pa, so the pressure solve drove fluid through the
// layer into the gap (10 kPa: 3 / 8 / 42 particles in the tissue at 0.1 / 0.3 / 0.6 s). Half a
// spacing (the wall within 1.5 d of the free layer) failed the 2 MPa sclera test: 207 um, bound
// 4.1 um. docs/methods/elasticity.md "Closing the gaps behind the sclera".
inline constexpr double kBackstopGapSpacings = 1.0;
// [1] the limbus clamp (docs/methods/elasticity.md "The limbus clamp and the bony orbit"): the
// sclera's anterior edge joins the cornea, here the rigid lens/IOL cap. Every sclera particle
// within this many spacings of a cap wall particle, or of the rigid collar that closes the seam
// from the cap's edge out to the backstop, is anchored, so the collar cannot push the free rim (it
// did, 0.14-0.3 mm, when those particles were free). Measured on the 2 MPa sclera test (10 ms):
// with 2 d (the kernel's support) two free particles 2.2-2.5 d from the collar moved 2.3 and 4.6 um
// (bound 4.1 um, elsewhere 0.1 um); with 3 d the largest displacement is 0.10 um, as without collar
// and clamp.
inline constexpr double kLimbusClampSpacings = 3.0;
// [1] the cap's rim (where the collar starts) reaches this far from the wall samples over the
// sclera: the cap and the sclera's wall samples are both at d/2, so a cap sample next to the
// boundary has one within ~d/2-d; one spacing takes the first row or two of the cap.
inline constexpr double kCapRimSpacings = 1.0;
// [1] the bony orbit around the elastic orbital fat: rigid wall particles (spacing d/2) at
// distances [kOrbitGapSpacings, kOrbitGapSpacings + 1) d from the nearest fat particle, outside
// the sclera's backstop shell, so the tissue assembly is enclosed by walls and fluid that gets
// through the tissue stays in the scene. Two spacings: no wall particle within the kernel's
// support of a fat particle (the sclera backstop's rule).
inline constexpr double kOrbitGapSpacings = 2.0;

struct TissueBody {
  std::string name;                    // "sclera" or "orbital fat"
  std::string material;                // material library name
  double youngsModulus = 0.0;          // [Pa] the tissue's (library, or the protocol's override)
  double poissonRatio = 0.0;           // [1]
  double density = 0.0;                // [kg/m^3]
  double thickness = 0.0;              // [m] used in the estimate
  double loadPressure = 0.0;           // [Pa] used in the estimate
  double estimatedDisplacement = 0.0;  // [m]
  sim::TissueDecision decision;
  // Elastic only.
  double layerThickness = 0.0;  // [m] mean sampled layer (>= kMinTissueLayerSpacings d)
  // [rad/s] first thickness mode of the layer, fixed on one face: pi c_p / (2 t_layer) with
  // c_p the P-wave speed of the simulated modulus. The elastic stage runs before the pressure
  // solve, so a layer loaded by the fluid answers as if softened by 1 + (omega_1 dt)^2.
  double thicknessModeFrequency = 0.0;
  double simulatedModulus = 0.0;  // [Pa] E (t / t_layer when thickened)
  int materialIndex = -1;         // in world.materials
  std::int32_t firstId = 0;       // particle ids firstId .. firstId + count - 1
  std::size_t count = 0;
  std::size_t anchored = 0;
  std::size_t limbusClamped = 0;  // sclera: of `anchored`, those anchored by the limbus clamp
  std::vector<sim::Vec3> restPositions;  // [m] by id - firstId
  std::string describe() const;          // one line for `tamponade plan` and notes
};

// The retina samples the coverage is measured at (RetinaMap order), #W.
struct RetinaSamples {
  std::vector<sim::Vec3> restPositions;  // [m]
  std::vector<sim::Vec3> normals;        // [1] outward (into the wall)
  std::vector<std::int32_t> followsId;   // tissue particle id the sample moves with, -1 = fixed
  // [m] sampled elastic sclera layer behind each sample (0: rigid wall or the lens/IOL cap); empty
  // when the sclera is not sampled. The leak counter (TissueMeasures) reads it.
  std::vector<double> scleraLayer;
  bool moves() const;
};

// Extra room [m] the World's domain needs around the cavity for the protocol's tissues.
double tissueDomainPadding(const Protocol& protocol, double particleSpacing);

// Records the retina samples: the mesh points where the coverage is measured, with their outward
// normals (call right after the walls are built; with the one-layer wall they are the first
// RetinaMap::areas.size() wall particles, with layered walls the surface samples behind them).
void recordRetinaSamples(Scenario& scenario, const std::vector<sim::Vec3>& points,
                         const std::vector<sim::Vec3>& normals);

// Decides each tissue of the protocol and adds the elastic ones (materials, particles, anchors;
// removes the wall particles they replace). Call right after recordRetinaSamples (before the
// wall tags are given contact angles, and before World::initialize). Throws ProtocolError at the
// value responsible: a forced elastic tissue the scene cannot sample (imported mesh: no anatomy), a
// thickness the anatomy rejects, a tissue that gets no particle at this spacing.
void addTissues(const Protocol& protocol, Scenario& scenario);

struct TissueMeasures {
  std::vector<double> maxDisplacement;  // [m] per Scenario::tissues entry (0 when rigid)
  double retinaMaxDisplacement = 0.0;   // [m] largest movement of a retina sample
  // [m^3] cavity volume change, sum_w A_w n_w . u_w over the retina samples (first order in u;
  // the divergence theorem on the wall, A_w the samples' areas).
  double cavityVolumeChange = 0.0;
  // [m] area-weighted mean outward displacement per reported region (kReportedRegions order).
  std::vector<double> regionMeanOutward;
  // Fluid in the tissue (a leak through the tissue's lattice; counted only when the sclera is
  // sampled). A fluid particle outside the cavity surface at depth r (distance to the rest surface)
  // is
  // - `fluidInTissue` when some sclera particle within 1.5 d of it lies more than d shallower
  //   (r_j < r - d), or none lies within 1.5 d and r > d: it sits behind a tissue particle, inside
  //   the layer. Fluid in the openings of the lattice-sampled face (the staircase's hollows, up to
  //   ~1 d deep) is not counted: it is no deeper than the innermost tissue particle of its own
  //   column (<= 1.37 d: the first lattice point past d/2 along a tilted column), and the
  //   shallowest one nearby is >= d/2 deep, so it is < 0.87 d + (relative tissue motion) deeper.
  // - `fluidThroughTissue` (a subset) when r > max(t_layer, d), t_layer the sampled layer at its
  //   nearest retina sample (0 on the cap): it has passed the whole layer (or the cap's wall).
  std::size_t fluidInTissue = 0;
  std::size_t fluidThroughTissue = 0;
  double deepestFluid = 0.0;  // [m] largest r of a fluid particle outside the cavity surface
};

// Current retina sample positions from the dynamic particles' positions and ids (#F each; any
// order). With no moving sample it returns the rest positions.
std::vector<sim::Vec3> retinaPositions(const Scenario& scenario, const std::vector<sim::Vec3>& x,
                                       const std::vector<std::int32_t>& ids);

TissueMeasures measureTissues(const Scenario& scenario, const std::vector<sim::Vec3>& x,
                              const std::vector<std::int32_t>& ids);

// Per dynamic particle displacement from its rest position [m] (zero for fluid), #F, in the
// arrays' order; written to the frames as the "tissue_displacement" field.
inline constexpr const char* kTissueDisplacementField = "tissue_displacement";
void updateTissueDisplacement(const Scenario& scenario, const std::vector<sim::Vec3>& x,
                              const std::vector<std::int32_t>& ids, std::vector<sim::Vec3>& out);

// The report's tissue lines: one ("tissue rigid (estimate ... < 0.1 d)") when no tissue is
// elastic, else per tissue its maximum displacement, the retina's, and the cavity volume change;
// with the run's mean time step [s] (0 = unknown), a warning for each elastic tissue whose
// thickness mode the step does not resolve ((omega_1 dt)^2 > 1, docs/methods/elasticity.md).
std::vector<std::string> tissueReportLines(const Scenario& scenario, const TissueMeasures& last,
                                           double lastTime, double meanTimeStep = 0.0);

}  // namespace protocols
