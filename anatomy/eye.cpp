#include "anatomy/eye.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "anatomy/anatomy_error.h"
#include "anatomy/clock_hour.h"

namespace anatomy {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Table resolution: linear interpolation error ~ (step^2 / 8) x second derivative, which is
// < 0.1 um along theta (step ~ 0.005 rad) and < 1 um across meridians (step 1 deg).
constexpr int kMeridians = 360;
constexpr int kThetas = 512;

std::string describe(const ClinicalPosition& p) {
  char buffer[96];
  std::snprintf(buffer, sizeof(buffer), "%.2f o'clock, %.2f mm posterior to the %s", p.clockHour,
                p.distance * 1e3, p.from == DistanceReference::kLimbus ? "limbus" : "ora serrata");
  return buffer;
}

}  // namespace

Eye::Eye(Laterality laterality, const CavityShape& cavity, const ClinicalLandmarks& landmarks)
    : laterality_(laterality), cavity_(cavity), landmarks_(landmarks) {
  const ClinicalLandmarks& l = landmarks_;
  require(l.limbusToRim >= 0.0 && l.oraFromLimbus > 0.0 && l.foveaToDisc > 0.0 &&
              l.maculaDiameter > 0.0 && l.opticDiscDiameter > 0.0 && l.posteriorPoleRadius > 0.0,
          "eye landmarks: distances must be positive (limbusToRim may be 0)");
  require(l.oraFromLimbus > l.limbusToRim, "eye landmarks: the ora serrata (" +
                                               mmText(l.oraFromLimbus) +
                                               " posterior to the limbus) "
                                               "must lie posterior to the cavity's rim (" +
                                               mmText(l.limbusToRim) + ")");

  // Tabulate the arc length to the rim: Gauss-Legendre per cell, accumulated from the rim.
  const double rimTheta = cavity_.rimTheta();
  arcTable_.assign(static_cast<size_t>(kMeridians) * (kThetas + 1), 0.0);
  for (int i = 0; i < kMeridians; ++i) {
    const double meridian = kTwoPi * i / kMeridians;
    double* column = &arcTable_[static_cast<size_t>(i) * (kThetas + 1)];
    column[kThetas] = 0.0;
    for (int k = kThetas - 1; k >= 0; --k)
      column[k] = column[k + 1] +
                  cavity_.arcLength(rimTheta * k / kThetas, rimTheta * (k + 1) / kThetas, meridian);
  }

  const double equatorTheta = std::min(0.5 * std::numbers::pi, rimTheta);
  for (int i = 0; i < kMeridians; ++i) {
    const double meridian = kTwoPi * i / kMeridians;
    const double equator = distanceFromLimbus({equatorTheta, meridian});
    require(l.oraFromLimbus < equator, "eye landmarks: the ora serrata (" +
                                           mmText(l.oraFromLimbus) +
                                           " posterior to the "
                                           "limbus) must lie anterior to the equator (" +
                                           mmText(equator) + " on some meridian)");
  }

  fovea_ = cavity_.posteriorPole();
  const double nasalAzimuth = laterality_ == Laterality::kRight ? 0.0 : std::numbers::pi;
  const double discMeridian = cavity_.meridianOfAzimuth(nasalAzimuth);
  const double poleDistance = distanceToPosteriorPole(discMeridian);
  require(poleDistance - l.foveaToDisc > l.oraFromLimbus, "eye landmarks: the optic disc (" +
                                                              mmText(l.foveaToDisc) +
                                                              " from the fovea) would lie "
                                                              "anterior to the ora serrata");
  opticDisc_ = cavity_.wallPoint(wallCoordinateAt(discMeridian, poleDistance - l.foveaToDisc));
}

double Eye::arcFromRim(double theta, double meridian) const {
  double m = std::fmod(meridian, kTwoPi);
  if (m < 0.0) m += kTwoPi;
  const double f = m / kTwoPi * kMeridians;
  int i0 = std::min(static_cast<int>(f), kMeridians - 1);
  const double t = f - i0;
  const int i1 = (i0 + 1) % kMeridians;
  const double g = std::clamp(theta / cavity_.rimTheta(), 0.0, 1.0) * kThetas;
  const int k0 = std::min(static_cast<int>(g), kThetas - 1);
  const double s = g - k0;
  const auto at = [&](int i, int k) {
    return arcTable_[static_cast<size_t>(i) * (kThetas + 1) + k];
  };
  const double a0 = (1 - s) * at(i0, k0) + s * at(i0, k0 + 1);
  const double a1 = (1 - s) * at(i1, k0) + s * at(i1, k0 + 1);
  return (1 - t) * a0 + t * a1;
}

