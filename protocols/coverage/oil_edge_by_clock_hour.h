// The oil's edge on the retina in clinical terms: for each clock hour, the stretches of that
// meridian the oil covers, as distances posterior to the ora serrata (docs/reading-the-report.md).
// What a surgeon asks of a posture ("does the oil reach the break at 11 o'clock, 4 mm behind the
// ora?") without reading a fundus map.
#pragma once

#include <vector>

#include "anatomy/eye.h"
#include "anatomy/retinal_regions.h"
#include "sim/core/types.h"

namespace protocols {

struct OilStretch {
  double from = 0.0;  // [m] posterior to the ora serrata
  double to = 0.0;    // [m]
};

struct ClockHourOilEdge {
  int clockHour = 12;           // 1 ... 12
  double meridianLength = 0.0;  // [m] along the wall, ora serrata to posterior pole
  std::vector<OilStretch> oil;  // oil-covered stretches, anterior to posterior; empty: none
};

// Bins along each meridian [m]: the edge is located to within one bin.
inline constexpr double kOilEdgeBin = 0.5e-3;
// Retina samples within this many hours of a clock hour count for its meridian (a 15 degree
// wedge: at 10 mm from the axis it is 2.6 mm wide, several samples at every preset's spacing).
inline constexpr double kOilEdgeWedge = 0.25;

// From the retina samples (`regions[w] != 0`) and their oil fractions: per clock hour 12, 1, ...,
// 11, each bin of the meridian is oil-covered when its samples' mean oil fraction is at least
// one half; a bin without samples takes its anterior neighbour's state.
std::vector<ClockHourOilEdge> oilEdgeByClockHour(const anatomy::Eye& eye,
                                                 const std::vector<sim::Vec3>& positions,
                                                 const std::vector<double>& oilFraction,
                                                 const std::vector<anatomy::RegionSet>& regions);

}  // namespace protocols
