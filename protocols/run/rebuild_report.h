// The report of a run from its files (`tamponade report DIR`), and the one function that turns a
// run's results into the report, shared with runScenario so both paths give the same report.
//
// Rebuilding: the protocol is re-read (the original file when its text still matches the copy in
// frames.h5, else that copy, written to DIR/protocol.toml), the scenario re-assembled (assembly
// is deterministic, and the wall count is checked against frames.h5), and every frame's coverage
// recomputed from its fluid positions and materials; the stage times come from the
// "stage_seconds" series, the stage decisions from the re-assembled pipeline.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "protocols/coverage/schedule_coverage.h"
#include "protocols/report/report_input.h"
#include "protocols/run/pressure_solve_totals.h"
#include "protocols/scenario/scenario.h"
#include "protocols/tissue/tissue_measures.h"
#include "sim/world/pipeline.h"

namespace protocols {

struct RunResults {
  std::vector<FrameCoverage> frames;
  WallOilFractions lastFractions;               // wall state of the last frame
  std::vector<sim::StageTimers::Entry> timers;  // per-stage wall-clock
  std::vector<sim::StageDecision> decisions;
  TissueMeasures lastTissue;          // tissue state of the last frame
  double meanTimeStep = 0.0;          // [s] simulated time / steps (0 = unknown)
  PressureSolveTotals pressureSolve;  // steps = 0: not recorded (an older run)
};

ReportInput makeRunReportInput(const Protocol& protocol, const Scenario& scenario,
                               const RunResults& results);

// The coverage of one state (support radius coverageSupportRadius(d, 1.2 d)) of the dynamic
// particles: positions and materials (#F); particles of other materials than the two phases
// (elastic tissue) are left out. `ids` (#F, or empty when no retina sample moves) place the
// retina samples that move with a tissue (retinaPositions).
WallOilFractions measureWallFractions(const Scenario& scenario,
                                      const std::vector<sim::Vec3>& positions,
                                      const std::vector<std::int32_t>& materials,
                                      const std::vector<std::int32_t>& ids = {});

// The protocol and scenario options a run in `folder` was made with (from its frames.h5): the
// original protocol file when its text is unchanged, else the stored copy written to
// folder/protocol.toml; the accuracy preset given on the command line, if any.
Protocol loadRunProtocol(const std::filesystem::path& folder, ScenarioOptions& options);

// Rewrites report.html, coverage.csv and summary.json in `folder` from its frames.h5.
// Throws IoError when the files are missing or do not match the re-assembled scenario.
void rebuildReport(const std::filesystem::path& folder);

}  // namespace protocols
