// A sweep as a Slurm job array (docs/sweeps.md): one array task per unfinished point, each
// running `tamponade sweep task DIR INDEX`, which runs that point like a local sweep does and
// writes the same point.json; `sweep status` and `sweep collect` then read the folder alike.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "protocols/sweep/sweep_folder.h"

namespace tools {

struct SlurmOptions {
  std::string partition;  // "" = the cluster's default
  std::string account;
  std::string time;    // e.g. "01:00:00"; "" = the partition's default
  std::string memory;  // e.g. "4G"; "" = the partition's default
  int cpusPerTask = 1;
  int maxParallel = 0;  // the array's %N throttle; 0 = no throttle
  bool submit = true;   // false: write the script only
};

// "0-4,7,9-10": Slurm's --array list of the given (sorted) indices.
std::string arrayIndexList(const std::vector<std::size_t>& indices);

// The batch script for the points `indices` (0-based manifest indices).
std::string slurmScript(const std::filesystem::path& folder, const std::filesystem::path& tamponade,
                        const std::vector<std::size_t>& indices, const SlurmOptions& options);

// Writes DIR/slurm/sweep.sbatch and submits it with sbatch (unless !options.submit); returns the
// exit code, printing what happened or why not.
int submitSweepToSlurm(const std::filesystem::path& folder,
                       const protocols::SweepManifest& manifest, const SlurmOptions& options);

}  // namespace tools
