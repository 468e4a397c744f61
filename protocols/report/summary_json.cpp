// summary.json (docs/reading-the-report.md): built as a JSON document by nlohmann-json, so every
// string is escaped and a number that is not finite (a run stopped before its first frame has no
// averages) is written as null instead of an invalid `nan`.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include <nlohmann/json.hpp>

#include "protocols/report/write_report.h"

namespace protocols {
namespace {

using Json = nlohmann::ordered_json;

// `value` rounded to `digits` significant digits (the precision of coverage.csv), null when not
// finite.
Json number(double value, int digits = 6) {
  if (!std::isfinite(value)) return nullptr;
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return std::strtod(buffer, nullptr);
}

double at(const std::vector<double>& values, std::size_t k) {
  return k < values.size() ? values[k] : 0.0;
}

Json regionsOf(const ReportInput& in) {
  Json regions = Json::array();
  for (std::size_t r = 0; r < kReportedRegions.size(); ++r) {
    const AreaCoverage last = in.frames.empty() ? AreaCoverage{} : in.frames.back().regions[r];
    regions.push_back({{"name", kReportedRegions[r].name},
                       {"area_m2", number(last.area)},
                       {"mean_fraction", number(in.summary.regions[r])},
                       {"final_fraction", number(last.fraction)}});
  }
  return regions;
}

Json breaksOf(const ReportInput& in) {
  Json breaks = Json::array();
  for (std::size_t b = 0; b < in.breaks.size(); ++b) {
    const bool coveredAtEnd = !in.frames.empty() && b < in.frames.back().breaks.size() &&
                              in.frames.back().breaks[b].covered;
    breaks.push_back({{"name", in.breaks[b].name},
                      {"where", in.breaks[b].where},
                      {"mean_fraction", number(at(in.summary.breakFraction, b))},
                      {"time_covered", number(at(in.summary.breakTimeCovered, b))},
                      {"covered_at_end", coveredAtEnd}});
  }
  return breaks;
}

Json stagesOf(const ReportInput& in) {
  Json stages = Json::array();
  for (const auto& stage : in.stages)
    stages.push_back(
        {{"name", stage.name}, {"active", stage.active}, {"seconds", number(stage.seconds)}});
  return stages;
}

Json accuracyOf(const ReportInput& in) {
  Json accuracy = Json::array();
  for (const auto& a : in.accuracy)
    accuracy.push_back({{"name", a.name}, {"value", a.value}, {"note", a.note}});
  return accuracy;
}

Json pressureSolveOf(const ReportPressureSolve& ps) {
  return {{"tolerance", number(ps.tolerance)},
          {"mean_density_error", number(ps.meanDensityError)},
          {"max_step_density_error", number(ps.maxStepDensityError)},
          {"mean_iterations", number(ps.meanIterations)},
          {"steps_at_iteration_cap_fraction", number(ps.capFraction)},
          {"iteration_cap", ps.iterationCap},
          {"steps", ps.steps}};
}

Json optionalNumber(const std::optional<double>& value) {
  return value ? number(*value) : Json(nullptr);
}

// The schedule as run; "ended_steady" is null for postures that were not "until steady".
Json posturesOf(const ReportInput& in) {
  Json postures = Json::array();
  for (const ReportPosture& p : in.postures) {
    Json posture = {{"name", p.label},
                    {"start_s", number(p.start, 9)},
                    {"end_s", number(p.end, 9)},
                    {"ended_steady", p.endedSteady ? Json(*p.endedSteady) : Json(nullptr)}};
    if (p.endedSteady && !*p.endedSteady) {
      posture["retina_coverage_at_end"] = optionalNumber(p.retinaAtEnd);
      posture["equilibrium_retina_coverage"] = optionalNumber(p.equilibriumRetina);
    }
    if (p.startsFromEquilibriumOf)
      posture["starts_from_equilibrium_of"] = *p.startsFromEquilibriumOf;
    postures.push_back(posture);
  }
  return postures;
}

Json equilibriaOf(const ReportInput& in) {
  Json equilibria = Json::array();
  for (const ReportEquilibrium& e : in.equilibria) {
    Json regions = Json::array();
    for (std::size_t r = 0; r < kReportedRegions.size(); ++r)
      regions.push_back({{"name", kReportedRegions[r].name},
                         {"fraction", number(e.coverage.regions[r].fraction)}});
    Json breaks = Json::array();
    for (std::size_t b = 0; b < e.coverage.breaks.size() && b < in.breaks.size(); ++b)
      breaks.push_back({{"name", in.breaks[b].name},
                        {"fraction", number(e.coverage.breaks[b].area.fraction)},
                        {"covered", e.coverage.breaks[b].covered}});
    Json oilEdge = Json::array();
    for (const ClockHourOilEdge& edge : e.oilEdge) {
      Json stretches = Json::array();
      for (const OilStretch& stretch : edge.oil)
        stretches.push_back({number(stretch.from * 1e3, 4), number(stretch.to * 1e3, 4)});
      oilEdge.push_back({{"clock_hour", edge.clockHour},
                         {"meridian_mm", number(edge.meridianLength * 1e3, 4)},
                         {"oil_mm_from_ora", stretches}});
    }
    equilibria.push_back({{"posture", e.label},
                          {"regions", regions},
                          {"breaks", breaks},
                          {"oil_edge_by_clock_hour", oilEdge}});
  }
  return equilibria;
}

}  // namespace

std::string renderSummaryJson(const ReportInput& in) {
  Json summary = {{"title", in.title},          {"duration_s", number(in.summary.duration, 9)},
                  {"complete", !in.incomplete}, {"postures", posturesOf(in)},
                  {"frames", in.frames.size()}, {"regions", regionsOf(in)},
                  {"breaks", breaksOf(in)},     {"tissue", in.tissue},
                  {"stages", stagesOf(in)},     {"accuracy", accuracyOf(in)}};
  if (in.pressureSolve) summary["pressure_solve"] = pressureSolveOf(*in.pressureSolve);
  if (!in.equilibria.empty()) summary["equilibria"] = equilibriaOf(in);
  // Invalid UTF-8 in a title or break name (protocol text is not checked for it) is replaced
  // instead of throwing.
  return summary.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace protocols
