// A sweep run on this machine: `jobs` points at a time, each a child `tamponade run` with its
// share of the threads (docs/sweeps.md). Finished points are skipped, stopped ones resume from
// their checkpoints; Ctrl-C or SIGTERM stops every running point at its next checkpoint.
#pragma once

#include <filesystem>
#include <optional>

#include "protocols/sweep/sweep_folder.h"

namespace tools {

struct LocalSweepOptions {
  int jobs = 1;                          // points at a time
  int threadsPerPoint = 1;               // OpenMP threads of each point
  std::optional<double> memoryPerPoint;  // [bytes] each point's --max-memory
};

// Returns the exit code: 0 every point done, 1 some failed, 128 + signal when stopped.
int runSweepLocally(const std::filesystem::path& folder, const protocols::SweepManifest& manifest,
                    const LocalSweepOptions& options);

// Runs point `index` in the foreground (a Slurm array task); returns its exit code.
int runSweepPoint(const std::filesystem::path& folder, const protocols::SweepManifest& manifest,
                  std::size_t index, int threads);

}  // namespace tools
