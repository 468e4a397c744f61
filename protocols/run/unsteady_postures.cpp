#include "protocols/run/unsteady_postures.h"

#include <algorithm>

#include "protocols/coverage/frame_coverage.h"
#include "protocols/equilibrium/posture_equilibrium_coverage.h"

namespace protocols {

void addUnsteadyPostureDistances(const Protocol& protocol, const Scenario& s, ReportInput& in) {
  std::vector<bool> unsteady(s.schedule.size(), false);
  for (std::size_t k = 0; k < in.postures.size() && k < s.schedule.size(); ++k) {
    ReportPosture& posture = in.postures[k];
    if (!posture.endedSteady || *posture.endedSteady) continue;
    posture.retinaAtEnd = retinaCoverageAt(in.frames, posture.end);
    unsteady[k] = true;
  }
  if (std::find(unsteady.begin(), unsteady.end(), true) == unsteady.end()) return;
  // Where no equilibrium can be computed the headline names the posture without a distance.
  const std::vector<std::optional<double>> equilibrium =
      equilibriumRetinaCoverage(s, protocol.tamponade.fill.value, unsteady);
  for (std::size_t k = 0; k < in.postures.size() && k < equilibrium.size(); ++k)
    in.postures[k].equilibriumRetina = equilibrium[k];
}

}  // namespace protocols
