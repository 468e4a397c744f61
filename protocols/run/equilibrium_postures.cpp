#include "protocols/run/equilibrium_postures.h"

#include <fmt/format.h>

#include "meshing/mesh_writer.h"
#include "protocols/coverage/oil_edge_by_clock_hour.h"
#include "protocols/equilibrium/posture_equilibrium.h"
#include "protocols/io/interface_series.h"
#include "protocols/report/report_format.h"

namespace protocols {
namespace {

// Each posture's frames stand just inside its nominal second, so that the trapezoidal means of
// summarizeSchedule weight the postures alike (to 0.1 %) and show a step between them.
constexpr double kFrameInset = 1e-3;  // [s]

}  // namespace

SolvedEquilibria solveEquilibriumPostures(
    const Protocol& protocol, const Scenario& s, std::size_t count,
    const std::filesystem::path& interfaceFolder,
    const std::function<void(const EquilibriumProgress&)>& progress) {
  SolvedEquilibria out;
  out.voxel = equilibriumVoxelSpacing(s.accuracy.preset);
  const CavityVoxels cavity = voxelizeCavity(s, out.voxel);
  const double fill = protocol.tamponade.fill.value;
  double t = 0.0;
  std::vector<PostureInterface> interfaces;
  for (std::size_t k = 0; k < count; ++k) {
    const ScheduledPosture& posture = s.schedule[k];
    const double start = t;  // [s] the posture's start on the schedule's clock
    const PostureEquilibrium e = solvePostureEquilibrium(s, cavity, fill, posture.gravity);
    out.frames.push_back(measureFrameCoverage(s.retina, e.wall, t + kFrameInset));
    out.frames.push_back(
        measureFrameCoverage(s.retina, e.wall, t + posture.duration - kFrameInset));
    t += posture.duration;
    out.last = e.wall;
    out.postures.push_back(
        {posture.label, out.frames.back(), e.wall.oilFraction, e.wall.wetting, {}});
    if (s.eye)
      out.postures.back().oilEdge = oilEdgeByClockHour(*s.eye, s.retinaSamples.restPositions,
                                                       e.wall.oilFraction, s.retina.regions);
    if (!interfaceFolder.empty() && !e.interface.empty())
      meshing::writeMesh(e.interface,
                         (interfaceFolder / fmt::format("interface_{}.ply", k + 1)).string());
    interfaces.push_back({posture.label, start, e.interface.vertices, e.interface.faces});
    out.solves.push_back(
        fmt::format("{}: {} iterations{}, {} s", posture.label, e.solution.iterations,
                    e.solution.converged ? "" : " (not settled)", formatNumber(e.seconds, 3)));
    if (progress)
      progress({k, s.schedule.size(), posture.label, e.seconds, out.frames.back().retina().fraction,
                e.solution.iterations, e.solution.converged});
  }
  if (!interfaceFolder.empty()) writeInterfaceSeries(interfaceFolder, interfaces);
  out.end = t;
  return out;
}

std::vector<ReportSetting> equilibriumAccuracyRows(const SolvedEquilibria& e, bool wholeSchedule) {
  std::string solves;
  for (const auto& line : e.solves) solves += (solves.empty() ? "" : "; ") + line;
  return {
      {"method", "static equilibrium (threshold dynamics with wetting)",
       "docs/methods/equilibrium.md; each posture's interface in interfaces.xmf (ParaView) and "
       "interface_<k>.ply"},
      {"voxel", formatNumber(e.voxel * 1e3, 3) + " mm",
       "in a 12 mm sphere at Bond ~1 the covered fraction is within 1 point of the "
       "Young-Laplace equilibrium at 0.3 mm at 18-30 deg and within 0.5 at 40-140 deg (the wall "
       "kernel calibrated at 18-75 deg; 160 deg: 1.1, 10 deg: 2.9), at fills 0.5-0.95; "
       "docs/methods/equilibrium.md, Accuracy"},
      wholeSchedule
          ? ReportSetting{"schedule means", "each posture weighted alike",
                          "transients between postures are neglected (one nominal second per "
                          "posture)"}
          : ReportSetting{"schedule means", "each posture at equilibrium weighted as one second",
                          "one nominal second per posture at equilibrium, then the simulated "
                          "postures for their simulated time"},
      {"solves", solves,
       "stages of sqrt(t) = 6, 3, 1.5 voxels, each until no voxel changes; from a wetting angle "
       "of 40 deg the last one in fractions of a voxel, until none changes by more than 0.001"},
  };
}

void addLeadingEquilibria(const SolvedEquilibria& e, ReportInput& report) {
  report.equilibria = e.postures;
  for (ReportSetting& row : equilibriumAccuracyRows(e, false)) {
    if (row.name != "schedule means") row.name = "equilibrium " + row.name;
    report.accuracy.push_back(std::move(row));
  }
}

}  // namespace protocols
