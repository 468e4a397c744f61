#include "protocols/sweep/render_sweep_html.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "protocols/io/xml_escape.h"
#include "protocols/report/report_format.h"

namespace protocols {

namespace {

constexpr double kWidth = 560, kHeight = 330, kLeft = 56, kRight = 16, kTop = 30, kBottom = 60;
constexpr std::array<const char*, 8> kLineColours = {"#1f5fa8", "#c0392b", "#2a8a3e", "#8e44ad",
                                                     "#b07800", "#117a8b", "#7f5539", "#555555"};

std::string num(double v) { return formatNumber(v, 5); }

// The x position of each distinct value of the first key: its number when every value starts
// with one (a fill, an angle), else its rank (a posture, an agent).
struct XAxis {
  std::vector<std::string> values;  // distinct, in sweep order
  std::vector<double> at;           // the position of each
  bool numeric = true;
  double min = 0, max = 1;
};

XAxis xAxisOf(const std::vector<SweepRow>& rows) {
  XAxis x;
  for (const SweepRow& row : rows)
    if (!row.point.values.empty() &&
        std::find(x.values.begin(), x.values.end(), row.point.values[0]) == x.values.end())
      x.values.push_back(row.point.values[0]);
  for (const std::string& v : x.values) {
    char* end = nullptr;
    const double number = std::strtod(v.c_str(), &end);
    x.numeric = x.numeric && end != v.c_str() && std::isfinite(number);
    x.at.push_back(number);
  }
  if (!x.numeric)
    for (std::size_t k = 0; k < x.at.size(); ++k) x.at[k] = static_cast<double>(k);
  if (!x.at.empty()) {
    x.min = *std::min_element(x.at.begin(), x.at.end());
    x.max = *std::max_element(x.at.begin(), x.at.end());
  }
  if (x.max == x.min) {
    x.min -= 1;
    x.max += 1;
  }
  const double margin = 0.05 * (x.max - x.min);  // end points and their labels stay inside
  x.min -= margin;
  x.max += margin;
  return x;
}

double positionOf(const XAxis& axis, const std::string& value) {
  const auto it = std::find(axis.values.begin(), axis.values.end(), value);
  return axis.at[static_cast<std::size_t>(it - axis.values.begin())];
}

// The line a row belongs to: the other keys' values, "k = v, ...".
std::string lineOf(const SweepManifest& m, const SweepRow& row) {
  std::string label;
  for (std::size_t k = 1; k < m.keys.size(); ++k)
    label += (k > 1 ? ", " : "") + m.keys[k] + " = " + row.point.values[k];
  return label.empty() ? "coverage" : label;
}

// The panel's lines: each combination of the other keys' values, with its (x, coverage) points.
struct PanelLines {
  std::vector<std::string> labels;  // in sweep order
  std::map<std::string, std::vector<std::pair<double, double>>> points;
};

PanelLines panelLines(const SweepManifest& m, const std::vector<SweepRow>& rows,
                      const std::string& region, const XAxis& axis) {
  PanelLines lines;
  for (const SweepRow& row : rows) {
    const std::string label = lineOf(m, row);
    if (std::find(lines.labels.begin(), lines.labels.end(), label) == lines.labels.end())
      lines.labels.push_back(label);
    for (const SweepRegionResult& r : row.regions)
      if (r.name == region)
        lines.points[label].emplace_back(positionOf(axis, row.point.values[0]), r.finalFraction);
  }
  for (auto& [label, points] : lines.points) std::sort(points.begin(), points.end());
  return lines;
}

void renderAxes(std::ostringstream& s, const SweepManifest& m, const XAxis& axis, double plotW,
                double plotH) {
  auto px = [&](double v) { return kLeft + (v - axis.min) / (axis.max - axis.min) * plotW; };
  for (int pct = 0; pct <= 100; pct += 20) {
    const double y = kTop + (1.0 - pct / 100.0) * plotH;
    s << "<line x1=\"" << num(kLeft) << "\" x2=\"" << num(kLeft + plotW) << "\" y1=\"" << num(y)
      << "\" y2=\"" << num(y) << "\" stroke=\"#cccccc\" stroke-width=\"0.5\"/>\n<text x=\""
      << num(kLeft - 6) << "\" y=\"" << num(y + 4) << "\" font-size=\"11\" text-anchor=\"end\">"
      << pct << " %</text>\n";
  }
  for (std::size_t k = 0; k < axis.values.size(); ++k)
    s << "<text x=\"" << num(px(axis.at[k])) << "\" y=\"" << num(kTop + plotH + 16)
      << "\" font-size=\"11\" text-anchor=\"middle\">" << escapeXml(axis.values[k]) << "</text>\n";
  s << "<text x=\"" << num(kLeft + plotW / 2) << "\" y=\"" << num(kHeight - 24)
    << "\" font-size=\"12\" text-anchor=\"middle\">" << escapeXml(m.keys.front()) << "</text>\n"
    << "<rect x=\"" << num(kLeft) << "\" y=\"" << num(kTop) << "\" width=\"" << num(plotW)
    << "\" height=\"" << num(plotH) << "\" fill=\"none\" stroke=\"#333333\"/>\n";
}

void renderPanel(std::ostringstream& s, const SweepManifest& m, const std::vector<SweepRow>& rows,
                 const std::string& region, const XAxis& axis) {
  const double plotW = kWidth - kLeft - kRight, plotH = kHeight - kTop - kBottom;
  auto px = [&](double v) { return kLeft + (v - axis.min) / (axis.max - axis.min) * plotW; };
  auto py = [&](double f) { return kTop + (1.0 - f) * plotH; };
  const PanelLines lines = panelLines(m, rows, region, axis);
  const double legendHeight = 16.0 * static_cast<double>(lines.labels.size());
  s << "<figure><svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(kWidth) << "\" height=\""
    << num(kHeight + legendHeight) << "\" role=\"img\">\n<text x=\"" << num(kLeft) << "\" y=\""
    << num(kTop - 10) << "\" font-size=\"13\" font-weight=\"bold\">" << escapeXml(region)
    << "</text>\n";
  renderAxes(s, m, axis, plotW, plotH);
  for (std::size_t l = 0; l < lines.labels.size(); ++l) {
    const char* colour = kLineColours[l % kLineColours.size()];
    const auto found = lines.points.find(lines.labels[l]);
    const auto& pts = found != lines.points.end() ? found->second : decltype(found->second){};
    s << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"";
    for (const auto& [x, f] : pts) s << num(px(x)) << "," << num(py(f)) << " ";
    s << "\"/>\n";
    for (const auto& [x, f] : pts)
      s << "<circle cx=\"" << num(px(x)) << "\" cy=\"" << num(py(f)) << "\" r=\"3\" fill=\""
        << colour << "\"/>\n";
    const double y = kHeight - 4 + 16.0 * static_cast<double>(l);
    s << "<rect x=\"" << num(kLeft) << "\" y=\"" << num(y - 9)
      << "\" width=\"10\" height=\"10\" fill=\"" << colour << "\"/><text x=\"" << num(kLeft + 16)
      << "\" y=\"" << num(y) << "\" font-size=\"11\">" << escapeXml(lines.labels[l]) << "</text>\n";
  }
  s << "</svg>\n<figcaption>" << escapeXml(region)
    << " covered at the end of the schedule, against " << escapeXml(m.keys.front())
    << ".</figcaption></figure>\n";
}

}  // namespace

std::string renderSweepHtml(const SweepManifest& manifest, const std::vector<SweepRow>& rows) {
  std::ostringstream s;
  s << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>"
    << escapeXml(manifest.title)
    << "</title>\n<style>body{font-family:sans-serif;max-width:1200px;margin:1em auto}"
       "figure{display:inline-block;margin:0.5em}table{border-collapse:collapse}"
       "td,th{border:1px solid #ccc;padding:2px 6px}td.n{text-align:right}</style></head><body>\n"
    << "<h1>" << escapeXml(manifest.title) << "</h1>\n";
  std::size_t done = 0;
  for (const SweepRow& row : rows) done += row.hasResults() ? 1 : 0;
  s << "<p>" << done << " of " << rows.size() << " points have results. Sweep file "
    << escapeXml(manifest.sweepFile) << ", base protocol " << escapeXml(manifest.base) << ".</p>\n";
  std::vector<SweepRow> withResults;
  for (const SweepRow& row : rows)
    if (row.hasResults()) withResults.push_back(row);
  if (!manifest.keys.empty()) {
    const XAxis axis = xAxisOf(withResults);
    for (const std::string& region : manifest.plotRegions)
      renderPanel(s, manifest, withResults, region, axis);
  }
  s << "<h2>Points</h2>\n<table><tr><th>point</th>";
  for (const auto& k : manifest.keys) s << "<th>" << escapeXml(k) << "</th>";
  for (const auto& r : manifest.plotRegions) s << "<th>" << escapeXml(r) << "</th>";
  s << "<th>report</th></tr>\n";
  for (const SweepRow& row : rows) {
    s << "<tr><td>" << row.point.id << "</td>";
    for (const auto& v : row.point.values) s << "<td>" << escapeXml(v) << "</td>";
    for (const auto& name : manifest.plotRegions) {
      std::string cell = escapeXml(row.problem);
      for (const SweepRegionResult& r : row.regions)
        if (r.name == name) cell = formatPercent(r.finalFraction);
      s << "<td class=\"n\">" << cell << "</td>";
    }
    s << "<td>"
      << (row.hasResults() ? "<a href=\"points/" + row.point.id + "/report.html\">report</a>"
                           : std::string())
      << "</td></tr>\n";
  }
  s << "</table>\n</body></html>\n";
  return s.str();
}

}  // namespace protocols
