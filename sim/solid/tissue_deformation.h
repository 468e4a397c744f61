// "Only when it matters" (docs/developer-guide.md principle 1): before a run, estimate how far a
// tissue would move under the loads the scene can apply, and treat it as a rigid wall when that is
// far below the particle spacing (no elastic stage, no elastic time-step limit).
#pragma once

#include <string>

#include "sim/core/types.h"

namespace sim {

// Expected wall displacement [m] of a tissue layer of `thickness` [m] around a cavity of radius
// `cavityRadius` [m] under a pressure `loadPressure` [Pa] (hydrostatic rho g 2R plus capillary
// 2 sigma / r, whichever the scene can apply), for Young's modulus `youngsModulus` [Pa].
// Thin spherical shell (membrane) formula u = p R^2 (1 - nu) / (2 E t) (Timoshenko & Woinowsky-
// Krieger, "Theory of plates and shells", membrane theory of a sphere) taken at nu = 0, the
// largest value over 0 <= nu < 0.5, so the estimate errs towards "elastic". For a layer thicker
// than the radius (orbital fat) the membrane formula over-estimates the displacement, again on the
// safe side. Throws SimError for non-positive lengths or modulus or a negative pressure.
Real estimateTissueDeformation(Real loadPressure, Real cavityRadius, Real thickness,
                               Real youngsModulus);

// Expected wall displacement [m] of a tissue layer of `thickness` [m] whose far face is anchored
// (the sclera held by the orbit at its outer surface, the fat at its back face), pressed by
// `loadPressure` [Pa]: the layer can only be compressed through its thickness, u = p t / E
// (uniaxial stress, nu = 0: lateral confinement only stiffens it, to E (1 - nu) / ((1 + nu)
// (1 - 2 nu)), so the estimate again errs towards "elastic"). Measured on the paper's 10 kPa
// sclera anchored at its outer surface (d = 1.2 mm, INDSPH, 0.3 s): the membrane formula above
// predicts 3.4 mm, the retina moved 0.09 mm at most (7 um on average), the layer compression of
// the simulated 2-particle layer (2.4 mm, E scaled to 4.2 kPa) is 0.13 mm. Throws SimError as
// above.
Real estimateAnchoredLayerCompression(Real loadPressure, Real thickness, Real youngsModulus);

enum class TissueChoice { kAuto, kElastic, kRigid };

struct TissueDecision {
  bool elastic = false;
  bool forced = false;  // the protocol overrode the rule
  std::string reason;   // one sentence with the estimate, for `tamponade plan`
};

// Fraction of the particle spacing above which a tissue is simulated as elastic [1]. Below a tenth
// of a spacing the wall would move less than the particle-position noise of the fluid next to it
// (the pressure solvers keep density errors near 0.1-1 %, i.e. positional noise ~ 0.01-0.1 d), so
// an elastic wall could not change where the fluid goes.
inline constexpr Real kElasticDisplacementFraction = 0.1;

// Elastic if `estimatedDisplacement` [m] >= kElasticDisplacementFraction * `particleSpacing` [m],
// unless `choice` forces one of the two. Throws SimError for a negative estimate or spacing <= 0.
TissueDecision decideElastic(Real estimatedDisplacement, Real particleSpacing,
                             TissueChoice choice = TissueChoice::kAuto);

}  // namespace sim
