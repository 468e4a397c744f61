// What `tamponade run` prints while it runs: a progress bar with ETA on a terminal,
// plain periodic lines otherwise (a log file or a CI console has no carriage return). Pure
// functions of the progress and the elapsed wall time, so the text is unit-tested without a run
// (tests/protocols/test_run_progress.cpp); tools/cmd_run.cpp only chooses and prints.
#pragma once

#include <string>

#include "protocols/run/run_scenario.h"

namespace protocols {

// Fraction of the run done, in [0, 1]: simulated time / the schedule's end. With "until steady"
// postures the end is their maximum duration, so the fraction (and the ETA) is a lower (upper)
// bound; a steady posture that ends early makes the fraction jump.
double progressFraction(const RunProgress& progress);

// Remaining wall time [s] if the rest runs at the average pace so far: elapsed (1 - f) / f.
// Negative (unknown) before any progress.
double estimateRemainingSeconds(double fraction, double elapsedSeconds);

// "45 s", "3 min 20 s", "2 h 05 min"; "?" for a negative (unknown) duration.
std::string formatWallDuration(double seconds);

// Terminal form: "\r[#######.......]  23.4 %  t = 0.117 s  upright  step 1520  ETA 1 min 05 s"
// padded to a fixed width so a shorter line overwrites a longer one; no newline.
std::string renderProgressBar(const RunProgress& progress, double elapsedSeconds,
                              int barWidth = 30);

// Plain form, one line with its newline:
// "progress  23.4 %  t = 0.117 s / 0.5 s  upright  step 1520  elapsed 20 s  ETA 1 min 05 s\n"
std::string renderProgressLine(const RunProgress& progress, double elapsedSeconds);

// When to print a plain line: every `fractionStep` of the run or every `maxSilence` seconds of
// wall time, whichever comes first (a slow run still shows it is alive), and always the first
// call. Pure state machine: `due` says whether to print now and advances the state if so.
class PlainProgressThrottle {
 public:
  explicit PlainProgressThrottle(double fractionStep = 0.1, double maxSilence = 30.0)
      : fractionStep_(fractionStep), maxSilence_(maxSilence) {}
  bool due(double fraction, double elapsedSeconds);

 private:
  double fractionStep_;          // [1]
  double maxSilence_;            // [s] wall
  double nextFraction_ = 0.0;    // [1]
  double lastPrinted_ = -1e300;  // [s] wall
};

}  // namespace protocols
