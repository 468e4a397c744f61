// Coverage over time as inline SVG: whole-retina coverage (solid) and each break's covered
// fraction (dashed) against simulated time, with the posture intervals shaded and labelled.
#pragma once

#include <string>

#include "protocols/report/report_input.h"

namespace protocols {

std::string renderCoverageChart(const ReportInput& input);

}  // namespace protocols
