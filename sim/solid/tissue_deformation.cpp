#include "sim/solid/tissue_deformation.h"

#include <cmath>
#include <sstream>

#include "sim/core/error.h"

namespace sim {

Real estimateTissueDeformation(Real loadPressure, Real cavityRadius, Real thickness,
                               Real youngsModulus) {
  require(loadPressure >= 0.0 && std::isfinite(loadPressure),
          "estimateTissueDeformation: load pressure must be finite and >= 0 Pa");
  require(cavityRadius > 0.0, "estimateTissueDeformation: cavity radius must be > 0 m");
  require(thickness > 0.0, "estimateTissueDeformation: tissue thickness must be > 0 m");
  require(youngsModulus > 0.0, "estimateTissueDeformation: Young's modulus must be > 0 Pa");
  return loadPressure * cavityRadius * cavityRadius / (2.0 * youngsModulus * thickness);
}

Real estimateAnchoredLayerCompression(Real loadPressure, Real thickness, Real youngsModulus) {
  require(loadPressure >= 0.0 && std::isfinite(loadPressure),
          "estimateAnchoredLayerCompression: load pressure must be finite and >= 0 Pa");
  require(thickness > 0.0, "estimateAnchoredLayerCompression: tissue thickness must be > 0 m");
  require(youngsModulus > 0.0, "estimateAnchoredLayerCompression: Young's modulus must be > 0 Pa");
  return loadPressure * thickness / youngsModulus;
}

TissueDecision decideElastic(Real estimatedDisplacement, Real particleSpacing,
                             TissueChoice choice) {
  require(estimatedDisplacement >= 0.0 && std::isfinite(estimatedDisplacement),
          "decideElastic: estimated displacement must be finite and >= 0 m");
  require(particleSpacing > 0.0, "decideElastic: particle spacing must be > 0 m");
  const Real ratio = estimatedDisplacement / particleSpacing;
  const bool rule = ratio >= kElasticDisplacementFraction;
  std::ostringstream why;
  why << "estimated displacement " << estimatedDisplacement << " m = " << ratio
      << " particle spacings " << (rule ? ">=" : "<") << " " << kElasticDisplacementFraction
      << (rule ? ": the tissue deforms visibly, simulated as elastic"
               : ": the tissue would barely move, treated as rigid wall");
  TissueDecision d{rule, false, why.str()};
  if (choice != TissueChoice::kAuto) {
    const bool on = choice == TissueChoice::kElastic;
    if (on != rule) {
      d.forced = true;
      d.reason = std::string("forced ") + (on ? "elastic" : "rigid") +
                 " by the protocol (rule: " + d.reason + ")";
    }
    d.elastic = on;
  }
  return d;
}

}  // namespace sim
