#include "protocols/format/toml_value_reader.h"

#include <cmath>

#include <fmt/format.h>

#include "protocols/format/edit_distance.h"

namespace protocols {

namespace {

std::string shortNumber(double v) { return formatIn(v, ""); }

std::string withArticle(std::string_view noun) {
  const bool vowel =
      !noun.empty() && std::string_view("aeiou").find(noun.front()) != std::string_view::npos;
  return (vowel ? "an " : "a ") + std::string(noun);
}

// The example of a spec as a TOML assignment, for "how to fix it": `fill = "90 %"`.
std::string exampleOf(const ParameterSpec& s, std::string_view key) {
  if (s.example.empty()) return {};
  return "e.g. " + std::string(key) + " = " + std::string(s.example);
}

}  // namespace

std::string describeNode(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "string \"" + std::string(*node.value<std::string_view>()) + "\"";
    case toml::node_type::integer: return "integer " + std::to_string(*node.value<std::int64_t>());
    case toml::node_type::floating_point: return "number " + shortNumber(*node.value<double>());
    case toml::node_type::boolean: return *node.value<bool>() ? "boolean true" : "boolean false";
    case toml::node_type::table: return "table";
    case toml::node_type::array: return "array";
    case toml::node_type::date: return "date";
    case toml::node_type::time: return "time";
    case toml::node_type::date_time: return "date-time";
    case toml::node_type::none: return "nothing";
  }
  return "value";
}

TomlValueReader::Table TomlValueReader::root(const toml::table& document) const {
  return Table{&document, "", "", SourceLocation{file_, 1, 1}};
}

SourceLocation TomlValueReader::at(const toml::source_region& region) const {
  // A value moved in from another file (a sweep's [vary]) keeps that file's name.
  const bool otherFile = region.path && !region.path->empty();
  return SourceLocation{otherFile ? *region.path : file_, static_cast<int>(region.begin.line),
                        static_cast<int>(region.begin.column)};
}

void TomlValueReader::error(SourceLocation where, std::string what, std::string fix) {
  diagnostics_.push_back(Diagnostic{std::move(where), std::move(what), std::move(fix)});
}

std::string TomlValueReader::shownKey(const Table& t, std::string_view key) {
  return t.shownPath.empty() ? std::string(key) : t.shownPath + "." + std::string(key);
}

const ParameterSpec& TomlValueReader::spec(const Table& t, std::string_view key) const {
  return parameterSpec(t.specPath.empty() ? std::string(key) : t.specPath + "." + std::string(key));
}

void TomlValueReader::reportUnknownKeys(const Table& t) {
  const std::vector<std::string_view> known = childKeys(t.specPath);
  for (auto&& [key, node] : *t.table) {
    (void)node;
    bool isKnown = false;
    for (std::string_view k : known) isKnown = isKnown || k == key.str();
    if (isKnown) continue;
    const std::string where = t.shownPath.empty() ? "at the top level" : "in [" + t.shownPath + "]";
    std::string fix = didYouMean(key.str(), known);
    const std::string list = "known keys " + where + ": " + joinNames(known);
    fix += fix.empty() ? list : " (" + list + ")";
    error(at(key.source()), "unknown key '" + std::string(key.str()) + "' " + where, fix);
  }
}

const toml::node* TomlValueReader::find(const Table& t, std::string_view key) {
  const toml::node* node = t.table->get(key);
  if (node == nullptr) {
    const ParameterSpec& s = spec(t, key);
    if (s.requirement == Requirement::kRequired) {
      const std::string where =
          t.shownPath.empty() ? "at the top level" : "in [" + t.shownPath + "]";
      std::string fix = s.kind == ValueKind::kTable ? "add the table [" + std::string(s.key) + "]"
                        : s.kind == ValueKind::kTableArray
                            ? "add at least one [[" + std::string(s.key) + "]] table"
                            : "add " + std::string(key) + " = " + std::string(s.example);
      error(t.where, "missing required key '" + shownKey(t, key) + "' " + where,
            fix + " (" + std::string(s.doc) + ")");
    }
  }
  return node;
}

void TomlValueReader::wrongType(const Table& t, std::string_view key, const toml::node& node,
                                std::string_view expected) {
  const ParameterSpec& s = spec(t, key);
  error(at(node.source()),
        shownKey(t, key) + " must be " + std::string(expected) + ", not a " + describeNode(node),
        exampleOf(s, key));
}

bool TomlValueReader::checkRange(const Table& t, std::string_view key, const ParameterSpec& s,
                                 const Located<double>& value) {
  const double v = value.value;
  const bool aboveMin = s.minInclusive ? v >= s.min : v > s.min;
  const bool belowMax = s.maxInclusive ? v <= s.max : v < s.max;
  if (aboveMin && belowMax) return true;
  std::string shown = formatIn(v, s.displayUnit);
  error(
      value.where,
      fmt::format("{} = {} is outside the allowed range {}", shownKey(t, key), shown, rangeText(s)),
      s.example.empty() ? std::string(s.doc) : fmt::format("{} {}", s.doc, exampleOf(s, key)));
  return false;
}

