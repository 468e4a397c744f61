// Wall-clock time per named stage, accumulated over a run (docs/developer-guide.md principle 1:
// every stage is timed, and the run records it).
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace sim {

class StageTimers {
 public:
  struct Entry {
    std::string name;
    double seconds = 0.0;
    long calls = 0;
  };

  // Returns a slot index; call once per stage at pipeline assembly (no allocation per step).
  int slot(const std::string& name) {
    for (std::size_t k = 0; k < entries_.size(); ++k)
      if (entries_[k].name == name) return static_cast<int>(k);
    entries_.push_back({name, 0.0, 0});
    return static_cast<int>(entries_.size()) - 1;
  }
  void add(int slotIndex, double seconds) {
    auto& e = entries_[static_cast<std::size_t>(slotIndex)];
    e.seconds += seconds;
    ++e.calls;
  }
  const std::vector<Entry>& entries() const { return entries_; }
  double total() const {
    double t = 0;
    for (const auto& e : entries_) t += e.seconds;
    return t;
  }
  void reset() {
    for (auto& e : entries_) e.seconds = 0, e.calls = 0;
  }

 private:
  std::vector<Entry> entries_;
};

// Times a scope into a StageTimers slot.
class ScopedStageTimer {
 public:
  ScopedStageTimer(StageTimers& timers, int slotIndex)
      : timers_(timers), slot_(slotIndex), start_(std::chrono::steady_clock::now()) {}
  ~ScopedStageTimer() {
    timers_.add(slot_,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  }
  ScopedStageTimer(const ScopedStageTimer&) = delete;
  ScopedStageTimer& operator=(const ScopedStageTimer&) = delete;

 private:
  StageTimers& timers_;
  int slot_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace sim
