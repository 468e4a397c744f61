#include "protocols/report/render_coverage_chart.h"

#include <algorithm>
#include <sstream>

#include "protocols/report/report_format.h"

namespace protocols {
namespace {

constexpr double kWidth = 720.0, kHeight = 300.0;                                      // [px]
constexpr double kLeft = 60.0, kRight = 20.0, kTop = 30.0, kBottom = 45.0;             // [px]
constexpr double kPlotW = kWidth - kLeft - kRight, kPlotH = kHeight - kTop - kBottom;  // [px]

std::string num(double v) { return formatNumber(v, 5); }

// The time axis [t0, t1] s mapped onto the plot area.
struct TimeAxis {
  double t0 = 0.0, t1 = 1.0;  // [s]
  double x(double t) const { return kLeft + kPlotW * (t - t0) / (t1 - t0); }
  static double y(double f) { return kTop + kPlotH * (1.0 - f); }
};

// Posture intervals, alternately shaded, with their names.
void drawPostures(std::ostream& s, const ReportInput& input, const TimeAxis& axis) {
  for (std::size_t k = 0; k < input.postures.size(); ++k) {
    const auto& p = input.postures[k];
    s << "<rect x=\"" << num(axis.x(p.start)) << "\" y=\"" << num(kTop) << "\" width=\""
      << num(std::max(0.0, axis.x(p.end) - axis.x(p.start))) << "\" height=\"" << num(kPlotH)
      << "\" fill=\"" << (k % 2 == 0 ? "#f2f2f2" : "#e6eef7") << "\"/>\n";
    s << "<line x1=\"" << num(axis.x(p.start)) << "\" y1=\"" << num(kTop) << "\" x2=\""
      << num(axis.x(p.start)) << "\" y2=\"" << num(kTop + kPlotH)
      << "\" stroke=\"#777777\" stroke-width=\"1\"/>\n";
    s << "<text x=\"" << num(axis.x(p.start) + 3) << "\" y=\"" << num(kTop - 8)
      << "\" font-size=\"11\">" << escapeXml(p.label) << "</text>\n";
  }
}

// Axes and grid.
void drawAxes(std::ostream& s, const ReportInput& input, const TimeAxis& axis) {
  for (int pct = 0; pct <= 100; pct += 25) {
    const double f = pct / 100.0;
    s << "<line x1=\"" << num(kLeft) << "\" y1=\"" << num(axis.y(f)) << "\" x2=\""
      << num(kLeft + kPlotW) << "\" y2=\"" << num(axis.y(f))
      << "\" stroke=\"#cccccc\" stroke-width=\"0.5\"/>\n";
    s << "<text x=\"" << num(kLeft - 6) << "\" y=\"" << num(axis.y(f) + 4)
      << "\" font-size=\"11\" text-anchor=\"end\">" << pct << " %</text>\n";
  }
  for (int k = 0; k <= 4; ++k) {
    const double t = axis.t0 + (axis.t1 - axis.t0) * k / 4.0;
    s << "<text x=\"" << num(axis.x(t)) << "\" y=\"" << num(kTop + kPlotH + 16)
      << "\" font-size=\"11\" text-anchor=\"middle\">" << formatNumber(t, 3) << "</text>\n";
  }
  s << "<text x=\"" << num(kLeft + 0.5 * kPlotW) << "\" y=\"" << num(kHeight - 6)
    << "\" font-size=\"12\" text-anchor=\"middle\">"
    << (input.equilibria.empty()     ? "simulated time [s]"
        : isEquilibriumReport(input) ? "postures at equilibrium (one nominal second each)"
                                     : "time [s]: postures at equilibrium one nominal second "
                                       "each, then simulated")
    << "</text>\n";
  s << "<rect x=\"" << num(kLeft) << "\" y=\"" << num(kTop) << "\" width=\"" << num(kPlotW)
    << "\" height=\"" << num(kPlotH) << "\" fill=\"none\" stroke=\"#333333\"/>\n";
}

// Series and their legend.
void drawSeries(std::ostream& s, const ReportInput& input, const TimeAxis& axis) {
  auto series = [&](auto value, const char* colour, const char* dash, const std::string& name) {
    if (input.frames.empty()) return;
    s << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\"" << dash
      << " points=\"";
    for (const auto& f : input.frames)
      s << num(axis.x(f.time)) << "," << num(axis.y(value(f))) << " ";
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
}

}  // namespace

std::string renderCoverageChart(const ReportInput& input) {
  TimeAxis axis;
  if (!input.frames.empty())
    axis.t0 = input.frames.front().time, axis.t1 = input.frames.back().time;
  for (const auto& p : input.postures)
    axis.t0 = std::min(axis.t0, p.start), axis.t1 = std::max(axis.t1, p.end);
  if (axis.t1 <= axis.t0) axis.t1 = axis.t0 + 1.0;

  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(kWidth) << "\" height=\""
    << num(kHeight) << "\" viewBox=\"0 0 " << num(kWidth) << " " << num(kHeight)
    << "\" role=\"img\" aria-label=\"oil coverage over time\">\n";
  drawPostures(s, input, axis);
  drawAxes(s, input, axis);
  drawSeries(s, input, axis);
  s << "</svg>\n";
  return s.str();
}

}  // namespace protocols
