// The static part of a scenario's report: title, the scenario in words, the posture timeline,
// the breaks and landmark outlines on the wall, the accuracy settings. A run adds the frames,
// the wall state and the pipeline's stage times (protocols/report/report_input.h).
#pragma once

#include "protocols/format/protocol.h"
#include "protocols/report/report_input.h"
#include "protocols/scenario/scenario.h"

namespace protocols {

ReportInput makeReportInput(const Protocol& protocol, const Scenario& scenario);

// The "pressure solve (achieved)" row of the report's accuracy table: value and note.
std::string pressureSolveValue(const ReportPressureSolve& solve);
std::string pressureSolveNote(const ReportPressureSolve& solve);

}  // namespace protocols
