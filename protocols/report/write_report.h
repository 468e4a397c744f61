// The report of one run: report.html (self-contained: inline CSS and SVG, no scripts, no network),
// coverage.csv (one row per frame) and summary.json (the schedule averages and final state).
// The HTML is also well-formed XML (XHTML syntax), so a plain XML checker can validate it.
#pragma once

#include <filesystem>
#include <string>

#include "protocols/report/report_input.h"

namespace protocols {

std::string renderReportHtml(const ReportInput& input);
// Header: time_s, retina..periphery (kReportedRegions, as fractions), then per break
// <name>_fraction, <name>_covered (0/1).
std::string renderCoverageCsv(const ReportInput& input);
std::string renderSummaryJson(const ReportInput& input);

// Writes the three files into `folder` (which must exist); throws IoError naming the file.
void writeReport(const ReportInput& input, const std::filesystem::path& folder);

}  // namespace protocols
