// The postures of a schedule that ask for their static equilibrium (duration = "equilibrium"),
// solved one after the other (protocols/equilibrium/posture_equilibrium.h) into what a report
// carries: two coverage frames per posture inside its nominal second (kEquilibriumHold), each
// posture's coverage, wall state and oil edge, and its interface as interface_<k>.ply. An
// equilibrium schedule is all of this (run_equilibrium.h); a mixed schedule begins with it and
// simulates the postures after it (run_scenario.h).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "protocols/coverage/frame_coverage.h"
#include "protocols/coverage/wall_oil_fraction.h"
#include "protocols/format/protocol.h"
#include "protocols/report/report_input.h"
#include "protocols/scenario/scenario.h"

namespace protocols {

struct EquilibriumProgress {
  std::size_t posture = 0;  // 0-based
  std::size_t postures = 0;
  std::string label;
  double seconds = 0.0;         // [s] the posture's solve
  double retinaCoverage = 0.0;  // [1]
  int iterations = 0;
  bool converged = false;
};

struct SolvedEquilibria {
  double voxel = 0.0;                       // [m]
  std::vector<FrameCoverage> frames;        // two per posture, in schedule time
  std::vector<ReportEquilibrium> postures;  // in schedule order
  WallOilFractions last;                    // the last posture's wall state
  std::vector<std::string> solves;          // per posture: iterations, settled, time
  double end = 0.0;  // [s] schedule time at the end of the last posture solved
};

// The first `count` postures of the schedule (each must be an equilibrium posture), at the
// protocol's fill. Writes interface_<k>.ply and the series interfaces.h5 + interfaces.xmf
// (protocols/io/interface_series.h) into `interfaceFolder` unless it is empty; calls
// `progress` (may be empty) after each posture. Throws SimError when a posture has no equilibrium
// the method can compute (e.g. no interfacial tension).
SolvedEquilibria solveEquilibriumPostures(
    const Protocol& protocol, const Scenario& scenario, std::size_t count,
    const std::filesystem::path& interfaceFolder,
    const std::function<void(const EquilibriumProgress&)>& progress);

// The report's accuracy rows of the equilibria: method, voxel, how the schedule's means weight
// them, the solves. `wholeSchedule`: every posture of the schedule is among them.
std::vector<ReportSetting> equilibriumAccuracyRows(const SolvedEquilibria& equilibria,
                                                   bool wholeSchedule);

// A mixed schedule's report (whose frames begin with the equilibria's): each equilibrium's
// coverage, wall state and oil edge, and their accuracy rows after the simulation's.
void addLeadingEquilibria(const SolvedEquilibria& equilibria, ReportInput& report);

}  // namespace protocols
