#include "protocols/coverage/schedule_coverage.h"

#include <string>

#include "protocols/coverage/coverage_error.h"

namespace protocols {

ScheduleCoverage summarizeSchedule(const std::vector<FrameCoverage>& frames) {
  if (frames.empty())
    throw CoverageError("summarizeSchedule: no frames; record at least one coverage frame");
  const std::size_t nBreaks = frames.front().breaks.size();
  for (std::size_t k = 1; k < frames.size(); ++k) {
    if (!(frames[k].time > frames[k - 1].time))
      throw CoverageError("summarizeSchedule: frame " + std::to_string(k) + " at t = " +
                          std::to_string(frames[k].time) + " s does not follow frame " +
                          std::to_string(k - 1) + " at t = " + std::to_string(frames[k - 1].time) +
                          " s; frames must be in increasing time");
    if (frames[k].breaks.size() != nBreaks)
      throw CoverageError("summarizeSchedule: frame " + std::to_string(k) + " has " +
                          std::to_string(frames[k].breaks.size()) + " breaks, frame 0 has " +
                          std::to_string(nBreaks));
  }
  ScheduleCoverage out;
  out.breakFraction.assign(nBreaks, 0.0);
  out.breakTimeCovered.assign(nBreaks, 0.0);
  out.duration = frames.back().time - frames.front().time;
  const std::size_t n = frames.size();
  for (std::size_t k = 0; k < n; ++k) {
    // Weight of frame k [1]: its share of [t_0, t_end] (1 for a single frame).
    double weight = 1.0;
    if (n > 1) {
      const double lo = k == 0 ? frames[0].time : 0.5 * (frames[k - 1].time + frames[k].time);
      const double hi = k + 1 == n ? frames[k].time : 0.5 * (frames[k].time + frames[k + 1].time);
      weight = (hi - lo) / out.duration;
    }
    for (std::size_t r = 0; r < kReportedRegions.size(); ++r)
      out.regions[r] += weight * frames[k].regions[r].fraction;
    for (std::size_t b = 0; b < nBreaks; ++b) {
      out.breakFraction[b] += weight * frames[k].breaks[b].area.fraction;
      if (frames[k].breaks[b].covered) out.breakTimeCovered[b] += weight;
    }
  }
  return out;
}

}  // namespace protocols
