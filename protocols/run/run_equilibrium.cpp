#include "protocols/run/run_equilibrium.h"

#include <algorithm>
#include <chrono>

#include "meshing/mesh_writer.h"
#include "protocols/coverage/oil_edge_by_clock_hour.h"
#include "protocols/equilibrium/posture_equilibrium.h"
#include "protocols/report/report_format.h"
#include "protocols/report/write_report.h"
#include "protocols/run/rebuild_report.h"

namespace protocols {
namespace {

// Each posture's frames stand just inside its nominal second, so that the trapezoidal means of
// summarizeSchedule weight the postures alike (to 0.1 %) and show a step between them.
constexpr double kFrameInset = 1e-3;  // [s]

}  // namespace

RunSummary runEquilibriumSchedule(const Protocol& protocol, Scenario& s, const RunOptions& options,
                                  const std::function<void(const EquilibriumProgress&)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  const double voxel = equilibriumVoxelSpacing(s.accuracy.preset);
  const CavityVoxels cavity = voxelizeCavity(s, voxel);
  const double fill = protocol.tamponade.fill.value;

  std::vector<FrameCoverage> frames;
  std::vector<ReportEquilibrium> equilibria;
  WallOilFractions last;
  std::vector<std::string> solves;
  double t = 0.0;
  for (std::size_t k = 0; k < s.schedule.size(); ++k) {
    ScheduledPosture& posture = s.schedule[k];
    const PostureEquilibrium e = solvePostureEquilibrium(s, cavity, fill, posture.gravity);
    frames.push_back(measureFrameCoverage(s.retina, e.wall, t + kFrameInset));
    frames.push_back(measureFrameCoverage(s.retina, e.wall, t + posture.duration - kFrameInset));
    t += posture.duration;
    last = e.wall;
    equilibria.push_back({posture.label, frames.back(), e.wall.oilFraction, e.wall.wetting, {}});
    if (s.eye)
      equilibria.back().oilEdge = oilEdgeByClockHour(*s.eye, s.retinaSamples.restPositions,
                                                     e.wall.oilFraction, s.retina.regions);
    if (!e.interface.empty())
      meshing::writeMesh(
          e.interface,
          (options.outputFolder / ("interface_" + std::to_string(k + 1) + ".ply")).string());
    solves.push_back(posture.label + ": " + std::to_string(e.solution.iterations) + " iterations" +
                     (e.solution.converged ? "" : " (not settled)") + ", " +
                     formatNumber(e.seconds, 3) + " s");
    if (progress)
      progress({k, s.schedule.size(), posture.label, e.seconds, frames.back().retina().fraction,
                e.solution.iterations, e.solution.converged});
  }

  // The scenario's notes are about the particle simulation (wall model, fill, spacing); none
  // applies to the equilibrium.
  s.notes.clear();
  RunResults results{frames, last, {}, {}, {}, 0.0, {}};
  ReportInput in = makeRunReportInput(protocol, s, results);
  in.equilibria = std::move(equilibria);
  in.accuracy = {
      {"method", "static equilibrium (threshold dynamics with wetting)",
       "docs/methods/equilibrium.md; each posture's interface in interface_<k>.ply"},
      {"voxel", formatNumber(voxel * 1e3, 3) + " mm",
       "in a 12 mm sphere at Bond ~1 the covered fraction is within 4.5 points of the "
       "Young-Laplace equilibrium at 0.5 mm (largest at 40 deg, 0.8 points at 18 deg and 90 % "
       "fill)"},
      {"schedule means", "each posture weighted alike",
       "transients between postures are neglected (one nominal second per posture)"},
      {"solves",
       [&] {
         std::string text;
         for (const auto& line : solves) text += (text.empty() ? "" : "; ") + line;
         return text;
       }(),
       "stages of sqrt(t) = 6, 3, 1.5 voxels, each until no voxel changes"},
  };
  if (protocol.outputs.report.value) writeReport(in, options.outputFolder);

  RunSummary summary;
  summary.frames = frames.size();
  summary.simulatedTime = 0.0;
  summary.retinaCoverage = in.summary.regions[0];
  summary.coverage = in.summary;
  summary.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace protocols
