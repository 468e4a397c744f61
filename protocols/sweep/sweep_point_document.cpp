#include "protocols/sweep/sweep_point_document.h"

#include <algorithm>
#include <sstream>

namespace protocols {

namespace {

bool isIndex(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// `value`'s TOML text parsed as if it stood where the sweep file has it, so that the node's
// source region names the sweep file, line and column.
toml::table valueAtItsPlace(const SweepValue& value) {
  const int line = std::max(value.where.line, 1);
  const int column = std::max(value.where.column, 3);
  const std::string text = std::string(static_cast<std::size_t>(line - 1), '\n') +
                           std::string(static_cast<std::size_t>(column - 3), ' ') +
                           "v=" + value.toml + "\n";
  return toml::parse(text, value.where.file);
}

// Sets `path` of `doc` to `value` (moved, keeping its source region), creating missing tables.
// Returns why it cannot ("" when done).
std::string setAt(toml::table& doc, const std::string& path, toml::node& value) {
  std::vector<std::string> parts;
  std::stringstream in(path);
  for (std::string part; std::getline(in, part, '.');) parts.push_back(part);
  toml::node* at = &doc;
  std::string shown;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const bool last = k + 1 == parts.size();
    const std::string& part = parts[k];
    if (toml::array* array = at->as_array(); array && isIndex(part)) {
      const std::size_t index = std::stoul(part);
      if (index >= array->size())
        return "the base protocol's " + shown + " has " + std::to_string(array->size()) +
               " element(s), numbered from 0, so " + part + " is not one of them";
      if (last) {
        value.visit([&](auto& v) {
          array->replace(array->cbegin() + static_cast<long>(index), std::move(v));
        });
        return {};
      }
      at = array->get(index);
    } else if (toml::table* table = at->as_table()) {
      if (last) {
        value.visit([&](auto& v) { table->insert_or_assign(part, std::move(v)); });
        return {};
      }
      if (!table->contains(part)) {
        if (isIndex(parts[k + 1]))
          return "the base protocol has no " + (shown.empty() ? "" : shown + ".") + part +
                 " to index";
        table->insert(part, toml::table{});
      }
      at = table->get(part);
    } else {
      return "the base protocol's " + shown + " is not a table";
    }
    shown += (shown.empty() ? "" : ".") + part;
  }
  return {};
}

}  // namespace

toml::table pointDocument(std::string_view baseText, const SweepPlan& plan, const SweepPoint& point,
                          std::vector<Diagnostic>& problems) {
  toml::table doc = toml::parse(baseText, plan.base.string());
  for (std::size_t k = 0; k < plan.keys.size(); ++k) {
    const SweepKey& key = plan.keys[k];
    const SweepValue& value = key.values[point.value[k]];
    toml::table holder = valueAtItsPlace(value);
    if (std::string why = setAt(doc, key.path, *holder.get("v")); !why.empty())
      problems.push_back(Diagnostic{key.where, "[vary] \"" + key.path + "\": " + why,
                                    "vary an element the base protocol has"});
  }
  return doc;
}

std::string pointProtocolText(toml::table document, const SweepPlan& plan,
                              const SweepPoint& point) {
  if (auto mesh = document["eye"]["mesh"].value<std::string>()) {
    const std::filesystem::path written(*mesh);
    if (!written.is_absolute())
      document["eye"].as_table()->insert_or_assign(
          "mesh",
          std::filesystem::absolute(plan.base.parent_path() / written).lexically_normal().string());
  }
  const bool titleVaried = std::any_of(plan.keys.begin(), plan.keys.end(),
                                       [](const SweepKey& k) { return k.path == "title"; });
  if (!titleVaried) {
    const std::string baseTitle =
        document["title"].value_or(plan.title.empty() ? plan.base.stem().string() : plan.title);
    document.insert_or_assign("title", baseTitle + " [" + plan.describe(point) + "]");
  }
  std::ostringstream text;
  text << "# Sweep point " << point.id << " of " << plan.points.size() << ": "
       << plan.describe(point) << "\n# made by tamponade sweep from "
       << plan.file.filename().string() << " (base " << plan.base.filename().string() << ")\n\n"
       << toml::toml_formatter(document) << "\n";
  return text.str();
}

}  // namespace protocols
