#include "protocols/report/render_oil_edge.h"

#include <cstdio>
#include <sstream>

#include "protocols/report/report_format.h"

namespace protocols {
namespace {

// One decimal: the edge is placed to within a 0.5 mm bin.
std::string decimal(double metres) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", metres * 1e3);
  return buffer;
}
std::string millimetres(double metres) { return decimal(metres) + " mm"; }

// "12 (superior)", "3 (nasal)" for OD, "3 (temporal)" for OS, "1" ...
std::string clockHourLabel(int hour, const std::string& eyeSide) {
  const bool right = eyeSide != "OS";
  switch (hour) {
    case 12: return "12 (superior)";
    case 6: return "6 (inferior)";
    case 3: return right ? "3 (nasal)" : "3 (temporal)";
    case 9: return right ? "9 (temporal)" : "9 (nasal)";
    default: return std::to_string(hour);
  }
}

}  // namespace

std::string describeOilStretches(const ClockHourOilEdge& edge) {
  if (edge.oil.empty()) return "none";
  // Within half a bin of an end counts as reaching it.
  const auto atOra = [](const OilStretch& s) { return s.from < 0.5 * kOilEdgeBin; };
  const auto atPole = [&](const OilStretch& s) {
    return s.to > edge.meridianLength - 0.5 * kOilEdgeBin;
  };
  std::string text;
  for (const OilStretch& s : edge.oil) {
    if (!text.empty()) text += ", ";
    if (atOra(s) && atPole(s))
      text += "ora to pole";
    else if (atOra(s))
      text += "ora to " + millimetres(s.to);
    else if (atPole(s))
      text += millimetres(s.from) + " to pole";
    else
      text += decimal(s.from) + "-" + millimetres(s.to);
  }
  return text;
}

std::string renderOilEdgeTable(const ReportInput& in) {
  bool any = false;
  for (const auto& e : in.equilibria) any = any || !e.oilEdge.empty();
  if (!any) return "";
  std::ostringstream s;
  s << "<h2>Oil edge by clock hour</h2>\n<table>\n<tr><th>clock hour</th>";
  for (const auto& e : in.equilibria) s << "<th>" << escapeXml(e.label) << "</th>";
  s << "</tr>\n";
  for (std::size_t k = 0; k < 12; ++k) {
    const int hour = k == 0 ? 12 : static_cast<int>(k);
    s << "<tr><td>" << clockHourLabel(hour, in.eyeSide) << "</td>";
    for (const auto& e : in.equilibria)
      s << "<td>" << (k < e.oilEdge.size() ? escapeXml(describeOilStretches(e.oilEdge[k])) : "")
        << "</td>";
    s << "</tr>\n";
  }
  s << "</table>\n<p>Where the oil touches the retina along each clock hour's meridian, in mm "
       "posterior to the ora serrata along the wall (\"pole\": the posterior pole, "
    << millimetres(in.equilibria.front().oilEdge.empty()
                       ? 0.0
                       : in.equilibria.front().oilEdge.front().meridianLength)
    << " from the ora at 12 o'clock). Read from the retina within a quarter hour of each "
       "meridian in bins of "
    << millimetres(kOilEdgeBin) << ": each edge is placed to within one bin.</p>\n";
  return s.str();
}

}  // namespace protocols
