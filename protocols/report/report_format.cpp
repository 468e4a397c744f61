#include "protocols/report/report_format.h"

#include <cmath>
#include <cstdio>

namespace protocols {

std::string formatPercent(double fraction) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f %%", 100.0 * fraction);
  return buffer;
}

std::string formatNumber(double value, int digits) {
  if (!std::isfinite(value)) return "nan";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

}  // namespace protocols
