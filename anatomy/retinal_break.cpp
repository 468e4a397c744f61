#include "anatomy/retinal_break.h"

#include <cstdio>
#include <utility>

#include "anatomy/anatomy_error.h"

namespace anatomy {

namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b, c);
  return buffer;
}

}  // namespace

RetinalBreak::RetinalBreak(const Eye& eye, RetinalBreakSpec spec) : spec_(std::move(spec)) {
  const std::string label = "retinal break '" + spec_.name + "'";
  const ClinicalPosition& p = spec_.position;
  require(
      spec_.diameter > 0.0 && spec_.diameter <= 20e-3,
      label + format(": diameter %.2f mm is out of range (0 < d <= 20 mm)", spec_.diameter * 1e3));
  require(p.clockHour >= 0.0 && p.clockHour <= 12.0,
          label + format(": clock hour %.2f is out of range (0..12)", p.clockHour));
  const double ora = eye.landmarks().oraFromLimbus;
  const bool fromOra = p.from == DistanceReference::kOraSerrata;
  const double fromLimbus = p.distance + (fromOra ? ora : 0.0);
  require(fromLimbus >= ora,
          label +
              format(" at %.2f o'clock, %.2f mm posterior to the ", p.clockHour, p.distance * 1e3) +
              (fromOra ? "ora serrata" : "limbus") +
              format(" lies anterior to the ora serrata (%.2f mm posterior to the limbus), "
                     "outside the retina: give a distance >= %.2f mm from the limbus or >= 0 mm "
                     "from the ora",
                     ora * 1e3, ora * 1e3));
  try {
    centre_ = eye.wallPointAt(p);
  } catch (const AnatomyError& e) {
    throw AnatomyError(label + ": " + e.what());
  }
}

bool RetinalBreak::isInBreak(const Vec3& point) const {
  return (point - centre_.position).squaredNorm() <= 0.25 * spec_.diameter * spec_.diameter;
}

}  // namespace anatomy
