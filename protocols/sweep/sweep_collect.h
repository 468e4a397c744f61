// `tamponade sweep collect`: one row per point from its summary.json and point.json, and the
// sweep's table in CSV, Markdown and HTML with SVG plots (docs/sweeps.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "protocols/sweep/sweep_folder.h"

namespace protocols {

struct SweepRegionResult {
  std::string name;
  double finalFraction = 0.0;  // [1] at the end of the schedule (the last posture)
  double meanFraction = 0.0;   // [1] over the schedule
};

struct SweepBreakResult {
  std::string name;
  bool coveredAtEnd = false;
  double timeCovered = 0.0;  // [1] share of the schedule's time
};

struct SweepRow {
  SweepManifestPoint point;
  PointRecord record;
  std::string problem;  // why the point has no results ("" when it has them)
  bool complete = false;
  std::vector<SweepRegionResult> regions;
  std::vector<SweepBreakResult> breaks;
  std::vector<std::pair<std::string, std::string>> accuracy;  // name, value with unit

  bool hasResults() const { return problem.empty(); }
};

std::vector<SweepRow> collectSweep(const SweepManifest& manifest,
                                   const std::filesystem::path& folder);

std::string renderSweepCsv(const SweepManifest& manifest, const std::vector<SweepRow>& rows);
std::string renderSweepMarkdown(const SweepManifest& manifest, const std::vector<SweepRow>& rows);

// Writes sweep.csv, sweep.md and sweep.html into `folder`.
void writeSweepTables(const SweepManifest& manifest, const std::vector<SweepRow>& rows,
                      const std::filesystem::path& folder);

}  // namespace protocols
