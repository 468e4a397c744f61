#include "anatomy/retinal_regions.h"

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "anatomy/anatomy_error.h"
#include "anatomy/clock_hour.h"

namespace anatomy {

namespace {

bool inSector(double hour, double centre) {
  const double d = clockHourDifference(hour, centre);
  return d >= -1.5 && d < 1.5;
}

}  // namespace

RegionSet regionsAt(const Eye& eye, const Vec3& point, const Vec3* normal) {
  const CavityShape& cavity = eye.cavity();
  const CavityProjection projection = cavity.project(point, normal);
  if (projection.part == CavityPart::kCap) return 0;
  const WallCoordinate& w = projection.wall;
  const ClinicalLandmarks& l = eye.landmarks();
  if (eye.distanceFromLimbus(w) < l.oraFromLimbus) return 0;

  RegionSet regions = kRetina;
  const Vec3 q = cavity.wallPoint(w);
  if (std::hypot(q.x(), q.y()) > 1e-9) {
    const double hour = clockHourOf(q);
    const bool rightEye = eye.laterality() == Laterality::kRight;
    if (inSector(hour, 12.0))
      regions |= kSuperior;
    else if (inSector(hour, 6.0))
      regions |= kInferior;
    else if (inSector(hour, 3.0))
      regions |= rightEye ? kNasal : kTemporal;
    else
      regions |= rightEye ? kTemporal : kNasal;
  }
  const double toFovea = (q - eye.fovea()).norm();
  if (toFovea <= 0.5 * l.maculaDiameter) regions |= kMacula;
  if ((q - eye.opticDisc()).norm() <= 0.5 * l.opticDiscDiameter) regions |= kOpticDisc;
  const double equatorTheta = std::min(0.5 * std::numbers::pi, cavity.rimTheta());
  if (toFovea <= l.posteriorPoleRadius)
    regions |= kPosteriorPole;
  else if (w.theta < equatorTheta)
    regions |= kMidPeriphery;
  else
    regions |= kPeriphery;
  return regions;
}

std::vector<RegionSet> assignRegions(const Eye& eye, const std::vector<Vec3>& points,
                                     const std::vector<Vec3>& normals) {
  require(normals.empty() || normals.size() == points.size(),
          "assignRegions: " + std::to_string(normals.size()) + " normals for " +
              std::to_string(points.size()) + " points (give none or one per point)");
  std::vector<RegionSet> regions(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    regions[i] = regionsAt(eye, points[i], normals.empty() ? nullptr : &normals[i]);
  return regions;
}

std::string describeRegions(RegionSet regions) {
  static constexpr std::array<std::pair<RegionSet, const char*>, 10> kNames = {{
      {kRetina, "retina"},
      {kSuperior, "superior"},
      {kInferior, "inferior"},
      {kNasal, "nasal"},
      {kTemporal, "temporal"},
      {kMacula, "macula"},
      {kOpticDisc, "optic-disc"},
      {kPosteriorPole, "posterior-pole"},
      {kMidPeriphery, "mid-periphery"},
      {kPeriphery, "periphery"},
  }};
  std::string text;
  for (const auto& [bit, name] : kNames) {
    if (!(regions & bit)) continue;
    if (!text.empty()) text.push_back('|');
    text.append(name);
  }
  return text.empty() ? "none" : text;
}

}  // namespace anatomy
