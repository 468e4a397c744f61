// A parameter study: a base protocol and the keys to vary (docs/sweeps.md). planSweep() reads the
// sweep file, expands it into points and validates every point as a protocol before anything
// runs; an invalid point refuses the whole sweep with the file, line and column of the value that
// broke it.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "protocols/format/source_location.h"

namespace protocols {

// One value a key takes: its TOML text and where the sweep file gives it (a range's values are
// all placed at the range).
struct SweepValue {
  std::string toml;   // e.g. "\"90 %\"", "0.9", "[0, 0, 1]"
  std::string shown;  // for tables and plots: "90 %" (strings without their quotes)
  SourceLocation where;
};

// A varied key, e.g. "tamponade.fill" or "schedule.postures.0.name" (a number indexes an array
// of tables from 0).
struct SweepKey {
  std::string path;
  SourceLocation where;
  std::vector<SweepValue> values;
};

enum class SweepCombine { kFactorial, kZip };

struct SweepPoint {
  std::string id;                  // "p001": the point's folder name, in sweep order
  std::vector<std::size_t> value;  // per key, the index into its values
  std::string protocolText;        // the point's whole protocol, TOML, self-contained
};

struct SweepPlan {
  std::filesystem::path file;  // the sweep file as given
  std::filesystem::path base;  // the base protocol, resolved against the sweep file's folder
  std::string title;
  SweepCombine combine = SweepCombine::kFactorial;
  std::vector<SweepKey> keys;
  std::vector<std::string> plotRegions;  // report regions, one plot panel each
  std::vector<SweepPoint> points;

  // "tamponade.fill = 90 %, schedule.postures.0.name = upright"
  std::string describe(const SweepPoint& point) const;
};

// The default refusal threshold of planSweep(): a sweep larger than this is most likely a typo
// in a range's step (the command line's --max-points raises it).
inline constexpr std::size_t kDefaultMaxSweepPoints = 1000;

// Reads, expands and validates. Throws ProtocolError listing every problem (of the sweep file
// and of every point, each point's problems once with the points it affects), or when the sweep
// has more than `maxPoints` points.
SweepPlan planSweep(const std::filesystem::path& sweepFile,
                    std::size_t maxPoints = kDefaultMaxSweepPoints);

}  // namespace protocols
