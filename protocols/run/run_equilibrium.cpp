#include "protocols/run/run_equilibrium.h"

#include <chrono>

#include "protocols/report/write_report.h"
#include "protocols/run/rebuild_report.h"

namespace protocols {

RunSummary runEquilibriumSchedule(const Protocol& protocol, Scenario& s, const RunOptions& options,
                                  const std::function<void(const EquilibriumProgress&)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  SolvedEquilibria solved =
      solveEquilibriumPostures(protocol, s, s.schedule.size(), options.outputFolder, progress);

  // The scenario's notes are about the particle simulation (wall model, fill, spacing); none
  // applies to the equilibrium.
  s.notes.clear();
  RunResults results{solved.frames, solved.last, {}, {}, {}, 0.0, {}};
  ReportInput in = makeRunReportInput(protocol, s, results);
  in.equilibria = std::move(solved.postures);
  in.accuracy = equilibriumAccuracyRows(solved, true);
  if (protocol.outputs.report.value) writeReport(in, options.outputFolder);

  RunSummary summary;
  summary.frames = solved.frames.size();
  summary.simulatedTime = 0.0;
  summary.retinaCoverage = in.summary.regions[0];
  summary.coverage = in.summary;
  summary.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace protocols
