// One Run of a scenario (STYLE.md names): steps the world through the posture schedule (turning
// gravity in the eye frame), writes frames and the coverage time series to <out>/frames.h5
// (FrameWriter), and the report (report.html, coverage.csv, summary.json) at the end.
//
// Frames are taken at every multiple of the protocol's frame interval (the first step crossing
// it), at the start and at the end; a posture ends at the first step that reaches its end time
// (the pipeline chooses dt; the overshoot is at most one step). "until steady" postures run
// their full maximum duration (steady-state detection is not implemented).
// Not yet: checkpoints, Ctrl-C handling and --resume; the protocol's `outputs.fields` selection
// (every registry field marked `written` is written).
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "protocols/format/protocol.h"
#include "protocols/scenario/scenario.h"

namespace protocols {

struct RunProgress {
  double time = 0.0;     // [s] simulated
  double endTime = 0.0;  // [s]
  long steps = 0;
  std::string posture;
};

struct RunOptions {
  std::filesystem::path outputFolder;        // must exist; frames.h5 must not
  std::function<void(const RunProgress&)> progress;  // called after every step (may be empty)
  std::string accuracyOverride;  // the preset name given on the command line, recorded for
                                 // `tamponade report DIR` ("" = the protocol's own)
};

struct RunSummary {
  std::size_t frames = 0;
  long steps = 0;
  double simulatedTime = 0.0;  // [s]
  double wallSeconds = 0.0;    // [s]
  double retinaCoverage = 0.0; // [1] time-weighted mean
};

// Runs `scenario` (built from `protocol`). Throws IoError for output problems, SimError when the
// simulation fails (e.g. a particle escapes the cavity).
RunSummary runScenario(const Protocol& protocol, Scenario& scenario, const RunOptions& options);

}  // namespace protocols
