// "Until steady" means steady: a posture that reached its maximum duration before the steady test
// held is named in the report's headline and in summary.json, with how far its coverage at the
// end lies from the coverage at the posture's static equilibrium (docs/reading-the-report.md).
#pragma once

#include "protocols/format/protocol.h"
#include "protocols/report/report_input.h"
#include "protocols/scenario/scenario.h"

namespace protocols {

// For each posture of `in` that ended unsteady: its retina coverage at the end (from in.frames)
// and, when the scene has an interfacial tension and a contact angle strictly between 0 and 180
// deg, at its static equilibrium (solved at the accuracy preset's voxel, a few seconds).
void addUnsteadyPostureDistances(const Protocol& protocol, const Scenario& scenario,
                                 ReportInput& in);

}  // namespace protocols
