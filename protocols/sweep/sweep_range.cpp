#include "protocols/sweep/sweep_range.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include <fmt/format.h>

namespace protocols {

namespace {

// A range end or step: a TOML number, or a string "<number> <unit>".
struct RangeNumber {
  double value = 0.0;
  std::string unit;  // "" for a bare number
  bool isString = false;
  bool isInteger = false;
};

std::optional<RangeNumber> readRangeNumber(const toml::node& node) {
  if (auto i = node.value_exact<std::int64_t>())
    return RangeNumber{static_cast<double>(*i), "", false, true};
  if (auto d = node.value_exact<double>()) return RangeNumber{*d, "", false, false};
  const auto text = node.value_exact<std::string>();
  if (!text) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text->c_str(), &end);
  if (end == text->c_str() || !std::isfinite(value)) return std::nullopt;
  std::string unit(end);
  unit.erase(0, unit.find_first_not_of(' '));
  unit.erase(unit.find_last_not_of(' ') + 1);
  return RangeNumber{value, unit, true, false};
}

std::string withUnit(double value, const RangeNumber& like) {
  return fmt::format("{}{}{}", shortestNumber(value), like.unit.empty() ? "" : " ", like.unit);
}

std::string valueToml(double value, const RangeNumber& like, bool integers) {
  if (like.isString) return fmt::format("\"{}\"", withUnit(value, like));
  if (integers) return std::to_string(std::llround(value));
  std::string text = shortestNumber(value);
  if (text.find_first_of(".en") == std::string::npos) text += ".0";  // a TOML float
  return text;
}

}  // namespace

std::string shortestNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", value);
  return text;
}

std::vector<SweepValue> expandRange(const toml::table& range, const std::string& key,
                                    const SourceLocation& where,
                                    std::vector<Diagnostic>& problems) {
  const std::string fix =
      "write a range as { from = \"60 %\", to = \"100 %\", step = \"5 %\" } or { from = 0.8, "
      "to = 0.95, count = 4 } (both ends included), or list the values: [\"80 %\", \"90 %\"]";
  auto fail = [&](const std::string& what) {
    problems.push_back(Diagnostic{where, "[vary] \"" + key + "\": " + what, fix});
    return std::vector<SweepValue>{};
  };
  for (const auto& [name, node] : range)
    if (name != "from" && name != "to" && name != "step" && name != "count")
      return fail("a range has no key '" + std::string(name.str()) + "'");
  const toml::node* fromNode = range.get("from");
  const toml::node* toNode = range.get("to");
  if (!fromNode || !toNode) return fail("a range needs both from and to");
  const auto from = readRangeNumber(*fromNode);
  const auto to = readRangeNumber(*toNode);
  if (!from || !to) return fail("from and to must be numbers or strings \"<number> <unit>\"");
  if (from->unit != to->unit || from->isString != to->isString)
    return fail("from and to are in different units ('" + from->unit + "', '" + to->unit + "')");
  const toml::node* stepNode = range.get("step");
  const toml::node* countNode = range.get("count");
  if ((stepNode != nullptr) == (countNode != nullptr)) return fail("give step or count, not both");

  std::vector<double> values;
  bool integers = from->isInteger && to->isInteger;
  if (countNode) {
    const auto count = countNode->value_exact<std::int64_t>();
    if (!count || *count < 1) return fail("count must be a whole number of at least 1");
    if (*count == 1 && from->value != to->value) return fail("count = 1 needs from = to");
    if (*count > 1'000'000) return fail("count " + std::to_string(*count) + " is too many points");
    integers = false;
    for (std::int64_t k = 0; k < *count; ++k)
      values.push_back(*count == 1
                           ? from->value
                           : from->value + static_cast<double>(k) * (to->value - from->value) /
                                               static_cast<double>(*count - 1));
  } else {
    const auto step = readRangeNumber(*stepNode);
    if (!step || step->unit != from->unit || step->isString != from->isString)
      return fail("step must be in the unit of from and to ('" + from->unit + "')");
    if (!(step->value != 0.0)) return fail("step must not be 0");
    integers = integers && step->isInteger;
    const double span = (to->value - from->value) / step->value;
    if (span < -1e-9)
      return fail("from " + withUnit(from->value, *from) + " to " + withUnit(to->value, *from) +
                  " with step " + withUnit(step->value, *from) +
                  " has no points (the step goes the other way)");
    if (span > 1e6) return fail("the range has more than a million points");
    const auto steps = static_cast<std::int64_t>(std::floor(span + 1e-9));
    for (std::int64_t k = 0; k <= steps; ++k)
      values.push_back(from->value + static_cast<double>(k) * step->value);
  }
  std::vector<SweepValue> out;
  for (double v : values) {
    const std::string toml = valueToml(v, *from, integers);
    const std::string shown = from->isString ? toml.substr(1, toml.size() - 2) : toml;
    out.push_back(SweepValue{toml, shown, where});
  }
  return out;
}

}  // namespace protocols
