#include "protocols/run/steady_state.h"

#include <algorithm>

namespace protocols {

SteadyCriteria steadyCriteriaOf(const Protocol& protocol) {
  SteadyCriteria c;
  c.window = protocol.schedule.steadyWindow.value;
  c.coverageChange = protocol.schedule.steadyCoverageChange.value;
  c.sampleInterval = c.window / 10;
  return c;
}

bool isSteady(std::span<const SteadySample> samples, double postureStart,
              const SteadyCriteria& criteria) {
  if (samples.empty()) return false;
  const double now = samples.back().time;            // [s]
  const double windowStart = now - criteria.window;  // [s]
  if (windowStart < postureStart) return false;      // the posture is younger than one window
  // The window must be covered: some sample at or before its start (otherwise the runner has
  // not looked long enough, e.g. right after a resume).
  if (samples.front().time > windowStart) return false;
  const std::size_t n = samples.back().coverage.size();
  std::vector<double> lo(n, 1.0), hi(n, 0.0);  // [1] coverage range of each region in the window
  for (auto it = samples.rbegin(); it != samples.rend(); ++it) {
    if (it->kineticEnergyPerMass >= criteria.kineticEnergyPerMass) return false;
    for (std::size_t c = 0; c < n && c < it->coverage.size(); ++c) {
      lo[c] = std::min(lo[c], it->coverage[c]);
      hi[c] = std::max(hi[c], it->coverage[c]);
    }
    if (it->time <= windowStart) break;  // the sample at the window's start is the last one needed
  }
  for (std::size_t c = 0; c < n; ++c)
    if (hi[c] - lo[c] >= criteria.coverageChange) return false;
  return true;
}

}  // namespace protocols
