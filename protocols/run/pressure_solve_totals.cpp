#include "protocols/run/pressure_solve_totals.h"

#include <algorithm>

namespace protocols {

void PressureSolveTotals::add(const sim::SolverStats& stats, double dt) {
  ++steps;
  densityIterations += stats.densityIterations;
  divergenceIterations += stats.divergenceIterations;
  iterationCap = stats.densityIterationLimit;
  if (iterationCap > 0 && stats.densityIterations >= iterationCap) ++stepsAtIterationCap;
  time += dt;
  densityErrorTime += dt * stats.averageCompression;
  maxStepDensityError =
      std::max(maxStepDensityError, static_cast<double>(stats.averageCompression));
}

double PressureSolveTotals::meanIterations() const {
  return steps > 0 ? static_cast<double>(densityIterations) / static_cast<double>(steps) : 0.0;
}

double PressureSolveTotals::meanDivergenceIterations() const {
  return steps > 0 ? static_cast<double>(divergenceIterations) / static_cast<double>(steps) : 0.0;
}

double PressureSolveTotals::meanDensityError() const {
  return time > 0.0 ? densityErrorTime / time : 0.0;
}

double PressureSolveTotals::capFraction() const {
  return steps > 0 ? static_cast<double>(stepsAtIterationCap) / static_cast<double>(steps) : 0.0;
}

std::vector<std::string> PressureSolveTotals::columns() {
  return {"steps",
          "density_iterations",
          "divergence_iterations",
          "steps_at_iteration_cap",
          "iteration_cap",
          "time",
          "density_error_time",
          "max_step_density_error"};
}

std::vector<double> PressureSolveTotals::row() const {
  return {static_cast<double>(steps),
          static_cast<double>(densityIterations),
          static_cast<double>(divergenceIterations),
          static_cast<double>(stepsAtIterationCap),
          static_cast<double>(iterationCap),
          time,
          densityErrorTime,
          maxStepDensityError};
}

PressureSolveTotals PressureSolveTotals::fromRow(const std::vector<double>& v) {
  PressureSolveTotals t;
  if (v.size() < columns().size()) return t;
  t.steps = static_cast<long>(v[0]);
  t.densityIterations = static_cast<long>(v[1]);
  t.divergenceIterations = static_cast<long>(v[2]);
  t.stepsAtIterationCap = static_cast<long>(v[3]);
  t.iterationCap = static_cast<int>(v[4]);
  t.time = v[5];
  t.densityErrorTime = v[6];
  t.maxStepDensityError = v[7];
  return t;
}

void PressureSolveTotals::save(std::map<std::string, double>& counters) const {
  const std::vector<std::string> names = columns();
  const std::vector<double> values = row();
  for (std::size_t k = 0; k < names.size(); ++k) counters["solve:" + names[k]] = values[k];
}

PressureSolveTotals PressureSolveTotals::restore(const std::map<std::string, double>& counters) {
  std::vector<double> values;
  for (const std::string& name : columns()) {
    const auto it = counters.find("solve:" + name);
    if (it == counters.end()) return {};  // a checkpoint from before the totals existed
    values.push_back(it->second);
  }
  return fromRow(values);
}

}  // namespace protocols
