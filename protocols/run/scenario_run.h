// The runner's state and its steps (runScenario in run_scenario.cpp drives them): the frames
// file opened afresh or resumed from a checkpoint, one frame recorded (particles, coverage,
// tissue, stage times, pressure-solve totals), a checkpoint written, a steady-state sample, one
// posture stepped to its end, and the report at the end.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "protocols/coverage/frame_coverage.h"
#include "protocols/coverage/wall_oil_fraction.h"
#include "protocols/io/frame_writer.h"
#include "protocols/run/run_scenario.h"
#include "protocols/run/run_state.h"
#include "protocols/tissue/tissue_measures.h"
#include "sim/world/pipeline.h"

namespace protocols {

class ScenarioRun {
 public:
  ScenarioRun(const Protocol& protocol, Scenario& scenario, const RunOptions& options);

  // Opens frames.h5 afresh (and records the start) or resumes from checkpoint.h5.
  void open();
  // Steps posture `k` to its end (its duration, or steady); false when a stop was requested (a
  // checkpoint is then written).
  bool runPosture(std::size_t k);
  std::size_t firstPosture() const { return state_.posture; }
  // The summary of a stopped run (frames closed, no report).
  RunSummary stop();
  // Records the end state, closes the frames and writes the report.
  RunSummary finish();

 private:
  void solveLeadingEquilibria();
  void start();
  void resume();
  void remeasureFrames(const CheckpointState& checkpoint);
  void record();
  void appendTissueSeries();
  void appendRunSeries();
  void checkpoint(std::size_t posture);
  SteadySample sample();
  bool sampleSteadiness();
  void snapshotParticles();
  // Whether this step ends the run: at a Z-sort step, a stop requested or --stop-after-steps.
  bool stopRequested() const;
  RunSummary summary(bool stopped) const;

  const Protocol& protocol_;
  Scenario& s_;
  sim::World& world_;
  const RunOptions& options_;
  std::chrono::steady_clock::time_point wallStart_;
  sim::Pipeline pipeline_;
  SteadyCriteria criteria_;
  std::vector<std::string> columns_, stageNames_;
  double interval_ = 0.0;   // [s] frame interval
  double totalMass_ = 0.0;  // [kg] constant
  RunState state_;
  std::optional<FrameWriter> writer_;
  std::vector<FrameCoverage> frames_;
  WallOilFractions lastFractions_;
  TissueMeasures lastTissue_;    // of the last frame
  SolvedEquilibria equilibria_;  // the postures at equilibrium a mixed schedule begins with
  double simulatedStart_ = 0.0;  // [s] schedule time at which the simulation starts
  std::vector<sim::Vec3> fluidPositions_;
  std::vector<std::int32_t> fluidMaterials_, fluidIds_;
};

}  // namespace protocols
