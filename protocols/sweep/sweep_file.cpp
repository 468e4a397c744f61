#include "protocols/sweep/sweep_file.h"

#include <toml++/toml.h>
#include <algorithm>
#include <fstream>
#include <sstream>

#include "protocols/coverage/frame_coverage.h"
#include "protocols/format/edit_distance.h"
#include "protocols/format/parameter_table.h"
#include "protocols/sweep/sweep_range.h"

namespace protocols {

namespace {

constexpr std::array<std::string_view, 5> kSweepFileKeys = {"base", "title", "combine", "vary",
                                                            "plots"};

SourceLocation locate(const std::filesystem::path& file, const toml::source_region& region) {
  return SourceLocation{file.string(), static_cast<int>(region.begin.line),
                        static_cast<int>(region.begin.column)};
}

std::vector<std::string> splitPath(const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream in(path);
  for (std::string part; std::getline(in, part, '.');) parts.push_back(part);
  return parts;
}

bool isIndex(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

const ParameterSpec* findSpec(const std::string& key) {
  for (const ParameterSpec& s : parameterTable())
    if (s.key == key) return &s;
  return nullptr;
}

std::string shownValue(const toml::node& node) {
  if (auto s = node.value_exact<std::string>()) return *s;
  std::ostringstream text;
  node.visit([&](const auto& v) { text << toml::toml_formatter(v); });
  return text.str();
}

std::string tomlText(const toml::node& node) {
  std::ostringstream text;
  node.visit([&](const auto& v) { text << toml::toml_formatter(v); });
  return text.str();
}

struct SweepFileReader {
  std::filesystem::path file;
  std::vector<Diagnostic>& problems;

  void error(const toml::node& node, std::string what, std::string fix) {
    problems.push_back(Diagnostic{locate(file, node.source()), std::move(what), std::move(fix)});
  }

  // [vary] "key" = [...] or { from, to, ... }; a dotted key written without quotes makes nested
  // tables, read the same way.
  void readVary(const toml::table& table, const std::string& prefix, SweepPlan& plan) {
    for (const auto& [name, node] : table) {
      const std::string path = prefix + std::string(name.str());
      const SourceLocation keyAt = locate(file, name.source());
      const toml::table* sub = node.as_table();
      if (sub && !sub->contains("from") && !sub->contains("to")) {
        readVary(*sub, path + ".", plan);
        continue;
      }
      std::string fix;
      if (std::string why = sweepKeyProblem(path, fix); !why.empty()) {
        problems.push_back(Diagnostic{keyAt, "[vary] \"" + path + "\" " + why, fix});
        continue;
      }
      SweepKey key{path, keyAt, {}};
      if (sub) {
        key.values = expandRange(*sub, path, locate(file, node.source()), problems);
      } else if (const toml::array* list = node.as_array()) {
        for (const toml::node& item : *list)
          key.values.push_back(
              SweepValue{tomlText(item), shownValue(item), locate(file, item.source())});
        if (list->empty())
          error(node, "[vary] \"" + path + "\" has no values",
                "list at least one value, e.g. [\"80 %\", \"90 %\"]");
      } else {
        error(node, "[vary] \"" + path + "\" must be a list of values or a range",
              "e.g. \"" + path + "\" = [" + tomlText(node) + ", ...]");
      }
      if (!key.values.empty()) plan.keys.push_back(std::move(key));
    }
  }

  void readPlots(const toml::table& plots, SweepPlan& plan) {
    for (const auto& [name, node] : plots) {
      if (name != "regions") {
        error(node, "[plots] has no key '" + std::string(name.str()) + "'",
              "[plots] takes regions = [\"whole retina\", \"macula\"]");
        continue;
      }
      const toml::array* list = node.as_array();
      for (std::size_t k = 0; list && k < list->size(); ++k) {
        const auto region = (*list)[k].value_exact<std::string>();
        const bool known = region && std::any_of(kReportedRegions.begin(), kReportedRegions.end(),
                                                 [&](const auto& r) { return r.name == *region; });
        if (known) {
          plan.plotRegions.push_back(*region);
        } else {
          std::string names;
          for (const auto& r : kReportedRegions)
            names += (names.empty() ? "" : ", ") + std::string(r.name);
          error((*list)[k], "[plots] regions: " + shownValue((*list)[k]) + " is not a region",
                "the regions are: " + names);
        }
      }
      if (!list) error(node, "[plots] regions must be a list of region names", "");
    }
  }

  SweepPlan read(const toml::table& doc) {
    SweepPlan plan;
    plan.file = file;
    for (const auto& [name, node] : doc)
      if (std::find(kSweepFileKeys.begin(), kSweepFileKeys.end(), name.str()) ==
          kSweepFileKeys.end())
        error(node, "unknown key '" + std::string(name.str()) + "' in a sweep file",
              didYouMean(name.str(), kSweepFileKeys) +
                  " a sweep file has base, title, combine, "
                  "[vary] and [plots] (docs/sweeps.md)");
    readBase(doc, plan);
    if (auto title = doc["title"].value<std::string>()) plan.title = *title;
    if (const toml::node* combine = doc.get("combine")) {
      const auto word = combine->value_exact<std::string>();
      if (word == "zip") {
        plan.combine = SweepCombine::kZip;
      } else if (word != "factorial") {
        error(*combine, "combine must be \"factorial\" or \"zip\"",
              "factorial runs every combination of the values; zip pairs the lists' k-th values");
      }
    }
    if (const toml::table* vary = doc["vary"].as_table()) {
      readVary(*vary, "", plan);
      // toml++ keeps a table's keys sorted; the sweep's key order (the plots' x axis is the first
      // key) is the order of the file.
      std::stable_sort(plan.keys.begin(), plan.keys.end(),
                       [](const SweepKey& a, const SweepKey& b) {
                         return std::pair(a.where.line, a.where.column) <
                                std::pair(b.where.line, b.where.column);
                       });
      if (vary->empty())
        error(*vary, "[vary] is empty", "add a key to vary, e.g. \"tamponade.fill\" = [\"80 %\"]");
    } else {
      problems.push_back(Diagnostic{SourceLocation{file.string(), 1, 1},
                                    "the sweep file has no [vary] table",
                                    "add [vary] with the keys to vary, e.g. \"tamponade.fill\" = "
                                    "[\"80 %\", \"90 %\"]"});
    }
    if (const toml::table* plots = doc["plots"].as_table()) readPlots(*plots, plan);
    if (plan.plotRegions.empty()) plan.plotRegions = {"whole retina"};
    return plan;
  }

  void readBase(const toml::table& doc, SweepPlan& plan) {
    const toml::node* base = doc.get("base");
    const auto text = base ? base->value_exact<std::string>() : std::nullopt;
    if (!text) {
      problems.push_back(
          Diagnostic{base ? locate(file, base->source()) : SourceLocation{file.string(), 1, 1},
                     "the sweep file needs base = \"<protocol file>\"",
                     "name the protocol every point starts from, relative to this file's folder"});
      return;
    }
    const std::filesystem::path written(*text);
    plan.base = written.is_absolute() ? written : file.parent_path() / written;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(plan.base, ec))
      error(*base,
            "base protocol '" + *text + "' is not a file (looked for " + plan.base.string() + ")",
            "the path is relative to the sweep file's folder");
  }
};

}  // namespace

std::string sweepKeyProblem(const std::string& path, std::string& fix) {
  std::string spec;
  const ParameterSpec* parent = nullptr;
  bool indexed = false;  // the previous part was an index into `parent`
  for (const std::string& part : splitPath(path)) {
    const bool inArray = parent && parent->kind == ValueKind::kTableArray;
    if (isIndex(part)) {
      if (!inArray || indexed) {
        fix = "a number indexes an array of tables only, e.g. schedule.postures.0.name";
        return "has an index where the protocol has no array of tables";
      }
      indexed = true;
      continue;
    }
    if (inArray && !indexed) {
      fix = "name the element, counting from 0: " + std::string(parent->key) + ".0." + part;
      return "needs the index of the " + std::string(parent->key) + " element";
    }
    indexed = false;
    spec += (spec.empty() ? "" : ".") + part;
    parent = findSpec(spec);
    if (!parent) {
      std::vector<std::string_view> keys;
      for (const ParameterSpec& s : parameterTable()) keys.push_back(s.key);
      fix = didYouMean(spec, keys);
      if (fix.empty()) fix = "see the parameter reference in docs/protocols.md";
      return "is not a protocol key";
    }
  }
  if (parent && (parent->kind == ValueKind::kTable || parent->kind == ValueKind::kTableArray)) {
    std::string children;
    for (std::string_view c : childKeys(parent->key))
      children += (children.empty() ? "" : ", ") + std::string(c);
    fix = "vary one of its keys: " + children;
    return "is a table, not a value";
  }
  if (!parent) {
    fix = "name a key, e.g. \"tamponade.fill\"";
    return "is not a protocol key";
  }
  return {};
}

SweepPlan readSweepFile(const std::filesystem::path& file, std::vector<Diagnostic>& problems) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec)) {
    problems.push_back(Diagnostic{SourceLocation{file.string(), 0, 0}, "cannot open the sweep file",
                                  "check the path (data/sweeps/ has examples)"});
    return {};
  }
  std::ostringstream text;
  text << in.rdbuf();
  toml::table doc;
  try {
    doc = toml::parse(text.str(), file.string());
  } catch (const toml::parse_error& e) {
    problems.push_back(Diagnostic{locate(file, e.source()),
                                  "malformed TOML: " + std::string(e.description()),
                                  "fix the syntax (TOML 1.0, https://toml.io); a dotted key "
                                  "in [vary] needs quotes: \"tamponade.fill\" = [...]"});
    return {};
  }
  return SweepFileReader{file, problems}.read(doc);
}

}  // namespace protocols
