#include "protocols/coverage/frame_coverage.h"

#include "protocols/coverage/coverage_error.h"

namespace protocols {
namespace {

void accumulate(AreaCoverage& c, double area, WallWetting wetting) {
  c.area += area;
  if (wetting == WallWetting::kOil) c.oilArea += area;
  if (wetting == WallWetting::kDry) c.dryArea += area;
}

void finish(AreaCoverage& c) { c.fraction = c.area > 0.0 ? c.oilArea / c.area : 0.0; }

}  // namespace

FrameCoverage measureFrameCoverage(const RetinaMap& map, const WallOilFractions& fractions,
                                   double time) {
  const std::size_t n = map.areas.size();
  if (map.regions.size() != n || fractions.wetting.size() != n)
    throw CoverageError("measureFrameCoverage: the retina map has " + std::to_string(n) +
                        " areas and " + std::to_string(map.regions.size()) +
                        " region sets, the frame " + std::to_string(fractions.wetting.size()) +
                        " wall fractions; all must have one entry per wall particle");
  if (map.breakWalls.size() != map.breakNames.size())
    throw CoverageError("measureFrameCoverage: " + std::to_string(map.breakNames.size()) +
                        " break names but " + std::to_string(map.breakWalls.size()) +
                        " wall lists");
  FrameCoverage out;
  out.time = time;
  // Serial: one pass over ~1e4-1e5 wall particles is microseconds, and a serial sum is
  // deterministic without further ado.
  for (std::size_t w = 0; w < n; ++w) {
    const anatomy::RegionSet r = map.regions[w];
    if (r == 0) continue;
    for (std::size_t k = 0; k < kReportedRegions.size(); ++k)
      if ((r & kReportedRegions[k].bit) != 0)
        accumulate(out.regions[k], map.areas[w], fractions.wetting[w]);
  }
  for (auto& c : out.regions) finish(c);
  out.breaks.resize(map.breakWalls.size());
  for (std::size_t b = 0; b < map.breakWalls.size(); ++b) {
    for (std::size_t w : map.breakWalls[b]) {
      if (w >= n)
        throw CoverageError("measureFrameCoverage: break '" + map.breakNames[b] +
                            "' lists wall particle " + std::to_string(w) + " of " +
                            std::to_string(n));
      accumulate(out.breaks[b].area, map.areas[w], fractions.wetting[w]);
    }
    finish(out.breaks[b].area);
    out.breaks[b].covered =
        out.breaks[b].area.area > 0.0 && out.breaks[b].area.fraction >= kBreakCoveredFraction;
  }
  return out;
}

std::optional<double> retinaCoverageAt(const std::vector<FrameCoverage>& frames, double time) {
  std::optional<double> coverage;
  for (const FrameCoverage& f : frames)
    if (f.time <= time * (1 + 1e-9)) coverage = f.retina().fraction;
  return coverage;
}

}  // namespace protocols
