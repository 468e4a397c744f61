// The parameter descriptions of the protocol format: name, kind, unit, range, requirement,
// default and one line of doc for every key. This one table drives the loader (which keys exist,
// "did you mean"), the validator (types, units, ranges) and the reference table in
// docs/protocols.md (renderParameterReference(); a test keeps the document in step), in the
// spirit of docs/developer-guide.md code rule 7.
#pragma once

#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "protocols/format/units.h"

namespace protocols {

enum class ValueKind {
  kTable,             // [name]
  kTableArray,        // [[name]], one table per element
  kInteger,           // TOML integer
  kNumber,            // TOML integer or float, dimensionless
  kQuantity,          // "<number> <unit>" of `dimension` (kFraction also takes a bare number)
  kViscosity,         // dynamic or kinematic viscosity; the unit says which
  kDurationOrSteady,  // a duration or "until steady"
  kString,
  kPath,    // a file path, relative to the protocol file
  kChoice,  // one of `choices`
  kBoolean,
  kEffectSwitch,  // true, false or "auto"
  kDirection,     // [x, y, z] non-zero, normalised on reading
  kStringList,    // ["a", "b"]
};

enum class Requirement { kRequired, kOptional, kConditional };

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

struct ParameterSpec {
  std::string_view key{};  // dotted path; elements of a [[table array]] add their keys to its path
  ValueKind kind = ValueKind::kString;
  Dimension dimension = Dimension::kLength;  // kQuantity, kDurationOrSteady
  std::string_view displayUnit{};            // unit of ranges in the docs and messages
  double min = -kUnbounded;                  // [SI]
  double max = kUnbounded;                   // [SI]
  bool minInclusive = true;
  bool maxInclusive = true;
  std::span<const std::string_view> choices{};  // kChoice
  Requirement requirement = Requirement::kOptional;
  std::string_view condition{};    // kConditional: when it is required / allowed, in words
  std::string_view defaultText{};  // what an absent optional key means
  std::string_view example{};      // a valid TOML value, used in messages and docs
  std::string_view doc{};          // one line

  bool hasRange() const { return min > -kUnbounded || max < kUnbounded; }
};

std::span<const ParameterSpec> parameterTable();
// The spec of `key`; throws std::logic_error for a key not in the table (a programming error).
const ParameterSpec& parameterSpec(std::string_view key);
// The keys directly inside the table at `tablePath` ("" for the top level): "eye" -> "kind", ...
std::vector<std::string_view> childKeys(std::string_view tablePath);

// "[18, 36] mm", "(0, 1]", "> 0 Pa", "" when unbounded: the range in the spec's display unit.
std::string rangeText(const ParameterSpec& spec);
// "length (mm)", "one of: supine, face-down, ...": the type column of the docs.
std::string typeText(const ParameterSpec& spec);

// The Markdown reference table of every key, as included in docs/protocols.md.
std::string renderParameterReference();
// The Markdown table of accepted units per dimension.
std::string renderUnitTable();
// The Markdown table of the accuracy presets' values.
std::string renderAccuracyPresetTable();

}  // namespace protocols
