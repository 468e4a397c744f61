// Area-weighted oil coverage of one frame: the whole retina, each reported region and each break.
//
// Coverage of a set S of retinal wall particles = sum_{w in S, oil-covered} A_w / sum_{w in S} A_w,
// A_w the wall area each particle stands for (meshing::sampleSurface's Voronoi areas). Dry wall
// counts as not covered by oil (it is in the denominator), so a detached oil bubble that leaves
// the wall dry shows up as lost coverage.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "anatomy/retinal_regions.h"
#include "protocols/coverage/wall_oil_fraction.h"

namespace protocols {

// The regions every report lists, in this order, with their clinical names.
struct ReportedRegion {
  anatomy::RetinalRegion bit;
  std::string_view name;
};
inline constexpr std::array<ReportedRegion, 9> kReportedRegions = {{
    {anatomy::kRetina, "whole retina"},
    {anatomy::kSuperior, "superior quadrant"},
    {anatomy::kInferior, "inferior quadrant"},
    {anatomy::kNasal, "nasal quadrant"},
    {anatomy::kTemporal, "temporal quadrant"},
    {anatomy::kMacula, "macula"},
    {anatomy::kPosteriorPole, "posterior pole"},
    {anatomy::kMidPeriphery, "mid-periphery"},
    {anatomy::kPeriphery, "periphery (ora to equator)"},
}};

// A break is "covered" when at least this fraction of its area is oil-covered. 1 would demand
// every wall particle of the break to read phi >= 0.5; at draft spacing a break of 1-2 mm holds
// only 2-6 wall particles and the interface is smeared over h = 2 d, so one particle at the
// interface would flip the answer. 0.5 (most of the break sealed) is the documented choice.
inline constexpr double kBreakCoveredFraction = 0.5;  // [1]

// The retina as the coverage metrics see it; built once per scenario (protocols/assembly).
struct RetinaMap {
  std::vector<double> areas;                         // [m^2] per wall particle, #W
  std::vector<anatomy::RegionSet> regions;           // per wall particle, #W (0 = not retina)
  std::vector<std::string> breakNames;               // #B
  std::vector<std::vector<std::size_t>> breakWalls;  // wall indices inside each break, #B lists
};

struct AreaCoverage {
  double fraction = 0.0;  // [1] oil-covered share of the area (0 when the area is 0)
  double oilArea = 0.0;   // [m^2]
  double dryArea = 0.0;   // [m^2]
  double area = 0.0;      // [m^2]
};

struct BreakCoverage {
  AreaCoverage area;
  bool covered = false;  // area.fraction >= kBreakCoveredFraction
};

struct FrameCoverage {
  double time = 0.0;                                          // [s]
  std::array<AreaCoverage, kReportedRegions.size()> regions;  // kReportedRegions order
  std::vector<BreakCoverage> breaks;                          // RetinaMap::breakNames order
  const AreaCoverage& retina() const { return regions[0]; }
};

// Throws CoverageError when the map's arrays and the fractions disagree in size or a break
// lists a wall index out of range.
FrameCoverage measureFrameCoverage(const RetinaMap& map, const WallOilFractions& fractions,
                                   double time);

// The retina's oil-covered share in the last of `frames` (in time order) at or before `time` [s]
// (to 1e-9 relative, the rounding of a sum of durations); none when every frame is later.
std::optional<double> retinaCoverageAt(const std::vector<FrameCoverage>& frames, double time);

}  // namespace protocols
