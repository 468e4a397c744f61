#include "protocols/sweep/sweep_folder.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace protocols {

namespace {

using nlohmann::json;

constexpr int kManifestFormat = 1;

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void writeFileAtomically(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path temporary = file.string() + ".part";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush()) throw SweepError("cannot write " + file.string());
  }
  std::filesystem::rename(temporary, file);
}

constexpr std::array<std::string_view, 5> kStateNames = {"pending", "running", "done", "failed",
                                                         "stopped"};

}  // namespace

std::string textHash(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a offset basis
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

SweepManifest manifestOf(const SweepPlan& plan) {
  SweepManifest m;
  m.title = plan.title.empty() ? plan.file.stem().string() : plan.title;
  m.sweepFile = plan.file.string();
  m.base = plan.base.string();
  for (const SweepKey& k : plan.keys) m.keys.push_back(k.path);
  m.plotRegions = plan.plotRegions;
  for (const SweepPoint& p : plan.points) {
    SweepManifestPoint point{p.id, {}, textHash(p.protocolText)};
    for (std::size_t k = 0; k < plan.keys.size(); ++k)
      point.values.push_back(plan.keys[k].values[p.value[k]].shown);
    m.points.push_back(std::move(point));
  }
  return m;
}

std::filesystem::path pointFolder(const std::filesystem::path& folder, std::string_view id) {
  return folder / "points" / std::string(id);
}

std::string sweepFolderConflict(const SweepManifest& plan, const std::filesystem::path& folder) {
  std::error_code ec;
  if (!std::filesystem::exists(folder, ec)) return {};
  if (!std::filesystem::is_directory(folder, ec)) return "exists and is not a folder";
  if (!std::filesystem::exists(folder / "sweep.json")) {
    if (std::filesystem::directory_iterator(folder, ec) == std::filesystem::directory_iterator())
      return {};
    return "holds other files and no sweep.json: choose an empty or new folder";
  }
  const SweepManifest held = readSweepManifest(folder);
  if (held.keys != plan.keys)
    return "holds a sweep over other keys: choose another --out, or remove the folder";
  if (held.points.size() != plan.points.size())
    return "holds a sweep of " + std::to_string(held.points.size()) + " points, this one has " +
           std::to_string(plan.points.size()) + ": choose another --out, or remove the folder";
  for (std::size_t p = 0; p < held.points.size(); ++p)
    if (held.points[p].protocolHash != plan.points[p].protocolHash)
      return "holds a different sweep (point " + held.points[p].id +
             "'s protocol differs: the base protocol or the sweep file changed); choose another "
             "--out, or remove the folder to run it afresh";
  return {};
}

void writeSweepFolder(const SweepPlan& plan, const std::filesystem::path& folder) {
  const SweepManifest m = manifestOf(plan);
  json points = json::array();
  for (const SweepManifestPoint& p : m.points)
    points.push_back({{"id", p.id}, {"values", p.values}, {"protocol_hash", p.protocolHash}});
  const json manifest = {{"format", kManifestFormat},
                         {"title", m.title},
                         {"sweep_file", m.sweepFile},
                         {"base", m.base},
                         {"keys", m.keys},
                         {"plot_regions", m.plotRegions},
                         {"points", points}};
  std::filesystem::create_directories(folder / "points");
  for (const SweepPoint& p : plan.points) {
    const std::filesystem::path dir = pointFolder(folder, p.id);
    std::filesystem::create_directories(dir);
    if (!std::filesystem::exists(dir / "protocol.toml"))
      writeFileAtomically(dir / "protocol.toml", p.protocolText);
  }
  writeFileAtomically(folder / "sweep.json", manifest.dump(2) + "\n");
}

SweepManifest readSweepManifest(const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / "sweep.json";
  if (!std::filesystem::exists(file))
    throw SweepError(folder.string() +
                     " is not a sweep folder (no sweep.json); give the --out folder of a "
                     "`tamponade sweep` run");
  try {
    const json j = json::parse(readFile(file));
    if (j.at("format").get<int>() != kManifestFormat)
      throw SweepError(file.string() + " has manifest format " + j.at("format").dump() +
                       "; this tamponade reads format " + std::to_string(kManifestFormat));
    SweepManifest m;
    m.title = j.at("title").get<std::string>();
    m.sweepFile = j.at("sweep_file").get<std::string>();
    m.base = j.at("base").get<std::string>();
    m.keys = j.at("keys").get<std::vector<std::string>>();
    m.plotRegions = j.at("plot_regions").get<std::vector<std::string>>();
    for (const json& p : j.at("points"))
      m.points.push_back(SweepManifestPoint{p.at("id").get<std::string>(),
                                            p.at("values").get<std::vector<std::string>>(),
                                            p.at("protocol_hash").get<std::string>()});
    return m;
  } catch (const json::exception& e) {
    throw SweepError(file.string() + " is damaged (" + e.what() +
                     "); make the sweep folder again with tamponade sweep SWEEP.toml --out DIR");
  }
}

std::string_view pointStateName(PointState state) {
  return kStateNames[static_cast<std::size_t>(state)];
}

PointRecord readPointRecord(const std::filesystem::path& pointFolder) {
  PointRecord r;
  const std::filesystem::path file = pointFolder / "point.json";
  if (!std::filesystem::exists(file)) return r;
  try {
    const json j = json::parse(readFile(file));
    const std::string state = j.at("state").get<std::string>();
    for (std::size_t k = 0; k < kStateNames.size(); ++k)
      if (kStateNames[k] == state) r.state = static_cast<PointState>(k);
    r.exitCode = j.value("exit_code", 0);
    r.wallSeconds = j.value("wall_seconds", 0.0);
    r.attempts = j.value("attempts", 0);
    r.backend = j.value("backend", "");
    r.host = j.value("host", "");
    r.pid = j.value("pid", 0L);
  } catch (const json::exception& e) {
    throw SweepError(file.string() + " is damaged (" + e.what() +
                     "); remove it and run the sweep again to redo the point");
  }
  return r;
}

void writePointRecord(const std::filesystem::path& pointFolder, const PointRecord& r) {
  const json j = {{"state", pointStateName(r.state)},
                  {"exit_code", r.exitCode},
                  {"wall_seconds", r.wallSeconds},
                  {"attempts", r.attempts},
                  {"backend", r.backend},
                  {"host", r.host},
                  {"pid", r.pid}};
  writeFileAtomically(pointFolder / "point.json", j.dump(2) + "\n");
}

}  // namespace protocols
