// Coverage over a posture schedule: time averages of the per-frame coverage.
//
// Frames are samples of a piecewise-continuous signal; each frame k stands for the time from
// halfway to its predecessor to halfway to its successor (the first and last frames for the half
// interval inside [t_0, t_end]). For the coverage fractions this is the trapezoidal rule; for the
// covered yes/no of a break it is sample-and-hold around each frame. The averages are therefore
// accurate to about one frame interval of the schedule: choose the frame interval well below the
// shortest posture.
#pragma once

#include <array>
#include <vector>

#include "protocols/coverage/frame_coverage.h"

namespace protocols {

struct ScheduleCoverage {
  double duration = 0.0;                                  // [s] t_last - t_first
  std::array<double, kReportedRegions.size()> regions{};  // [1] time-weighted mean fraction
  std::vector<double> breakFraction;                      // [1] time-weighted mean, per break
  std::vector<double> breakTimeCovered;  // [1] share of the time covered, per break
};

// `frames` in increasing time. One frame (duration 0) gives its own values. Throws
// CoverageError for no frames, times not increasing, or frames with different break counts.
ScheduleCoverage summarizeSchedule(const std::vector<FrameCoverage>& frames);

}  // namespace protocols
