#include "protocols/run/run_scenario.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "protocols/run/scenario_run.h"

#include "protocols/io/frame_reader.h"

namespace protocols {

double nextTimeAfter(double next, double interval, double now) {
  // Stepping by `interval` keeps the times on the schedule's grid (start + k interval) as before;
  // far behind (an interval much shorter than the step) or stalled (next + interval == next in
  // floating point) the next time is taken from now instead, so this always ends.
  constexpr int kMostIncrements = 64;
  for (int k = 0; k < kMostIncrements && next <= now; ++k) {
    const double advanced = next + interval;
    if (!(advanced > next)) break;
    next = advanced;
  }
  if (next > now) return next;
  const double fromNow = now + interval;
  return fromNow > now ? fromNow : std::nextafter(now, std::numeric_limits<double>::infinity());
}

void applyRecordedPostureEnds(const FrameReader& reader, Scenario& s, double upTo) {
  const std::vector<std::string> names = reader.seriesNames();
  if (std::find(names.begin(), names.end(), "postures") == names.end()) return;
  const SeriesData ends = reader.readSeries("postures");
  const std::vector<double> times = ends.column("time"), index = ends.column("posture"),
                            steady = ends.column("steady"), start = ends.column("start");
  for (std::size_t r = 0; r < ends.rows; ++r) {
    const auto k = static_cast<std::size_t>(index[r]);
    if (times[r] > upTo || k >= s.schedule.size()) continue;
    s.schedule[k].endedSteady = steady[r] > 0;
    if (steady[r] > 0) s.schedule[k].duration = times[r] - start[r];
  }
}

RunSummary runScenario(const Protocol& protocol, Scenario& s, const RunOptions& options) {
  ScenarioRun run(protocol, s, options);
  run.open();
  for (std::size_t k = run.firstPosture(); k < s.schedule.size(); ++k)
    if (!run.runPosture(k)) return run.stop();
  return run.finish();
}

}  // namespace protocols
