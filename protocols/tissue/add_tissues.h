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

#include <vector>

#include "protocols/format/protocol.h"
#include "protocols/scenario/scenario.h"

namespace protocols {

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

}  // namespace protocols
