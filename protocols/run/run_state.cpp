#include "protocols/run/run_state.h"

namespace protocols {

namespace {

// The checkpoint's counter names (format 2, protocols/io/frame_file_layout.h).
std::string sampleKey(std::size_t k) { return "steady:" + std::to_string(k) + ":"; }
constexpr const char* kStagePrefix = "stage:";

}  // namespace

void RunState::save(CheckpointState& c) const {
  c.integerCounters["posture"] = static_cast<std::int64_t>(posture);
  c.realCounters["next_frame"] = nextFrame;
  c.realCounters["posture_start"] = postureStart;
  c.realCounters["next_sample"] = nextSample;
  c.integerCounters["steady_samples"] = static_cast<std::int64_t>(samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const std::string key = sampleKey(k);
    c.realCounters[key + "time"] = samples[k].time;
    c.realCounters[key + "energy"] = samples[k].kineticEnergyPerMass;
    c.integerCounters[key + "coverages"] = static_cast<std::int64_t>(samples[k].coverage.size());
    for (std::size_t v = 0; v < samples[k].coverage.size(); ++v)
      c.realCounters[key + "coverage:" + std::to_string(v)] = samples[k].coverage[v];
  }
  for (const auto& [name, seconds] : stageSeconds) c.realCounters[kStagePrefix + name] = seconds;
  solve.save(c.realCounters);
}

RunState RunState::restore(const CheckpointState& c) {
  RunState s;
  s.posture = static_cast<std::size_t>(c.integerCounters.at("posture"));
  s.nextFrame = c.realCounters.at("next_frame");
  s.postureStart = c.realCounters.at("posture_start");
  s.nextSample = c.realCounters.at("next_sample");
  const std::int64_t count = c.integerCounters.at("steady_samples");
  for (std::int64_t k = 0; k < count; ++k) {
    const std::string key = sampleKey(static_cast<std::size_t>(k));
    SteadySample restored{c.realCounters.at(key + "time"), c.realCounters.at(key + "energy"), {}};
    const std::int64_t values = c.integerCounters.at(key + "coverages");
    for (std::int64_t v = 0; v < values; ++v)
      restored.coverage.push_back(c.realCounters.at(key + "coverage:" + std::to_string(v)));
    s.samples.push_back(std::move(restored));
  }
  const std::string prefix = kStagePrefix;
  for (const auto& [name, value] : c.realCounters)
    if (name.rfind(prefix, 0) == 0) s.stageSeconds[name.substr(prefix.size())] = value;
  s.solve = PressureSolveTotals::restore(c.realCounters);
  return s;
}

}  // namespace protocols
