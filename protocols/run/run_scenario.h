// One Run of a scenario (docs/developer-guide.md, names): steps the world through the posture
// schedule (turning gravity in the eye frame), writes frames and the coverage time series to
// <out>/frames.h5 (FrameWriter), and the report (report.html, coverage.csv, summary.json) at the
// end.
//
// Frames are taken at every multiple of the protocol's frame interval (the first step crossing
// it), at the start and at the end; a posture ends at the first step that reaches its end time
// (the pipeline chooses dt; the overshoot is at most one step). "until steady" postures run
// their full maximum duration (steady-state detection is not implemented).
// Checkpoints (<out>/checkpoint.h5, protocols/io) are written every `checkpointInterval` steps
// and when a stop is requested; both happen only at multiples of the World's Z-sort interval
// (16 steps), the only steps at which a resumed World is in the same state as the continuous one
// (run_scenario.cpp). A resumed run is bit-identical to an uninterrupted one at the same thread
// count (tests/protocols/test_scenario_run.cpp).
// Frames hold Scenario::outputFields (the protocol's outputs.fields plus position and material).
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "protocols/coverage/schedule_coverage.h"
#include "protocols/format/protocol.h"
#include "protocols/io/frame_reader.h"
#include "protocols/run/equilibrium_postures.h"
#include "protocols/run/pressure_solve_totals.h"
#include "protocols/run/steady_state.h"
#include "protocols/scenario/scenario.h"

namespace protocols {

struct RunProgress {
  double time = 0.0;     // [s] simulated
  double endTime = 0.0;  // [s]
  long steps = 0;
  std::string posture;
};

struct RunOptions {
  std::filesystem::path outputFolder;                // must exist; frames.h5 must not
  std::function<void(const RunProgress&)> progress;  // called after every step (may be empty)
  bool resume = false;  // continue from <out>/checkpoint.h5 (the scenario must be re-assembled
                        // from the same protocol and accuracy)
  const std::atomic<bool>* stopRequested = nullptr;  // set by a signal handler: checkpoint, stop
  long stopAfterSteps = -1;              // > 0: behave as if stopped at this step (tests)
  long checkpointInterval = 1024;        // [steps] a multiple of the Z-sort interval (16)
  std::string accuracyOverride;          // the preset name given on the command line, recorded for
                                         // `tamponade report DIR` ("" = the protocol's own)
  std::optional<SteadyCriteria> steady;  // "until steady": default steadyCriteriaOf(protocol)
  // A mixed schedule: called after each of the postures at equilibrium it begins with.
  std::function<void(const EquilibriumProgress&)> equilibriumProgress;
};

struct RunSummary {
  bool stopped = false;  // a stop was requested: checkpoint written, no report
  std::size_t frames = 0;
  long steps = 0;
  double simulatedTime = 0.0;   // [s] (a mixed schedule's postures at equilibrium not included)
  double wallSeconds = 0.0;     // [s]
  double retinaCoverage = 0.0;  // [1] time-weighted mean
  PressureSolveTotals pressureSolve;
  ScheduleCoverage coverage;  // every reported region's and break's time-weighted mean
  // [1] per posture, the retina's oil-covered share in the last frame at or before its end (NaN
  // for a posture the run did not reach)
  std::vector<double> retinaAtPostureEnd;
};

// Runs `scenario` (built from `protocol`). Throws IoError for output problems, SimError when the
// simulation fails (e.g. a particle escapes the cavity).
// A mixed schedule (leadingEquilibria(scenario) > 0) first solves the postures at equilibrium it
// begins with (equilibrium_postures.h; again on resume, for the report) and simulates the rest
// on the schedule's clock, from the end of their nominal seconds; its fluid starts from the last
// equilibrium when the scenario was assembled by assembleStartingScenario.
// Steady postures' durations in the scenario's schedule become what was run, and every ended
// posture's ScheduledPosture::endedSteady is set (see above).
RunSummary runScenario(const Protocol& protocol, Scenario& scenario, const RunOptions& options);

// The first of next, next + interval, next + 2 interval, ... after `now` [s]; when that is more
// than a few dozen intervals away or `interval` is too small to advance `next` in floating point,
// now + interval (or the next double after now). Always ends, for any interval > 0.
double nextTimeAfter(double next, double interval, double now);

// Shortens the durations of `scenario`'s postures that ended steady to what the run's "postures"
// series recorded (rows at or before `upTo` [s]); a run without that series changes nothing.
void applyRecordedPostureEnds(const FrameReader& reader, Scenario& scenario,
                              double upTo = std::numeric_limits<double>::infinity());

}  // namespace protocols
