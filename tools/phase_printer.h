// What a long command is doing before its progress bar can start (assembling a fine scene,
// calibrating the plan's cost model): one line per phase on stderr, from the first phase that
// starts after `quietSeconds`, so that quick commands print nothing.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>

namespace tools {

class PhasePrinter {
 public:
  PhasePrinter(std::string command, double quietSeconds = 1.0)
      : command_(std::move(command)), quietSeconds_(quietSeconds) {}

  void operator()(std::string_view phase) const {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed < quietSeconds_) return;
    std::fprintf(stderr, "tamponade %s: %.*s (%.0f s so far)\n", command_.c_str(),
                 static_cast<int>(phase.size()), phase.data(), elapsed);
    std::fflush(stderr);
  }

 private:
  std::string command_;
  double quietSeconds_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace tools
