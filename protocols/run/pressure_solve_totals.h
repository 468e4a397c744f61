// What the pressure solve achieved over a run: iterations per step, the mean density error it
// stopped at (weighted by each step's dt), and how many steps stopped at the iteration cap
// instead of at accuracy.solver_tolerance. Written as the "pressure_solve" series of frames.h5
// (cumulative, one row per frame) so that `tamponade report DIR` and a resumed run see the same
// totals as the run that wrote them.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "sim/world/step_context.h"

namespace protocols {

struct PressureSolveTotals {
  long steps = 0;
  long densityIterations = 0;
  long divergenceIterations = 0;
  long stepsAtIterationCap = 0;
  int iterationCap = 0;              // of the last step (0: explicit solver)
  double time = 0.0;                 // [s] simulated time of the steps counted
  double densityErrorTime = 0.0;     // [s] sum of dt x the step's final mean density error
  double maxStepDensityError = 0.0;  // [1] largest of the steps' final mean density errors

  void add(const sim::SolverStats& stats, double dt);
  bool implicitSolve() const { return iterationCap > 0; }
  double meanIterations() const;
  double meanDivergenceIterations() const;
  double meanDensityError() const;  // [1] dt-weighted
  double capFraction() const;       // [1] of the steps

  // The series row (column names and values in the same order) and its inverse.
  static std::vector<std::string> columns();
  std::vector<double> row() const;
  static PressureSolveTotals fromRow(const std::vector<double>& values);
  // Checkpoint counters ("solve:<column>").
  void save(std::map<std::string, double>& counters) const;
  static PressureSolveTotals restore(const std::map<std::string, double>& counters);
};

}  // namespace protocols