double Eye::distanceFromLimbus(const WallCoordinate& w) const {
  return landmarks_.limbusToRim + arcFromRim(w.theta, w.meridian);
}

double Eye::distanceToPosteriorPole(double meridian) const {
  return landmarks_.limbusToRim + arcFromRim(0.0, meridian);
}

WallCoordinate Eye::wallCoordinateAt(double meridian, double distance) const {
  const double target = distance - landmarks_.limbusToRim;  // [m] from the rim
  const double total = arcFromRim(0.0, meridian);
  require(
      target >= -1e-12 && target <= total + 1e-12,
      "wall distance " + mmText(distance) + " posterior to the limbus is off the modelled wall (" +
          mmText(landmarks_.limbusToRim) + " .. " + mmText(total + landmarks_.limbusToRim) + ")");
  // arcFromRim decreases with theta: bisection on the tabulated theta grid, then linear.
  const double rimTheta = cavity_.rimTheta();
  int lo = 0, hi = kThetas;  // arc(lo) >= target >= arc(hi)
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (arcFromRim(rimTheta * mid / kThetas, meridian) >= target)
      lo = mid;
    else
      hi = mid;
  }
  const double arcLo = arcFromRim(rimTheta * lo / kThetas, meridian);
  const double arcHi = arcFromRim(rimTheta * hi / kThetas, meridian);
  const double fraction =
      arcLo > arcHi ? std::clamp((arcLo - target) / (arcLo - arcHi), 0.0, 1.0) : 0.0;
  return {rimTheta * (lo + fraction) / kThetas, meridian};
}

WallPoint Eye::wallPointAt(const ClinicalPosition& position) const {
  require(position.clockHour >= 0.0 && position.clockHour <= 12.0,
          "clinical position " + describe(position) + ": clock hour must be in 0..12");
  const double fromLimbus =
      position.distance +
      (position.from == DistanceReference::kOraSerrata ? landmarks_.oraFromLimbus : 0.0);
  const Vec3 direction = clockHourDirection(position.clockHour);
  const double meridian = cavity_.meridianOfAzimuth(std::atan2(direction.y(), direction.x()));
  require(fromLimbus >= landmarks_.limbusToRim, "clinical position " + describe(position) +
                                                    " is anterior to the modelled wall, which "
                                                    "starts " +
                                                    mmText(landmarks_.limbusToRim) +
                                                    " posterior to the limbus (at the lens/IOL)");
  const double pole = distanceToPosteriorPole(meridian);
  require(fromLimbus <= pole, "clinical position " + describe(position) +
                                  " lies beyond the "
                                  "posterior pole (" +
                                  mmText(pole) + " from the limbus on this meridian)");
  const WallCoordinate w = wallCoordinateAt(meridian, fromLimbus);
  return {cavity_.wallPoint(w), cavity_.wallNormal(w)};
}

ClinicalPosition Eye::clinicalPositionOf(const Vec3& point, DistanceReference from) const {
  const CavityProjection projection = cavity_.project(point);
  require(projection.part == CavityPart::kWall,
          "point (" + mmText(point.x()) + ", " + mmText(point.y()) + ", " + mmText(point.z()) +
              ") is on the lens/IOL cap, which has no clinical wall position");
  const WallCoordinate& w = projection.wall;
  const Vec3 q = cavity_.wallPoint(w);
  ClinicalPosition result;
  result.from = from;
  result.clockHour = std::hypot(q.x(), q.y()) > 1e-9 ? clockHourOf(q) : 12.0;
  result.distance = distanceFromLimbus(w) -
                    (from == DistanceReference::kOraSerrata ? landmarks_.oraFromLimbus : 0.0);
  return result;
}

}  // namespace anatomy
