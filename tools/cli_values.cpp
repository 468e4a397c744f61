#include "tools/cli_values.h"

#include <cmath>
#include <cstdio>
#include <utility>

namespace tools {
namespace {

// The number std::stod / std::stol (`parse`) reads from the whole of `text`, or nullopt (no
// number, trailing characters, out of range).
template <class Parse>
auto wholeText(const std::string& text, Parse parse) -> std::optional<decltype(parse(text, 0))> {
  std::size_t used = 0;
  try {
    const auto value = parse(text, &used);
    if (!text.empty() && used == text.size()) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

std::optional<long> wholeInteger(const std::string& text) {
  return wholeText(text, [](const std::string& t, std::size_t* n) { return std::stol(t, n); });
}

std::optional<double> wholeNumber(const std::string& text) {
  return wholeText(text, [](const std::string& t, std::size_t* n) { return std::stod(t, n); });
}

std::string inQuotes(const std::string& text) { return "'" + text + "'"; }

std::string shortNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

}  // namespace

CLI::Validator positiveInteger(long max) {
  return CLI::Validator(
      [max](std::string& text) -> std::string {
        const std::optional<long> value = wholeInteger(text);
        if (!value || *value < 1) return inQuotes(text) + " must be a positive whole number";
        if (*value > max)
          return inQuotes(text) + " must be a whole number from 1 to " + std::to_string(max);
        return {};
      },
      "");
}

CLI::Validator wholeNumber(long min, long max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        const std::optional<long> value = wholeInteger(text);
        if (!value) return inQuotes(text) + " must be a whole number";
        if (*value < min || *value > max)
          return inQuotes(text) + " must be a whole number from " + std::to_string(min) + " to " +
                 std::to_string(max);
        return {};
      },
      "");
}

CLI::Validator positiveNumber(double max) {
  return CLI::Validator(
      [max](std::string& text) -> std::string {
        const std::optional<double> value = wholeNumber(text);
        if (!value || !(*value > 0) || !std::isfinite(*value))
          return inQuotes(text) + " must be a positive number";
        if (*value > max)
          return inQuotes(text) + " is above its largest value, " + shortNumber(max);
        return {};
      },
      "");
}

CLI::Validator numberBetween(double min, double max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        const std::optional<double> value = wholeNumber(text);
        if (!value || !(*value >= min && *value <= max))
          return inQuotes(text) + " must be a number from " + shortNumber(min) + " to " +
                 shortNumber(max);
        return {};
      },
      "");
}

std::string wordList(const std::vector<std::string>& words, const char* last) {
  std::string list;
  for (std::size_t k = 0; k < words.size(); ++k) {
    if (k > 0) list += k + 1 == words.size() ? std::string(" ") + last + " " : std::string(", ");
    list += words[k];
  }
  return list;
}

CLI::Validator oneOf(std::vector<std::string> names) {
  return CLI::Validator(
      [names = std::move(names)](std::string& text) -> std::string {
        for (const std::string& name : names)
          if (text == name) return {};
        return inQuotes(text) + " must be " + wordList(names);
      },
      "");
}

std::optional<double> parseMemorySize(const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  std::string unit = text.substr(used);
  if (!unit.empty() && unit.front() == ' ') unit.erase(0, 1);
  const std::pair<const char*, double> units[] = {
      {"MiB", 1048576.0}, {"GiB", 1073741824.0}, {"MB", 1e6}, {"GB", 1e9}};
  for (const auto& [name, bytes] : units)
    if (unit == name && value > 0 && std::isfinite(value)) return value * bytes;
  return std::nullopt;
}

CLI::Validator memorySize() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::optional<double> bytes = parseMemorySize(text);
        if (!bytes)
          return inQuotes(text) +
                 " must be a positive size with a unit: MiB, GiB, MB or GB (e.g. 4 GiB)";
        char exact[40];  // %.17g: the double itself, read back unchanged
        std::snprintf(exact, sizeof exact, "%.17g", *bytes);
        text = exact;
        return {};
      },
      "");
}

}  // namespace tools
