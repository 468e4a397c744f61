#include "protocols/run/progress_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace protocols {

double progressFraction(const RunProgress& p) {
  if (!(p.endTime > 0)) return 1.0;
  return std::clamp(p.time / p.endTime, 0.0, 1.0);
}

double estimateRemainingSeconds(double fraction, double elapsedSeconds) {
  if (!(fraction > 0)) return -1.0;
  return elapsedSeconds * (1.0 - fraction) / fraction;
}

std::string formatWallDuration(double seconds) {
  if (!(seconds >= 0) || !std::isfinite(seconds)) return "?";
  char text[64];
  const long s = std::lround(seconds);
  if (s < 60)
    std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  return text;
}

std::string renderProgressBar(const RunProgress& p, double elapsedSeconds, int barWidth) {
  const double f = progressFraction(p);
  const int filled = std::clamp(static_cast<int>(f * barWidth), 0, barWidth);
  std::string line = "\r[" + std::string(static_cast<std::size_t>(filled), '#') +
                     std::string(static_cast<std::size_t>(barWidth - filled), '.') + "]";
  char rest[256];
  std::snprintf(rest, sizeof rest, " %5.1f %%  t = %.4g s  %s  step %ld  ETA %s", 100 * f, p.time,
                p.posture.c_str(), p.steps,
                formatWallDuration(estimateRemainingSeconds(f, elapsedSeconds)).c_str());
  line += rest;
  // Pad to a fixed width: the next, possibly shorter, line overwrites this one completely.
  constexpr std::size_t kWidth = 100;
  if (line.size() < kWidth) line.append(kWidth - line.size(), ' ');
  return line;
}

std::string renderProgressLine(const RunProgress& p, double elapsedSeconds) {
  const double f = progressFraction(p);
  char text[384];
  std::snprintf(text, sizeof text,
                "progress %5.1f %%  t = %.4g s / %.4g s  %s  step %ld  elapsed %s  ETA %s\n",
                100 * f, p.time, p.endTime, p.posture.c_str(), p.steps,
                formatWallDuration(elapsedSeconds).c_str(),
                formatWallDuration(estimateRemainingSeconds(f, elapsedSeconds)).c_str());
  return text;
}

bool PlainProgressThrottle::due(double fraction, double elapsedSeconds) {
  if (fraction < nextFraction_ && elapsedSeconds - lastPrinted_ < maxSilence_) return false;
  while (nextFraction_ <= fraction) nextFraction_ += fractionStep_;
  lastPrinted_ = elapsedSeconds;
  return true;
}

}  // namespace protocols
