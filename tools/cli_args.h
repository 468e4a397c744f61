// Parsing helpers shared by the `tamponade` sub-commands: one usage-error type (exit code 2) and
// the option-value parsers several commands use.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tools {

// Wrong command-line usage: the command prints the message and its usage text and exits 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "a,b,,c" -> {"a", "b", "c"}: empty items are dropped.
inline std::vector<std::string> splitList(std::string_view text) {
  std::vector<std::string> items;
  std::stringstream in{std::string(text)};
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) items.push_back(item);
  return items;
}

// The number std::stod / std::stol (`parse`) reads at the start of `text`, and in `used` how many
// characters it took (0 when none: no number, or out of range).
template <class Parse>
auto leadingNumber(const std::string& text, std::size_t& used, Parse parse) {
  used = 0;
  try {
    return parse(text, &used);
  } catch (const std::exception&) {
    used = 0;
    return decltype(parse(text, &used)){};
  }
}

// The whole of `text` as a finite number > 0, or a UsageError naming `option`.
inline double parsePositive(const std::string& text, const char* option) {
  std::size_t used = 0;
  const double value = leadingNumber(
      text, used, [](const std::string& t, std::size_t* n) { return std::stod(t, n); });
  if (used != text.size() || !(value > 0) || !std::isfinite(value))
    throw UsageError(std::string(option) + " '" + text + "' must be a positive number");
  return value;
}

// The whole of `text` as an integer > 0, or a UsageError naming `option` ("abc", "12x", "0" and
// values beyond long are refused, where atol would read them as 0 or wrap).
inline long parsePositiveInteger(const std::string& text, const char* option) {
  std::size_t used = 0;
  const long value = leadingNumber(
      text, used, [](const std::string& t, std::size_t* n) { return std::stol(t, n); });
  if (text.empty() || used != text.size() || value < 1)
    throw UsageError(std::string(option) + " '" + text + "' must be a positive whole number");
  return value;
}

// A memory size with its unit, "512 MiB", "8GiB", "2 GB", as bytes; a UsageError naming `option`
// for anything else (a bare number is refused: MB and MiB differ by 5 %).
inline double parseMemorySize(const std::string& text, const char* option) {
  std::size_t used = 0;
  const double value = leadingNumber(
      text, used, [](const std::string& t, std::size_t* n) { return std::stod(t, n); });
  std::string unit = used > 0 ? text.substr(used) : std::string();
  if (!unit.empty() && unit.front() == ' ') unit.erase(0, 1);
  const std::pair<const char*, double> units[] = {
      {"MiB", 1048576.0}, {"GiB", 1073741824.0}, {"MB", 1e6}, {"GB", 1e9}};
  for (const auto& [name, bytes] : units)
    if (used > 0 && unit == name && value > 0 && std::isfinite(value)) return value * bytes;
  throw UsageError(std::string(option) + " '" + text +
                   "' must be a positive size with a unit: MiB, GiB, MB or GB (e.g. 4 GiB)");
}

}  // namespace tools
