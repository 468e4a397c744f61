// The progress display of every command that runs a protocol (`run`, `bench accuracy`): a bar
// with ETA on a terminal, redrawn at most ten times a second; plain throttled lines otherwise
// (a log file has no carriage return). The text itself is protocols/run/progress_text.h's.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>

#include "protocols/run/progress_text.h"

namespace tools {

class ProgressPrinter {
 public:
  ProgressPrinter() : terminal_(isatty(fileno(stderr)) != 0) {}

  void operator()(const protocols::RunProgress& p) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (terminal_) {
      if (elapsed - lastBar_ < 0.1) return;
      lastBar_ = elapsed;
      std::fputs(protocols::renderProgressBar(p, elapsed).c_str(), stderr);
      drawn_ = true;
    } else if (throttle_.due(protocols::progressFraction(p), elapsed)) {
      std::fputs(protocols::renderProgressLine(p, elapsed).c_str(), stderr);
      std::fflush(stderr);
    }
  }

  // Ends the bar's line so that what follows starts on its own.
  void finish() {
    if (terminal_ && drawn_) std::fputc('\n', stderr);
    drawn_ = false;
  }

 private:
  bool terminal_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  protocols::PlainProgressThrottle throttle_;
  double lastBar_ = -1.0;  // [s] wall time of the last bar redraw
};

}  // namespace tools
