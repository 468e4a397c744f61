// A schedule of equilibrium postures (duration = "equilibrium"): each posture's static
// equilibrium (equilibrium_postures.h), one after the other, then the same
// report as a simulated run (report.html, coverage.csv, summary.json) and each posture's interface
// as interface_<k>.ply (ParaView, MeshLab). Nothing is simulated: no frames or checkpoints. In the
// report and the CSV each posture spans one nominal second (kEquilibriumHold), so the schedule's
// means weight every posture alike; the transients between postures are neglected.
#pragma once

#include <functional>

#include "protocols/run/equilibrium_postures.h"
#include "protocols/run/run_scenario.h"

namespace protocols {

// Runs the schedule into options.outputFolder (which must exist). `progress` is called after
// each posture. Throws IoError for output problems, SimError when a posture has no equilibrium
// the method can compute (e.g. no interfacial tension).
RunSummary runEquilibriumSchedule(const Protocol& protocol, Scenario& scenario,
                                  const RunOptions& options,
                                  const std::function<void(const EquilibriumProgress&)>& progress);

}  // namespace protocols
