// A schedule of equilibrium postures (duration = "equilibrium"): each posture's static
// equilibrium (protocols/equilibrium/posture_equilibrium.h), one after the other, then the same
// report as a simulated run (report.html, coverage.csv, summary.json) and each posture's interface
// as interface_<k>.ply (ParaView, MeshLab). Nothing is simulated: no frames or checkpoints. In the
// report and the CSV each posture spans one nominal second (kEquilibriumHold), so the schedule's
// means weight every posture alike; the transients between postures are neglected.
#pragma once

#include <functional>

#include "protocols/run/run_scenario.h"

namespace protocols {

struct EquilibriumProgress {
  std::size_t posture = 0;  // 0-based
  std::size_t postures = 0;
  std::string label;
  double seconds = 0.0;         // [s] the posture's solve
  double retinaCoverage = 0.0;  // [1]
  int iterations = 0;
  bool converged = false;
};

// Runs the schedule into options.outputFolder (which must exist). `progress` is called after
// each posture. Throws IoError for output problems, SimError when a posture has no equilibrium
// the method can compute (e.g. no interfacial tension).
RunSummary runEquilibriumSchedule(const Protocol& protocol, Scenario& scenario,
                                  const RunOptions& options,
                                  const std::function<void(const EquilibriumProgress&)>& progress);

}  // namespace protocols
