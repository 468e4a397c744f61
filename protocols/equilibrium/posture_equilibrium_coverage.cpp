#include "protocols/equilibrium/posture_equilibrium_coverage.h"

#include "protocols/coverage/frame_coverage.h"
#include "protocols/equilibrium/posture_equilibrium.h"
#include "sim/core/error.h"

namespace protocols {

bool equilibriumDefined(const Scenario& s) {
  const FluidPhase& oil = s.phases[1];
  return oil.interfacialTension && *oil.interfacialTension > 0.0 &&
         oil.contactAngleThroughAqueous && *oil.contactAngleThroughAqueous > 0.0 &&
         *oil.contactAngleThroughAqueous < 180.0;
}

std::vector<std::optional<double>> equilibriumRetinaCoverage(const Scenario& s, double fill,
                                                             const std::vector<bool>& wanted) {
  std::vector<std::optional<double>> out(s.schedule.size());
  if (!equilibriumDefined(s)) return out;
  std::optional<CavityVoxels> cavity;
  for (std::size_t k = 0; k < s.schedule.size(); ++k) {
    if (!wanted.empty() && (k >= wanted.size() || !wanted[k])) continue;
    try {
      if (!cavity) cavity = voxelizeCavity(s, equilibriumVoxelSpacing(s.accuracy.preset));
      const PostureEquilibrium e = solvePostureEquilibrium(s, *cavity, fill, s.schedule[k].gravity);
      out[k] = measureFrameCoverage(s.retina, e.wall, 0.0).retina().fraction;
    } catch (const sim::SimError&) {
      // No equilibrium the method can compute for this scene: no reference for this posture.
    }
  }
  return out;
}

}  // namespace protocols
