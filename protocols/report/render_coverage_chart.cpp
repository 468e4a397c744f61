#include "protocols/report/render_coverage_chart.h"

#include <algorithm>
#include <sstream>

#include "protocols/report/report_format.h"

namespace protocols {

std::string renderCoverageChart(const ReportInput& input) {
  constexpr double kWidth = 720.0, kHeight = 300.0;                           // [px]
  constexpr double kLeft = 60.0, kRight = 20.0, kTop = 30.0, kBottom = 45.0;  // [px]
  const double plotW = kWidth - kLeft - kRight, plotH = kHeight - kTop - kBottom;
  double t0 = 0.0, t1 = 1.0;  // [s]
  if (!input.frames.empty()) t0 = input.frames.front().time, t1 = input.frames.back().time;
  for (const auto& p : input.postures) t0 = std::min(t0, p.start), t1 = std::max(t1, p.end);
  if (t1 <= t0) t1 = t0 + 1.0;
  auto x = [&](double t) { return kLeft + plotW * (t - t0) / (t1 - t0); };
  auto y = [&](double f) { return kTop + plotH * (1.0 - f); };
  auto num = [](double v) { return formatNumber(v, 5); };

  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(kWidth) << "\" height=\""
    << num(kHeight) << "\" viewBox=\"0 0 " << num(kWidth) << " " << num(kHeight)
    << "\" role=\"img\" aria-label=\"oil coverage over time\">\n";
  // Posture intervals, alternately shaded, with their names.
  for (std::size_t k = 0; k < input.postures.size(); ++k) {
    const auto& p = input.postures[k];
    s << "<rect x=\"" << num(x(p.start)) << "\" y=\"" << num(kTop) << "\" width=\""
      << num(std::max(0.0, x(p.end) - x(p.start))) << "\" height=\"" << num(plotH) << "\" fill=\""
      << (k % 2 == 0 ? "#f2f2f2" : "#e6eef7") << "\"/>\n";
    s << "<line x1=\"" << num(x(p.start)) << "\" y1=\"" << num(kTop) << "\" x2=\""
      << num(x(p.start)) << "\" y2=\"" << num(kTop + plotH)
      << "\" stroke=\"#777777\" stroke-width=\"1\"/>\n";
    s << "<text x=\"" << num(x(p.start) + 3) << "\" y=\"" << num(kTop - 8) << "\" font-size=\"11\">"
      << escapeXml(p.label) << "</text>\n";
  }
  // Axes and grid.
  for (int pct = 0; pct <= 100; pct += 25) {
    const double f = pct / 100.0;
    s << "<line x1=\"" << num(kLeft) << "\" y1=\"" << num(y(f)) << "\" x2=\"" << num(kLeft + plotW)
      << "\" y2=\"" << num(y(f)) << "\" stroke=\"#cccccc\" stroke-width=\"0.5\"/>\n";
    s << "<text x=\"" << num(kLeft - 6) << "\" y=\"" << num(y(f) + 4)
      << "\" font-size=\"11\" text-anchor=\"end\">" << pct << " %</text>\n";
  }
  for (int k = 0; k <= 4; ++k) {
    const double t = t0 + (t1 - t0) * k / 4.0;
    s << "<text x=\"" << num(x(t)) << "\" y=\"" << num(kTop + plotH + 16)
      << "\" font-size=\"11\" text-anchor=\"middle\">" << formatNumber(t, 3) << "</text>\n";
  }
  s << "<text x=\"" << num(kLeft + 0.5 * plotW) << "\" y=\"" << num(kHeight - 6)
    << "\" font-size=\"12\" text-anchor=\"middle\">"
    << (input.equilibria.empty()     ? "simulated time [s]"
        : isEquilibriumReport(input) ? "postures at equilibrium (one nominal second each)"
                                     : "time [s]: postures at equilibrium one nominal second "
                                       "each, then simulated")
    << "</text>\n";
  s << "<rect x=\"" << num(kLeft) << "\" y=\"" << num(kTop) << "\" width=\"" << num(plotW)
    << "\" height=\"" << num(plotH) << "\" fill=\"none\" stroke=\"#333333\"/>\n";
  // Series.
  auto series = [&](auto value, const char* colour, const char* dash, const std::string& name) {
    if (input.frames.empty()) return;
    s << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\"" << dash
      << " points=\"";
    for (const auto& f : input.frames) s << num(x(f.time)) << "," << num(y(value(f))) << " ";
    s << "\"><title>" << escapeXml(name) << "</title></polyline>\n";
  };
  series([](const FrameCoverage& f) { return f.retina().fraction; }, "#e0a526", "", "whole retina");
  static const char* kBreakColours[] = {"#c00000", "#7030a0", "#00804a", "#404040"};
  for (std::size_t b = 0; b < input.breaks.size(); ++b)
    series(
        [b](const FrameCoverage& f) {
          return b < f.breaks.size() ? f.breaks[b].area.fraction : 0.0;
        },
        kBreakColours[b % 4], " stroke-dasharray=\"6 3\"", "break " + input.breaks[b].name);
  // Legend.
  double ly = kTop + 12;
  s << "<text x=\"" << num(kLeft + 8) << "\" y=\"" << num(ly)
    << "\" font-size=\"11\" fill=\"#b07800\">&#8212; whole retina</text>\n";
  for (std::size_t b = 0; b < input.breaks.size(); ++b) {
    ly += 14;
    s << "<text x=\"" << num(kLeft + 8) << "\" y=\"" << num(ly) << "\" font-size=\"11\" fill=\""
      << kBreakColours[b % 4] << "\">- - break " << escapeXml(input.breaks[b].name) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace protocols
