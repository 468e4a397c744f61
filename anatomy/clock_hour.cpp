#include "anatomy/clock_hour.h"

#include <cmath>
#include <numbers>

#include "anatomy/anatomy_error.h"

namespace anatomy {

namespace {
constexpr double kRadiansPerHour = std::numbers::pi / 6.0;  // 360 deg / 12 h
}

Vec3 clockHourDirection(double hour) {
  const double angle = hour * kRadiansPerHour;  // [rad] clockwise from 12, seen from the front
  return {std::sin(angle), std::cos(angle), 0.0};
}

double clockHourOf(const Vec3& point) {
  const double radial = std::hypot(point.x(), point.y());  // [m]
  require(radial > 1e-12 * (1.0 + std::abs(point.z())),
          "clock hour of a point on the optical axis is undefined (point at x = y = 0)");
  double hour = std::atan2(point.x(), point.y()) / kRadiansPerHour;  // (-6, 6]
  if (hour <= 0.0) hour += 12.0;
  return hour;
}

double clockHourDifference(double a, double b) {
  double d = std::fmod(a - b, 12.0);
  if (d <= -6.0) d += 12.0;
  if (d > 6.0) d -= 12.0;
  return d;
}

}  // namespace anatomy
