// The report's "Oil edge by clock hour" table of an equilibrium run: for each clock hour and
// posture, the stretches of the meridian the oil covers, in mm posterior to the ora serrata.
#pragma once

#include <string>
#include <vector>

#include "protocols/coverage/oil_edge_by_clock_hour.h"
#include "protocols/report/report_input.h"

namespace protocols {

// "ora to pole", "none", "ora to 12.5 mm", "8.0 mm to pole", "3.0-9.5 mm, 12.0 mm to pole".
std::string describeOilStretches(const ClockHourOilEdge& edge);

// The table (XHTML) and its explanation; "" when no posture has the table (an imported mesh
// eye has no ora serrata to measure from).
std::string renderOilEdgeTable(const ReportInput& input);

}  // namespace protocols
