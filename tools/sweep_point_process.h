// Running one sweep point as a child `tamponade run` (docs/sweeps.md): a crash or a memory limit
// hits that point only, and the point's folder is an ordinary run folder (resumable, with its
// report). Local sweeps run several at a time; a Slurm array task runs one.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "protocols/sweep/sweep_folder.h"

namespace tools {

struct PointLaunch {
  std::size_t index = 0;  // into the manifest's points
  pid_t pid = 0;
  std::chrono::steady_clock::time_point start;
  protocols::PointRecord record;
};

struct PointResources {
  int threads = 1;
  std::optional<double> memoryLimit;  // [bytes] passed as --max-memory
  std::string backend = "local";
};

// Whether the point needs running: not done (a done point has its summary.json).
bool pointNeedsRun(const std::filesystem::path& sweepFolder, const std::string& id);

// Starts `tamponade run` for point `index`: resumes from its checkpoint when it has one, else
// clears what an earlier attempt left and starts afresh. Output goes to the point's run.log.
PointLaunch launchPoint(const std::filesystem::path& sweepFolder,
                        const protocols::SweepManifest& manifest, std::size_t index,
                        const PointResources& resources);

// Records how the child ended (from waitpid's status) in point.json; returns the record.
protocols::PointRecord finishPoint(const std::filesystem::path& sweepFolder,
                                   const protocols::SweepManifest& manifest, PointLaunch& launch,
                                   int waitStatus);

// The host name, for point.json (a running point on another host is not checked for life).
std::string hostName();

}  // namespace tools
