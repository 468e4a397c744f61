// Everything a coverage report shows, as plain data: no engine or anatomy objects, so the report
// can be rebuilt from a run's files (`tamponade report DIR`) as well as at the end of a run.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "protocols/coverage/frame_coverage.h"
#include "protocols/coverage/oil_edge_by_clock_hour.h"
#include "protocols/coverage/schedule_coverage.h"

namespace protocols {

struct ReportPosture {
  std::string label;   // e.g. "face-down"
  double start = 0.0;  // [s]
  double end = 0.0;    // [s]
  // An "until steady" posture: whether it settled before its maximum (absent for a fixed
  // duration, an equilibrium posture, or a run stopped before the posture ended).
  std::optional<bool> endedSteady = std::nullopt;
  // A posture that ended unsteady at its maximum: the retina's oil-covered share at its end, and
  // at the posture's static equilibrium when the equilibrium solver can give one [1].
  std::optional<double> retinaAtEnd = std::nullopt;
  std::optional<double> equilibriumRetina = std::nullopt;
  // A simulated posture right after a posture at its equilibrium (a mixed schedule): that
  // posture's label; the simulation starts from its equilibrium.
  std::optional<std::string> startsFromEquilibriumOf = std::nullopt;
};

struct ReportStage {
  std::string name;
  bool active = false;
  std::string reason;    // why it is (not) in the pipeline
  double seconds = 0.0;  // [s] wall-clock time spent in it (0 when not run)
  long calls = 0;
};

// What the implicit pressure solve achieved over the run (absent for explicit solvers and for
// runs that did not record it).
struct ReportPressureSolve {
  double tolerance = 0.0;            // [1] accuracy.solver_tolerance asked for
  double meanDensityError = 0.0;     // [1] the steps' final mean density errors, dt-weighted
  double maxStepDensityError = 0.0;  // [1]
  double meanIterations = 0.0;       // density-solve iterations per step
  double capFraction = 0.0;          // [1] steps that stopped at the iteration cap
  int iterationCap = 0;
  long steps = 0;
};

struct ReportSetting {
  std::string name;   // e.g. "particle spacing"
  std::string value;  // with its unit, e.g. "0.8 mm"
  std::string note;   // estimated error where known, or where the value comes from
};

// A line drawn on the fundus map (ora serrata, equator, macula, ...), as points on the wall.
struct ReportOutline {
  std::string name;
  std::vector<sim::Vec3> points;  // [m] eye frame, in drawing order
  bool closed = true;
};

struct ReportBreak {
  std::string name;
  std::string where;  // clinical position in words, e.g. "12 o'clock, 8 mm from the limbus"
  std::vector<sim::Vec3> outline;  // [m] eye frame, closed ring on the wall
};

// One posture at its static equilibrium (duration = "equilibrium"): its coverage and wall state.
struct ReportEquilibrium {
  std::string label;
  FrameCoverage coverage;
  std::vector<double> wallOilFraction;   // [1] #W
  std::vector<WallWetting> wallWetting;  // #W
  // Per clock hour 12, 1, ..., 11: what the oil covers along the meridian; empty for an imported
  // mesh eye (no ora serrata to measure from).
  std::vector<ClockHourOilEdge> oilEdge;
};

struct ReportInput {
  std::string title;
  std::string eyeSide = "OD";           // "OD" or "OS": which side of the map is nasal
  std::vector<std::string> scenario;    // the scenario in words, one paragraph each
  std::vector<ReportPosture> postures;  // the schedule as run
  std::vector<FrameCoverage> frames;    // in increasing time
  ScheduleCoverage summary;             // summarizeSchedule(frames)
  std::vector<ReportBreak> breaks;      // same order as the frames' breaks
  // The fundus map shows the wall state of one frame (normally the last).
  double mapTime = 0.0;                         // [s]
  std::vector<sim::Vec3> wallPositions;         // [m] eye frame, #W
  std::vector<double> wallOilFraction;          // [1] #W
  std::vector<WallWetting> wallWetting;         // #W
  std::vector<anatomy::RegionSet> wallRegions;  // #W; particles outside the retina are not drawn
  std::vector<ReportOutline> outlines;
  std::vector<ReportStage> stages;
  std::vector<ReportSetting> accuracy;
  std::optional<ReportPressureSolve> pressureSolve;
  // Elastic tissue, one sentence each: the decision, maximum displacements, the cavity
  // volume change; one line ("tissue rigid (estimate ...)") when no tissue is elastic.
  std::vector<std::string> tissue;
  // Postures at their static equilibrium, in schedule order; empty for a simulated run. The
  // report gives each one's coverage and fundus map; when every posture is one
  // (isEquilibriumReport) instead of a time course, else (a mixed schedule, whose equilibria
  // come first) beside the simulated postures' time course.
  std::vector<ReportEquilibrium> equilibria;
  // A run read back after it was stopped (Ctrl-C, a kill) before the end of its schedule: the
  // report's headline says so, and every mean is over the part simulated only.
  bool incomplete = false;
  double scheduledDuration = 0.0;  // [s] the schedule's full length (set when incomplete)
};

// Whether every posture of the report is at its static equilibrium: nothing was simulated.
inline bool isEquilibriumReport(const ReportInput& in) {
  return !in.equilibria.empty() && in.equilibria.size() >= in.postures.size();
}

}  // namespace protocols
