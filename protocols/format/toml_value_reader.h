// Reads typed, unit-checked values out of a parsed TOML document, driven by the parameter table,
// and collects every problem as a Diagnostic instead of stopping at the first one.
// Internal to protocols/format: the only header of the library that includes toml++.
//
// Like pbrt-v4's ParameterDictionary::ReportUnused, each table remembers nothing of what was
// read; instead reportUnknownKeys() checks every key the file has against the parameter table,
// so a key the file has but the format does not know can never be silently ignored.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "protocols/format/parameter_table.h"
#include "protocols/format/protocol.h"
#include "protocols/format/protocol_error.h"

namespace protocols {

// What durationOrSteady returns for duration = "until steady" and "equilibrium".
inline constexpr double kUntilSteadyDuration = -1.0;
inline constexpr double kEquilibriumDuration = -2.0;

class TomlValueReader {
 public:
  // A table being read: its parameter-table path ("eye.breaks"), its path as shown to the user
  // ("eye.breaks[2]") and where it starts.
  struct Table {
    const toml::table* table = nullptr;
    std::string specPath;
    std::string shownPath;
    SourceLocation where;
  };

  explicit TomlValueReader(std::string file) : file_(std::move(file)) {}

  Table root(const toml::table& document) const;
  SourceLocation at(const toml::source_region& region) const;
  void error(SourceLocation where, std::string what, std::string fix);
  std::vector<Diagnostic>& diagnostics() { return diagnostics_; }

  // Reports keys of `t` that the parameter table does not list for it, with a suggestion.
  void reportUnknownKeys(const Table& t);
  // The node of `key`, or nullptr; reports a missing required key.
  const toml::node* find(const Table& t, std::string_view key);

  std::optional<Table> table(const Table& parent, std::string_view key);
  std::vector<Table> tableArray(const Table& parent, std::string_view key);

  // Each returns nullopt when the key is absent or wrong (the problem is then reported).
  std::optional<Located<double>> quantity(const Table& t, std::string_view key);
  std::optional<Located<Viscosity>> viscosity(const Table& t, std::string_view key);
  std::optional<Located<double>> number(const Table& t, std::string_view key);
  std::optional<Located<int>> integer(const Table& t, std::string_view key);
  std::optional<Located<std::string>> string(const Table& t, std::string_view key);
  // The index of the chosen name in the spec's choices.
  std::optional<Located<std::size_t>> choice(const Table& t, std::string_view key);
  std::optional<Located<bool>> boolean(const Table& t, std::string_view key);
  std::optional<Located<EffectSetting>> effectSwitch(const Table& t, std::string_view key);
  std::optional<Located<std::array<double, 3>>> direction(const Table& t, std::string_view key);
  std::optional<std::vector<Located<std::string>>> stringList(const Table& t, std::string_view key);
  // A duration, or "until steady" (then value = -1).
  // A duration [s], or kUntilSteadyDuration / kEquilibriumDuration for those words.
  std::optional<Located<double>> durationOrSteady(const Table& t, std::string_view key);

  // "eye.axial_length" for messages (with array indices).
  static std::string shownKey(const Table& t, std::string_view key);

 private:
  const ParameterSpec& spec(const Table& t, std::string_view key) const;
  void wrongType(const Table& t, std::string_view key, const toml::node& node,
                 std::string_view expected);
  // Reports a value outside the spec's range; returns whether it is inside.
  bool checkRange(const Table& t, std::string_view key, const ParameterSpec& s,
                  const Located<double>& value);

  std::string file_;
  std::vector<Diagnostic> diagnostics_;
};

// "integer 28", "string \"abc\"", "table": what a node is, for messages.
std::string describeNode(const toml::node& node);

}  // namespace protocols