std::optional<TomlValueReader::Table> TomlValueReader::table(const Table& parent,
                                                             std::string_view key) {
  const toml::node* node = find(parent, key);
  if (node == nullptr) return std::nullopt;
  if (!node->is_table()) {
    wrongType(parent, key, *node, "a table [" + shownKey(parent, key) + "]");
    return std::nullopt;
  }
  Table t{node->as_table(), std::string(spec(parent, key).key), shownKey(parent, key),
          at(node->source())};
  reportUnknownKeys(t);
  return t;
}

std::vector<TomlValueReader::Table> TomlValueReader::tableArray(const Table& parent,
                                                                std::string_view key) {
  std::vector<Table> tables;
  const toml::node* node = find(parent, key);
  if (node == nullptr) return tables;
  const toml::array* array = node->as_array();
  const std::string name = shownKey(parent, key);
  if (array == nullptr || !array->is_array_of_tables()) {
    wrongType(parent, key, *node, "an array of tables, each written [[" + name + "]]");
    return tables;
  }
  for (std::size_t k = 0; k < array->size(); ++k) {
    const toml::node& element = *array->get(k);
    Table t{element.as_table(), std::string(spec(parent, key).key),
            name + "[" + std::to_string(k + 1) + "]", at(element.source())};
    reportUnknownKeys(t);
    tables.push_back(std::move(t));
  }
  return tables;
}

std::optional<Located<double>> TomlValueReader::quantity(const Table& t, std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  const ParameterSpec& s = spec(t, key);
  Located<double> result{0.0, at(node->source())};
  if (node->is_number()) {
    const double v = *node->value<double>();
    if (s.dimension != Dimension::kFraction) {
      error(result.where,
            shownKey(t, key) + " = " + shortNumber(v) + " has no unit, and " +
                withArticle(dimensionName(s.dimension)) + " needs one",
            "write it as a string with a unit, e.g. " + std::string(key) + " = \"" +
                shortNumber(v) + " " + std::string(s.displayUnit) + "\" (" +
                std::string(dimensionName(s.dimension)) + " units: " + unitSymbols(s.dimension) +
                ")");
      return std::nullopt;
    }
    result.value = v;
  } else if (node->is_string()) {
    try {
      result.value = parseQuantity(*node->value<std::string_view>(), s.dimension);
    } catch (const UnitError& e) {
      error(result.where, shownKey(t, key) + ": " + e.problem(), e.fix());
      return std::nullopt;
    }
  } else {
    wrongType(t, key, *node,
              "a " + std::string(dimensionName(s.dimension)) + " written as a string with a unit");
    return std::nullopt;
  }
  if (!checkRange(t, key, s, result)) return std::nullopt;
  return result;
}

std::optional<Located<Viscosity>> TomlValueReader::viscosity(const Table& t, std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  const ParameterSpec& s = spec(t, key);
  const SourceLocation where = at(node->source());
  constexpr std::array kAllowed = {Dimension::kDynamicViscosity, Dimension::kKinematicViscosity};
  if (!node->is_string()) {
    if (node->is_number())
      error(where,
            shownKey(t, key) + " = " + describeNode(*node) +
                " has no unit, and a viscosity needs one",
            "say which viscosity it is with the unit: \"1000 cSt\" (kinematic) or \"970 mPa s\" "
            "(dynamic)");
    else
      wrongType(t, key, *node, "a viscosity written as a string with a unit");
    return std::nullopt;
  }
  Quantity q{};
  try {
    q = parseQuantity(*node->value<std::string_view>(), kAllowed);
  } catch (const UnitError& e) {
    error(where, shownKey(t, key) + ": " + e.problem(), e.fix());
    return std::nullopt;
  }
  if (!checkRange(t, key, s, Located<double>{q.value, where})) return std::nullopt;
  const ViscosityKind kind = q.dimension == Dimension::kDynamicViscosity
                                 ? ViscosityKind::kDynamic
                                 : ViscosityKind::kKinematic;
  return Located<Viscosity>{Viscosity{q.value, kind}, where};
}

std::optional<Located<double>> TomlValueReader::number(const Table& t, std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  if (!node->is_number()) {
    wrongType(t, key, *node, "a plain number");
    return std::nullopt;
  }
  Located<double> result{*node->value<double>(), at(node->source())};
  if (!checkRange(t, key, spec(t, key), result)) return std::nullopt;
  return result;
}

std::optional<Located<int>> TomlValueReader::integer(const Table& t, std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  if (!node->is_integer()) {
    wrongType(t, key, *node, "an integer");
    return std::nullopt;
  }
  const std::int64_t v = *node->value<std::int64_t>();
  Located<double> asDouble{static_cast<double>(v), at(node->source())};
  if (!checkRange(t, key, spec(t, key), asDouble)) return std::nullopt;
  return Located<int>{static_cast<int>(v), asDouble.where};
}

