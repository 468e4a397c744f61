// A sweep's folder (docs/sweeps.md): sweep.json (the manifest: keys, points, their values) and
// points/<id>/ per point, holding protocol.toml, point.json (its state) and the run's own files.
// The same layout serves local runs and Slurm job arrays, so `sweep status` and `sweep collect`
// read both alike.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "protocols/sweep/sweep_plan.h"

namespace protocols {

// A sweep folder that cannot be read or used: the message names the folder and the fix.
struct SweepError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SweepManifestPoint {
  std::string id;
  std::vector<std::string> values;  // shown values, in key order
  std::string protocolHash;         // of protocol.toml, to tell a changed sweep
};

struct SweepManifest {
  std::string title;
  std::string sweepFile;  // as given when the folder was made
  std::string base;
  std::vector<std::string> keys;
  std::vector<std::string> plotRegions;
  std::vector<SweepManifestPoint> points;
};

SweepManifest manifestOf(const SweepPlan& plan);

// Why `folder` cannot take `plan` ("" when it is new, empty, or holds this same sweep): it holds
// another sweep, or other files.
std::string sweepFolderConflict(const SweepManifest& plan, const std::filesystem::path& folder);

// Writes sweep.json and each point's protocol.toml (kept when present: it is the same text).
void writeSweepFolder(const SweepPlan& plan, const std::filesystem::path& folder);

// Throws SweepError when `folder` is not a sweep folder or its sweep.json is damaged.
SweepManifest readSweepManifest(const std::filesystem::path& folder);

std::filesystem::path pointFolder(const std::filesystem::path& folder, std::string_view id);

enum class PointState { kPending, kRunning, kDone, kFailed, kStopped };
std::string_view pointStateName(PointState state);

// points/<id>/point.json: the last attempt at the point.
struct PointRecord {
  PointState state = PointState::kPending;
  int exitCode = 0;
  double wallSeconds = 0.0;  // [s] of the last attempt
  int attempts = 0;
  std::string backend;  // "local" or "slurm"
  std::string host;
  long pid = 0;  // of the running `tamponade run`, while running
};

// kPending when the point has no point.json yet.
PointRecord readPointRecord(const std::filesystem::path& pointFolder);
// Atomic (a temporary file renamed into place): a kill never leaves half a record.
void writePointRecord(const std::filesystem::path& pointFolder, const PointRecord& record);

// A 64-bit FNV-1a hash of `text` as 16 hex digits.
std::string textHash(std::string_view text);

}  // namespace protocols
