#include "protocols/sweep/sweep_plan.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "protocols/format/parse_protocol_document.h"
#include "protocols/sweep/sweep_file.h"
#include "protocols/sweep/sweep_point_document.h"

namespace protocols {

namespace {

std::string pointId(std::size_t index, std::size_t count) {
  const std::size_t width = std::max<std::size_t>(3, std::to_string(count).size());
  return fmt::format("p{:0>{}}", index + 1, width);
}

// The points' value indices: every combination (the last key varying fastest), or the lists'
// k-th values together. Refuses zip lists of different lengths and more than `maxPoints` points.
std::vector<std::vector<std::size_t>> combinations(const SweepPlan& plan, std::size_t maxPoints,
                                                   std::vector<Diagnostic>& problems) {
  double count = plan.keys.empty() ? 0.0 : 1.0;  // a double: a typo'd range must not overflow
  for (const SweepKey& key : plan.keys) {
    const auto n = static_cast<double>(key.values.size());
    if (plan.combine == SweepCombine::kFactorial) {
      count *= n;
    } else if (n != static_cast<double>(plan.keys.front().values.size())) {
      problems.push_back(Diagnostic{
          key.where,
          "[vary] \"" + key.path + "\" has " + std::to_string(key.values.size()) +
              " values but \"" + plan.keys.front().path + "\" has " +
              std::to_string(plan.keys.front().values.size()),
          "combine = \"zip\" pairs the k-th values of every key: give each the same number"});
    } else {
      count = n;
    }
  }
  if (count > static_cast<double>(maxPoints)) {
    char shown[32];
    std::snprintf(shown, sizeof shown, "%.0f", count);
    problems.push_back(Diagnostic{SourceLocation{plan.file.string(), 1, 1},
                                  "the sweep has " + std::string(shown) +
                                      " points, more than --max-points " +
                                      std::to_string(maxPoints),
                                  "check the ranges' steps, or raise --max-points if you mean it"});
  }
  if (!problems.empty()) return {};
  std::vector<std::vector<std::size_t>> points;
  std::vector<std::size_t> at(plan.keys.size(), 0);
  for (std::size_t p = 0; p < static_cast<std::size_t>(count); ++p) {
    if (plan.combine == SweepCombine::kZip) std::fill(at.begin(), at.end(), p);
    points.push_back(at);
    for (std::size_t k = plan.keys.size(); k-- > 0 && plan.combine == SweepCombine::kFactorial;) {
      if (++at[k] < plan.keys[k].values.size()) break;
      at[k] = 0;
    }
  }
  return points;
}

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Each distinct problem once, saying which points it affects.
std::vector<Diagnostic> mergePointProblems(
    const std::vector<std::pair<Diagnostic, std::string>>& found, std::size_t pointCount) {
  std::vector<Diagnostic> merged;
  std::map<std::string, std::vector<std::string>> pointsOf;
  for (const auto& [diagnostic, id] : found) {
    auto& ids = pointsOf[diagnostic.toString()];
    if (ids.empty()) merged.push_back(diagnostic);
    if (ids.empty() || ids.back() != id) ids.push_back(id);
  }
  for (Diagnostic& d : merged) {
    const auto& ids = pointsOf[d.toString()];
    std::string which = ids.size() == pointCount ? "every point" : "point";
    if (ids.size() < pointCount) {
      which += ids.size() > 1 ? "s " : " ";
      for (std::size_t k = 0; k < ids.size() && k < 6; ++k) which += (k ? ", " : "") + ids[k];
      if (ids.size() > 6) which += " and " + std::to_string(ids.size() - 6) + " more";
    }
    d.what += " (in " + which + ")";
  }
  return merged;
}

}  // namespace

std::string SweepPlan::describe(const SweepPoint& point) const {
  std::string text;
  for (std::size_t k = 0; k < keys.size(); ++k)
    text += (k ? ", " : "") + keys[k].path + " = " + keys[k].values[point.value[k]].shown;
  return text;
}

SweepPlan planSweep(const std::filesystem::path& sweepFile, std::size_t maxPoints) {
  std::vector<Diagnostic> problems;
  SweepPlan plan = readSweepFile(sweepFile, problems);
  std::stable_sort(problems.begin(), problems.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::pair(a.where.line, a.where.column) < std::pair(b.where.line, b.where.column);
  });
  if (!problems.empty()) throw ProtocolError(problems);
  const auto values = combinations(plan, maxPoints, problems);
  if (!problems.empty()) throw ProtocolError(problems);
  for (std::size_t p = 0; p < values.size(); ++p)
    plan.points.push_back(SweepPoint{pointId(p, values.size()), values[p], {}});

  const std::string baseText = readText(plan.base);
  std::vector<std::pair<Diagnostic, std::string>> found;
  for (SweepPoint& point : plan.points) {
    std::vector<Diagnostic> placement;
    toml::table doc;
    try {
      doc = pointDocument(baseText, plan, point, placement);
    } catch (const toml::parse_error& e) {  // the base protocol's syntax: once, at its place
      const toml::source_region& at = e.source();
      throw ProtocolError({Diagnostic{
          SourceLocation{at.path ? *at.path : plan.base.string(), static_cast<int>(at.begin.line),
                         static_cast<int>(at.begin.column)},
          "malformed TOML: " + std::string(e.description()),
          "fix the syntax (TOML 1.0, https://toml.io)"}});
    }
    for (const Diagnostic& d : placement) found.emplace_back(d, point.id);
    if (!placement.empty()) continue;
    try {
      parseProtocolDocument(doc, plan.base);
    } catch (const ProtocolError& e) {
      for (const Diagnostic& d : e.diagnostics()) found.emplace_back(d, point.id);
      continue;
    }
    point.protocolText = pointProtocolText(std::move(doc), plan, point);
  }
  if (!found.empty()) throw ProtocolError(mergePointProblems(found, plan.points.size()));
  return plan;
}

}  // namespace protocols
