#include "protocols/report/render_fundus_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "protocols/report/report_format.h"

namespace protocols {
namespace {

constexpr double kSize = 520.0;   // [px] drawing square
constexpr double kMargin = 40.0;  // [px] around it, for labels
constexpr double kDegree = 180.0 / std::numbers::pi;

std::string colourOf(WallWetting w) {
  switch (w) {
    case WallWetting::kOil: return "#e0a526";      // amber: oil
    case WallWetting::kAqueous: return "#3f7fbf";  // blue: aqueous
    case WallWetting::kDry: return "#b0b0b0";      // grey: no fluid
  }
  return "#000000";
}

}  // namespace

std::array<double, 2> projectFundus(const sim::Vec3& p) {
  const double theta = std::atan2(std::hypot(p.x(), p.y()), -p.z()) * kDegree;  // [deg]
  const double azimuth = std::atan2(p.y(), p.x());                              // [rad]
  return {theta * std::cos(azimuth), theta * std::sin(azimuth)};
}

namespace {

std::string num(double v) { return formatNumber(v, 5); }

// Where the map's drawing sits: the most anterior retinal point (largest angle from the pole)
// touches the drawing's edge, rounded up to 10 degrees.
struct FundusFrame {
  double maxAngle = 90.0;  // [deg]
  double scale = 0;        // [px/deg]
  double centre = 0;       // [px] of the pole, in x and y
  double total = 0;        // [px] the drawing's square with its margins
  std::array<double, 2> px(const sim::Vec3& p) const {
    const auto q = projectFundus(p);
    return {centre + scale * q[0], centre - scale * q[1]};
  }
};

FundusFrame fundusFrame(const ReportInput& input) {
  FundusFrame f;
  for (std::size_t w = 0; w < input.wallPositions.size(); ++w)
    if (w < input.wallRegions.size() && input.wallRegions[w] != 0) {
      const auto q = projectFundus(input.wallPositions[w]);
      f.maxAngle = std::max(f.maxAngle, std::hypot(q[0], q[1]));
    }
  f.maxAngle = 10.0 * std::ceil(f.maxAngle / 10.0);
  f.scale = 0.5 * kSize / f.maxAngle;
  f.centre = kMargin + 0.5 * kSize;
  f.total = kSize + 2 * kMargin;
  return f;
}

// The svg element, a white background (150 px wider for the legend) and angle rings every 30
// degrees from the posterior pole.
void writeBackground(std::ostringstream& s, const FundusFrame& f) {
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(f.total + 150) << "\" height=\""
    << num(f.total) << "\" viewBox=\"0 0 " << num(f.total + 150) << " " << num(f.total)
    << "\" role=\"img\" aria-label=\"fundus map of oil coverage\">\n";
  s << "<rect x=\"0\" y=\"0\" width=\"" << num(f.total + 150) << "\" height=\"" << num(f.total)
    << "\" fill=\"#ffffff\"/>\n";
  for (double a = 30.0; a <= f.maxAngle + 1e-9; a += 30.0)
    s << "<circle cx=\"" << num(f.centre) << "\" cy=\"" << num(f.centre) << "\" r=\""
      << num(a * f.scale) << "\" fill=\"none\" stroke=\"#dddddd\" stroke-width=\"1\"/>\n";
}

// One dot per retinal wall particle, coloured by what wets it.
void writeWallDots(std::ostringstream& s, const ReportInput& input, const FundusFrame& f) {
  const double dot =
      std::max(1.5, std::min(4.0, 0.5 * kSize /
                                      std::sqrt(std::max<double>(
                                          1.0, static_cast<double>(input.wallPositions.size())))));
  s << "<g id=\"wall\">\n";
  for (std::size_t w = 0; w < input.wallPositions.size(); ++w) {
    if (w >= input.wallRegions.size() || input.wallRegions[w] == 0) continue;
    const auto q = f.px(input.wallPositions[w]);
    const WallWetting wet = w < input.wallWetting.size() ? input.wallWetting[w] : WallWetting::kDry;
    s << "<circle cx=\"" << num(q[0]) << "\" cy=\"" << num(q[1]) << "\" r=\"" << num(dot)
      << "\" fill=\"" << colourOf(wet) << "\"/>\n";
  }
  s << "</g>\n";
}

// Quadrant boundaries: the diagonals (clock hours 1:30, 4:30, 7:30, 10:30).
void writeQuadrantLines(std::ostringstream& s, const FundusFrame& f) {
  for (double deg : {45.0, 135.0}) {
    const double c = std::cos(deg / kDegree) * f.maxAngle * f.scale;
    const double sn = std::sin(deg / kDegree) * f.maxAngle * f.scale;
    s << "<line x1=\"" << num(f.centre - c) << "\" y1=\"" << num(f.centre + sn) << "\" x2=\""
      << num(f.centre + c) << "\" y2=\"" << num(f.centre - sn)
      << "\" stroke=\"#555555\" stroke-width=\"1\" stroke-dasharray=\"4 4\"/>\n";
  }
}

void writePolyline(std::ostringstream& s, const FundusFrame& f,
                   const std::vector<sim::Vec3>& points, bool closed, const char* style) {
  if (points.size() < 2) return;
  s << "<" << (closed ? "polygon" : "polyline") << " points=\"";
  for (const auto& p : points) {
    const auto q = f.px(p);
    s << num(q[0]) << "," << num(q[1]) << " ";
  }
  s << "\" fill=\"none\" " << style << "/>\n";
}

// Outlines (ora serrata, equator, posterior pole, macula, ...) and the breaks, each named.
void writeOutlinesAndBreaks(std::ostringstream& s, const ReportInput& input, const FundusFrame& f) {
  for (const auto& o : input.outlines) {
    s << "<g class=\"outline\"><title>" << escapeXml(o.name) << "</title>\n";
    writePolyline(s, f, o.points, o.closed, "stroke=\"#222222\" stroke-width=\"1.5\"");
    if (!o.points.empty()) {
      const auto q = f.px(o.points.front());
      s << "<text x=\"" << num(q[0] + 3) << "\" y=\"" << num(q[1] - 3)
        << "\" font-size=\"11\" fill=\"#222222\">" << escapeXml(o.name) << "</text>\n";
    }
    s << "</g>\n";
  }
  for (const auto& b : input.breaks) {
    s << "<g class=\"break\"><title>" << escapeXml(b.name + ": " + b.where) << "</title>\n";
    writePolyline(s, f, b.outline, true, "stroke=\"#c00000\" stroke-width=\"2.5\"");
    if (!b.outline.empty()) {
      sim::Vec3 mean = sim::Vec3::Zero();
      for (const auto& p : b.outline) mean += p;
      const auto q = f.px(mean / static_cast<double>(b.outline.size()));
      s << "<text x=\"" << num(q[0] + 8) << "\" y=\"" << num(q[1] + 4)
        << "\" font-size=\"12\" font-weight=\"bold\" fill=\"#c00000\">" << escapeXml(b.name)
        << "</text>\n";
    }
    s << "</g>\n";
  }
}

void writeOrientationLabels(std::ostringstream& s, const ReportInput& input, const FundusFrame& f) {
  const bool nasalRight = input.eyeSide == "OD";  // OD: nasal = patient's left = +x = right
  s << "<text x=\"" << num(f.centre) << "\" y=\"" << num(kMargin - 12)
    << "\" font-size=\"13\" text-anchor=\"middle\">superior</text>\n";
  s << "<text x=\"" << num(f.centre) << "\" y=\"" << num(f.total - 12)
    << "\" font-size=\"13\" text-anchor=\"middle\">inferior</text>\n";
  s << "<text x=\"" << num(f.total - 4) << "\" y=\"" << num(f.centre)
    << "\" font-size=\"13\" text-anchor=\"end\">" << (nasalRight ? "nasal" : "temporal")
    << "</text>\n";
  s << "<text x=\"4\" y=\"" << num(f.centre) << "\" font-size=\"13\">"
    << (nasalRight ? "temporal" : "nasal") << "</text>\n";
}

// To the right of the drawing: the colours, the break line, the rings and the map's time.
void writeLegend(std::ostringstream& s, const ReportInput& input, const FundusFrame& f) {
  const double lx = f.total + 10;
  double ly = kMargin;
  const std::pair<WallWetting, const char*> legend[] = {{WallWetting::kOil, "oil"},
                                                        {WallWetting::kAqueous, "aqueous"},
                                                        {WallWetting::kDry, "dry (no fluid)"}};
  for (const auto& [wet, label] : legend) {
    s << "<circle cx=\"" << num(lx + 6) << "\" cy=\"" << num(ly) << "\" r=\"5\" fill=\""
      << colourOf(wet) << "\"/><text x=\"" << num(lx + 16) << "\" y=\"" << num(ly + 4)
      << "\" font-size=\"12\">" << label << "</text>\n";
    ly += 20;
  }
  s << "<line x1=\"" << num(lx) << "\" y1=\"" << num(ly) << "\" x2=\"" << num(lx + 12) << "\" y2=\""
    << num(ly) << "\" stroke=\"#c00000\" stroke-width=\"2.5\"/><text x=\"" << num(lx + 16)
    << "\" y=\"" << num(ly + 4) << "\" font-size=\"12\">break</text>\n";
  ly += 20;
  s << "<text x=\"" << num(lx) << "\" y=\"" << num(ly + 4)
    << "\" font-size=\"11\">rings: 30 deg</text>\n";
  s << "<text x=\"" << num(lx) << "\" y=\"" << num(ly + 20)
    << "\" font-size=\"11\">from the pole</text>\n";
  s << "<text x=\"" << num(lx) << "\" y=\"" << num(ly + 40) << "\" font-size=\"11\">"
    << (input.equilibria.empty() ? "t = " + formatNumber(input.mapTime, 4) + " s"
                                 : std::string("at equilibrium"))
    << "</text>\n";
}

}  // namespace

std::string renderFundusMap(const ReportInput& input) {
  const FundusFrame frame = fundusFrame(input);
  std::ostringstream s;
  writeBackground(s, frame);
  writeWallDots(s, input, frame);
  writeQuadrantLines(s, frame);
  writeOutlinesAndBreaks(s, input, frame);
  writeOrientationLabels(s, input, frame);
  writeLegend(s, input, frame);
  s << "</svg>\n";
  return s.str();
}

}  // namespace protocols
