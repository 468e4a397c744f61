// The values of a range in a sweep's [vary] table: { from = "60 %", to = "100 %", step = "5 %" }
// or { from = 0.8, to = 0.95, count = 4 } (docs/sweeps.md). Both ends are included.
#pragma once

#include <toml++/toml.h>
#include <string>
#include <vector>

#include "protocols/format/protocol_error.h"
#include "protocols/sweep/sweep_plan.h"

namespace protocols {

// The values of `range` (the value of key `key`, at `where`). Problems are appended to
// `problems` (and the result is then empty).
std::vector<SweepValue> expandRange(const toml::table& range, const std::string& key,
                                    const SourceLocation& where, std::vector<Diagnostic>& problems);

// A number as text with 12 significant digits and no trailing zeros: "0.9", "75", "1e-07"
// (0.8 + 2 * 0.05 prints as 0.9, not as its last-bit error).
std::string shortestNumber(double value);

}  // namespace protocols
