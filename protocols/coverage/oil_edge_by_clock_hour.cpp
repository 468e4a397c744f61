#include "protocols/coverage/oil_edge_by_clock_hour.h"

#include <cmath>
#include <cstddef>

#include "anatomy/anatomy_error.h"
#include "anatomy/clock_hour.h"

namespace protocols {
namespace {

struct Bins {
  std::vector<double> oil;   // sum of the samples' oil fractions
  std::vector<int> samples;  // samples per bin
};

double meridianLengthAt(const anatomy::Eye& eye, int hour) {
  const anatomy::Vec3 direction = anatomy::clockHourDirection(hour);
  const double meridian = eye.cavity().meridianOfAzimuth(std::atan2(direction.y(), direction.x()));
  return eye.distanceToPosteriorPole(meridian) - eye.landmarks().oraFromLimbus;
}

// Runs of covered bins as stretches; a bin without samples keeps the previous bin's state.
std::vector<OilStretch> stretchesOf(const Bins& bins, double length) {
  std::vector<OilStretch> stretches;
  const std::size_t count = bins.samples.size();
  bool covered = false;
  std::size_t runStart = 0;
  for (std::size_t b = 0; b <= count; ++b) {
    const bool was = covered;
    if (b < count && bins.samples[b] > 0) covered = bins.oil[b] >= 0.5 * bins.samples[b];
    const bool ends = b == count;
    if (!was && covered && !ends) runStart = b;
    if (was && (!covered || ends))
      stretches.push_back({static_cast<double>(runStart) * kOilEdgeBin,
                           std::min(length, static_cast<double>(b) * kOilEdgeBin)});
    if (ends) break;
  }
  return stretches;
}

}  // namespace

std::vector<ClockHourOilEdge> oilEdgeByClockHour(const anatomy::Eye& eye,
                                                 const std::vector<sim::Vec3>& positions,
                                                 const std::vector<double>& oilFraction,
                                                 const std::vector<anatomy::RegionSet>& regions) {
  std::vector<ClockHourOilEdge> edges(12);
  std::vector<Bins> bins(12);
  for (int k = 0; k < 12; ++k) {
    edges[k].clockHour = k == 0 ? 12 : k;
    edges[k].meridianLength = meridianLengthAt(eye, edges[k].clockHour);
    const auto count = static_cast<std::size_t>(std::ceil(edges[k].meridianLength / kOilEdgeBin));
    bins[k].oil.assign(count, 0.0);
    bins[k].samples.assign(count, 0);
  }
  for (std::size_t w = 0; w < positions.size() && w < oilFraction.size(); ++w) {
    if (w >= regions.size() || regions[w] == 0) continue;
    anatomy::ClinicalPosition at;
    try {
      at = eye.clinicalPositionOf(positions[w], anatomy::DistanceReference::kOraSerrata);
    } catch (const anatomy::AnatomyError&) {
      continue;  // on the lens/IOL cap: no clinical position
    }
    const int hour = static_cast<int>(std::lround(at.clockHour)) % 12;
    if (std::abs(anatomy::clockHourDifference(at.clockHour, hour)) > kOilEdgeWedge) continue;
    if (at.distance < 0.0) continue;
    const auto b = static_cast<std::size_t>(at.distance / kOilEdgeBin);
    if (b >= bins[hour].samples.size()) continue;
    bins[hour].oil[b] += oilFraction[w];
    ++bins[hour].samples[b];
  }
  for (int k = 0; k < 12; ++k) edges[k].oil = stretchesOf(bins[k], edges[k].meridianLength);
  return edges;
}

}  // namespace protocols
