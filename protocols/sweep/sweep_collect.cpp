#include "protocols/sweep/sweep_collect.h"

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "protocols/report/report_format.h"
#include "protocols/sweep/render_sweep_html.h"

namespace protocols {

namespace {

using nlohmann::json;

// A number of summary.json; null (what the report writes for a value that is not finite) -> NaN.
double numberOf(const json& value) {
  return value.is_null() ? std::numeric_limits<double>::quiet_NaN() : value.get<double>();
}

// Reads a point's summary.json into `row`; sets row.problem when it cannot.
void readSummary(const std::filesystem::path& file, SweepRow& row) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    row.problem = "no summary.json";
    return;
  }
  try {
    const json j = json::parse(in);
    row.complete = j.value("complete", false);
    for (const json& r : j.at("regions"))
      row.regions.push_back(SweepRegionResult{r.at("name").get<std::string>(),
                                              numberOf(r.at("final_fraction")),
                                              numberOf(r.at("mean_fraction"))});
    for (const json& b : j.at("breaks"))
      row.breaks.push_back(SweepBreakResult{b.at("name").get<std::string>(),
                                            b.at("covered_at_end").get<bool>(),
                                            numberOf(b.at("time_covered"))});
    for (const json& a : j.value("accuracy", json::array()))
      row.accuracy.emplace_back(a.at("name").get<std::string>(), a.at("value").get<std::string>());
  } catch (const json::exception& e) {
    row.problem = "summary.json unreadable (" + std::string(e.what()) + ")";
  }
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// The columns every row shares: regions, breaks and accuracy names in order of first appearance.
struct Columns {
  std::vector<std::string> regions, breaks, accuracy;
};

Columns columnsOf(const std::vector<SweepRow>& rows) {
  Columns c;
  auto add = [](std::vector<std::string>& list, const std::string& name) {
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  };
  for (const SweepRow& row : rows) {
    for (const auto& r : row.regions) add(c.regions, r.name);
    for (const auto& b : row.breaks) add(c.breaks, b.name);
    for (const auto& a : row.accuracy) add(c.accuracy, a.first);
  }
  return c;
}

template <class T>
const T* named(const std::vector<T>& list, const std::string& name) {
  for (const T& item : list)
    if (item.name == name) return &item;
  return nullptr;
}

std::string accuracyValue(const SweepRow& row, const std::string& name) {
  for (const auto& [n, v] : row.accuracy)
    if (n == name) return v;
  return {};
}

}  // namespace

std::vector<SweepRow> collectSweep(const SweepManifest& manifest,
                                   const std::filesystem::path& folder) {
  std::vector<SweepRow> rows;
  for (const SweepManifestPoint& point : manifest.points) {
    SweepRow row{point, readPointRecord(pointFolder(folder, point.id)), {}, false, {}, {}, {}};
    if (row.record.state != PointState::kDone)
      row.problem = std::string(pointStateName(row.record.state));
    else
      readSummary(pointFolder(folder, point.id) / "summary.json", row);
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string renderSweepCsv(const SweepManifest& manifest, const std::vector<SweepRow>& rows) {
  const Columns c = columnsOf(rows);
  std::ostringstream s;
  s << "point";
  for (const auto& k : manifest.keys) s << "," << csvField(k);
  s << ",state,run_seconds";
  for (const auto& r : c.regions)
    s << "," << csvField(r + " final") << "," << csvField(r + " mean");
  for (const auto& b : c.breaks)
    s << "," << csvField(b + " covered at end") << "," << csvField(b + " time covered");
  for (const auto& a : c.accuracy) s << "," << csvField(a);
  s << "\n";
  for (const SweepRow& row : rows) {
    s << row.point.id;
    for (const auto& v : row.point.values) s << "," << csvField(v);
    s << "," << (row.hasResults() ? "done" : csvField(row.problem)) << ","
      << (row.record.attempts > 0 ? formatNumber(row.record.wallSeconds, 4) : "");
    for (const auto& name : c.regions) {
      const SweepRegionResult* r = named(row.regions, name);
      s << "," << (r ? formatNumber(r->finalFraction, 6) : "") << ","
        << (r ? formatNumber(r->meanFraction, 6) : "");
    }
    for (const auto& name : c.breaks) {
      const SweepBreakResult* b = named(row.breaks, name);
      s << "," << (b ? (b->coveredAtEnd ? "1" : "0") : "") << ","
        << (b ? formatNumber(b->timeCovered, 6) : "");
    }
    for (const auto& name : c.accuracy) s << "," << csvField(accuracyValue(row, name));
    s << "\n";
  }
  return s.str();
}

std::string renderSweepMarkdown(const SweepManifest& manifest, const std::vector<SweepRow>& rows) {
  const Columns c = columnsOf(rows);
  std::ostringstream s;
  s << "# " << manifest.title << "\n\nRetinal coverage at the end of the schedule, per point.\n\n";
  s << "| point |";
  for (const auto& k : manifest.keys) s << " " << k << " |";
  for (const auto& r : manifest.plotRegions) s << " " << r << " |";
  for (const auto& b : c.breaks) s << " " << b << " covered |";
  s << " run time |\n|---|";
  for (std::size_t k = 0; k < manifest.keys.size() + manifest.plotRegions.size() + c.breaks.size();
       ++k)
    s << "---|";
  s << "---|\n";
  for (const SweepRow& row : rows) {
    s << "| " << row.point.id << " |";
    for (const auto& v : row.point.values) s << " " << v << " |";
    for (const auto& name : manifest.plotRegions) {
      const SweepRegionResult* r = named(row.regions, name);
      s << " " << (r ? formatPercent(r->finalFraction) : row.problem) << " |";
    }
    for (const auto& name : c.breaks) {
      const SweepBreakResult* b = named(row.breaks, name);
      s << " " << (b ? (b->coveredAtEnd ? "yes" : "no") : "") << " |";
    }
    s << " " << (row.record.attempts > 0 ? formatNumber(row.record.wallSeconds, 3) + " s" : "")
      << " |\n";
  }
  return s.str();
}

void writeSweepTables(const SweepManifest& manifest, const std::vector<SweepRow>& rows,
                      const std::filesystem::path& folder) {
  const std::pair<const char*, std::string> files[] = {
      {"sweep.csv", renderSweepCsv(manifest, rows)},
      {"sweep.md", renderSweepMarkdown(manifest, rows)},
      {"sweep.html", renderSweepHtml(manifest, rows)}};
  for (const auto& [name, text] : files) {
    std::ofstream out(folder / name, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush()) throw SweepError("cannot write " + (folder / name).string());
  }
}

}  // namespace protocols
