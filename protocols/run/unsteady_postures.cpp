#include "protocols/run/unsteady_postures.h"

#include <optional>

#include "protocols/equilibrium/posture_equilibrium.h"
#include "sim/core/error.h"

namespace protocols {
namespace {

// The last frame's retina coverage at or before `end` [s].
std::optional<double> retinaAt(const std::vector<FrameCoverage>& frames, double end) {
  std::optional<double> coverage;
  for (const FrameCoverage& f : frames)
    if (f.time <= end * (1 + 1e-9)) coverage = f.retina().fraction;
  return coverage;
}

// Whether the equilibrium solver has what it needs: a tension, and an angle it can hold. The
// solver refuses the same (sim/equilibrium/threshold_dynamics_xu2017.cpp); asking first saves
// voxelising the cavity for nothing. An absent angle is not taken as 90 deg here: a distance to an
// equilibrium at an angle the protocol never gave would mislead.
bool equilibriumDefined(const Scenario& s) {
  const FluidPhase& oil = s.phases[1];
  return oil.interfacialTension && *oil.interfacialTension > 0.0 &&
         oil.contactAngleThroughAqueous && *oil.contactAngleThroughAqueous > 0.0 &&
         *oil.contactAngleThroughAqueous < 180.0;
}

}  // namespace

void addUnsteadyPostureDistances(const Protocol& protocol, const Scenario& s, ReportInput& in) {
  std::optional<CavityVoxels> cavity;
  for (std::size_t k = 0; k < in.postures.size() && k < s.schedule.size(); ++k) {
    ReportPosture& posture = in.postures[k];
    if (!posture.endedSteady || *posture.endedSteady) continue;
    posture.retinaAtEnd = retinaAt(in.frames, posture.end);
    if (!equilibriumDefined(s)) continue;
    try {
      if (!cavity) cavity = voxelizeCavity(s, equilibriumVoxelSpacing(s.accuracy.preset));
      const PostureEquilibrium e =
          solvePostureEquilibrium(s, *cavity, protocol.tamponade.fill.value, s.schedule[k].gravity);
      posture.equilibriumRetina = measureFrameCoverage(s.retina, e.wall, 0.0).retina().fraction;
    } catch (const sim::SimError&) {
      // No equilibrium the method can compute for this scene: the headline names the posture
      // without a distance.
    }
  }
}

}  // namespace protocols
