// Parsing helpers shared by the `tamponade` sub-commands: one usage-error type (exit code 2) and
// the option-value parsers several commands use.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
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

// The whole of `text` as a finite number > 0, or a UsageError naming `option`.
inline double parsePositive(const std::string& text, const char* option) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value > 0) || !std::isfinite(value))
    throw UsageError(std::string(option) + " '" + text + "' must be a positive number");
  return value;
}

}  // namespace tools