std::optional<Located<std::string>> TomlValueReader::string(const Table& t, std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  if (!node->is_string()) {
    wrongType(t, key, *node, "a string");
    return std::nullopt;
  }
  return Located<std::string>{std::string(*node->value<std::string_view>()), at(node->source())};
}

std::optional<Located<std::size_t>> TomlValueReader::choice(const Table& t, std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  const ParameterSpec& s = spec(t, key);
  if (!node->is_string()) {
    wrongType(t, key, *node, "a string, one of " + joinNames(s.choices, true));
    return std::nullopt;
  }
  const std::string_view value = *node->value<std::string_view>();
  for (std::size_t k = 0; k < s.choices.size(); ++k)
    if (s.choices[k] == value) return Located<std::size_t>{k, at(node->source())};
  std::string fix = didYouMean(value, s.choices);
  fix += fix.empty() ? "choose one of " + joinNames(s.choices, true)
                     : " (choose one of " + joinNames(s.choices, true) + ")";
  error(at(node->source()),
        "unknown " + std::string(key) + " '" + std::string(value) + "' for " + shownKey(t, key),
        fix);
  return std::nullopt;
}

std::optional<Located<bool>> TomlValueReader::boolean(const Table& t, std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  if (!node->is_boolean()) {
    wrongType(t, key, *node, "true or false");
    return std::nullopt;
  }
  return Located<bool>{*node->value<bool>(), at(node->source())};
}

std::optional<Located<EffectSetting>> TomlValueReader::effectSwitch(const Table& t,
                                                                    std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  const SourceLocation where = at(node->source());
  if (node->is_boolean())
    return Located<EffectSetting>{*node->value<bool>() ? EffectSetting::kOn : EffectSetting::kOff,
                                  where};
  if (node->is_string() && *node->value<std::string_view>() == "auto")
    return Located<EffectSetting>{EffectSetting::kAuto, where};
  wrongType(t, key, *node, "true (force on), false (force off) or \"auto\"");
  return std::nullopt;
}

std::optional<Located<std::array<double, 3>>> TomlValueReader::direction(const Table& t,
                                                                         std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  const toml::array* array = node->as_array();
  const SourceLocation where = at(node->source());
  bool ok = array != nullptr && array->size() == 3;
  std::array<double, 3> v{};
  for (std::size_t k = 0; ok && k < 3; ++k) {
    ok = array->get(k)->is_number();
    if (ok) v[k] = *array->get(k)->value<double>();
  }
  if (!ok) {
    wrongType(t, key, *node, "an array of three numbers [x, y, z]");
    return std::nullopt;
  }
  if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) {
    error(where, shownKey(t, key) + " has a NaN or infinite component",
          "give three finite numbers, e.g. [0, -1, 0] (upright)");
    return std::nullopt;
  }
  const double norm = std::hypot(v[0], v[1], v[2]);  // no overflow for huge components
  if (!(norm > 1e-12) || !std::isfinite(norm)) {
    error(where, shownKey(t, key) + " is a zero vector and has no direction",
          "give the direction gravity pulls in the eye frame, e.g. [0, -1, 0] (upright)");
    return std::nullopt;
  }
  for (double& c : v) c /= norm;
  return Located<std::array<double, 3>>{v, where};
}

std::optional<std::vector<Located<std::string>>> TomlValueReader::stringList(const Table& t,
                                                                             std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  const toml::array* array = node->as_array();
  if (array == nullptr || (!array->empty() && !array->is_homogeneous(toml::node_type::string))) {
    wrongType(t, key, *node, "an array of strings");
    return std::nullopt;
  }
  std::vector<Located<std::string>> values;
  for (const toml::node& element : *array)
    values.push_back({std::string(*element.value<std::string_view>()), at(element.source())});
  return values;
}

std::optional<Located<double>> TomlValueReader::durationOrSteady(const Table& t,
                                                                 std::string_view key) {
  const toml::node* node = find(t, key);
  if (node == nullptr) return std::nullopt;
  constexpr std::string_view kSteady = "until steady";
  constexpr std::string_view kEquilibrium = "equilibrium";
  if (node->is_string()) {
    const std::string_view text = *node->value<std::string_view>();
    if (text == kSteady) return Located<double>{kUntilSteadyDuration, at(node->source())};
    if (text == kEquilibrium) return Located<double>{kEquilibriumDuration, at(node->source())};
    const bool startsLikeNumber =
        !text.empty() &&
        std::string_view("0123456789.+-").find(text.front()) != std::string_view::npos;
    if (!startsLikeNumber) {
      error(at(node->source()),
            shownKey(t, key) + " = \"" + std::string(text) +
                "\" is neither a duration, \"until steady\" nor \"equilibrium\"",
            editDistance(text, kSteady) <= 3        ? "did you mean \"until steady\"?"
            : editDistance(text, kEquilibrium) <= 3 ? "did you mean \"equilibrium\"?"
                                                    : "write a duration like \"10 min\", \"until "
                                                      "steady\" or \"equilibrium\"");
      return std::nullopt;
    }
  }
  return quantity(t, key);
}

}  // namespace protocols
