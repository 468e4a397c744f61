// What a run carries from step to step besides the particles: the posture it is in, when the
// next frame and steady-state sample are due, the steady-state samples of the current window,
// the pressure-solve totals and the stage times. A checkpoint stores it and a resumed run restores
// it (save/restore own the checkpoint's counter names, so the file format stays one place).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "protocols/io/checkpoint.h"
#include "protocols/run/pressure_solve_totals.h"
#include "protocols/run/steady_state.h"

namespace protocols {

struct RunState {
  std::size_t posture = 0;                     // the posture the run continues with
  double nextFrame = 0.0;                      // [s]
  double postureStart = 0.0;                   // [s] simulated time the current posture began
  double nextSample = 0.0;                     // [s] next steady-state sample (until steady)
  std::vector<SteadySample> samples;           // of the current posture, trimmed to one window
  PressureSolveTotals solve;                   // since the run's start
  std::map<std::string, double> stageSeconds;  // [s] per pipeline stage name

  // Into the checkpoint's counters.
  void save(CheckpointState& checkpoint) const;
  // From them; throws std::out_of_range for a checkpoint without the run's counters.
  static RunState restore(const CheckpointState& checkpoint);
};

}  // namespace protocols
