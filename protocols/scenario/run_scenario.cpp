#include "protocols/scenario/run_scenario.h"

#include <chrono>
#include <fstream>
#include <sstream>

#include "protocols/coverage/schedule_coverage.h"
#include "protocols/io/frame_writer.h"
#include "protocols/report/write_report.h"
#include "protocols/scenario/scenario_report_input.h"

namespace protocols {
namespace {

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Column names of the coverage series: the reported regions, then per break fraction, covered.
std::vector<std::string> seriesColumns(const RetinaMap& map) {
  std::vector<std::string> columns;
  for (const auto& r : kReportedRegions) columns.emplace_back(r.name);
  for (const auto& name : map.breakNames) {
    columns.push_back("break " + name + " fraction");
    columns.push_back("break " + name + " covered");
  }
  return columns;
}

}  // namespace

RunSummary runScenario(const Protocol& protocol, Scenario& s, const RunOptions& options) {
  const auto wallStart = std::chrono::steady_clock::now();
  sim::World& world = *s.world;
  sim::Pipeline pipeline = sim::assemblePipeline(world, s.pipelineOptions);
  pipeline.attach(world);

  RunMetadata metadata;
  metadata.protocolText = readText(protocol.file);
  metadata.strings["protocol_file"] = protocol.file.string();
  metadata.strings["accuracy"] = s.accuracy.preset;
  metadata.strings["solver"] = s.pipelineOptions.solver;
  metadata.numbers["particle_spacing [m]"] = s.accuracy.particleSpacing;
  FrameWriter writer(options.outputFolder / "frames.h5", metadata);
  writer.writeStatic("wall", world.walls.fields);

  // Coverage kernel: support gap + sqrt(3) d (wall_oil_fraction.h), the gap the scenario used.
  const double d = s.accuracy.particleSpacing;
  const sim::Kernel coverageKernel(sim::KernelKind::kCubicSpline, coverageSupportRadius(d, 1.2 * d));
  const std::vector<std::string> columns = seriesColumns(s.retina);
  std::vector<FrameCoverage> frames;
  WallOilFractions lastFractions;
  std::vector<sim::Vec3> fluidPositions;
  std::vector<double> fluidVolumes;

  auto record = [&]() {
    if (!frames.empty() && !(world.time > frames.back().time)) return;
    writer.writeFrame(world.time, world.stepCount, {{"fluid", &world.particles.fields}});
    const std::size_t n = world.particles.size();
    fluidPositions.assign(world.particles.x.begin(), world.particles.x.end());
    fluidVolumes.resize(n);
    for (std::size_t i = 0; i < n; ++i) fluidVolumes[i] = world.restVolumeOf(static_cast<sim::Index>(i));
    const std::vector<std::uint8_t> flags = s.tamponadeFlags();
    lastFractions = computeWallOilFractions(world.walls.x, {&fluidPositions, &flags, &fluidVolumes},
                                            coverageKernel);
    frames.push_back(measureFrameCoverage(s.retina, lastFractions, world.time));
    std::vector<double> row;
    for (const auto& r : frames.back().regions) row.push_back(r.fraction);
    for (const auto& b : frames.back().breaks) {
      row.push_back(b.area.fraction);
      row.push_back(b.covered ? 1.0 : 0.0);
    }
    writer.appendSeries("coverage", world.time, row, columns);
  };

  const double interval = protocol.outputs.frameInterval.value;  // [s]
  const double endTime = s.totalDuration();
  double nextFrame = world.time + interval;
  record();
  double postureEnd = 0.0;
  for (const ScheduledPosture& posture : s.schedule) {
    world.gravity = posture.gravity;
    postureEnd += posture.duration;
    while (world.time < postureEnd) {
      pipeline.step(world);
      if (world.time >= nextFrame) {
        record();
        while (nextFrame <= world.time) nextFrame += interval;
      }
      if (options.progress) options.progress({world.time, endTime, world.stepCount, posture.label});
    }
  }
  record();  // the end state (skipped when the last step already wrote it)
  writer.close();

  // Report.
  ReportInput in = makeReportInput(protocol, s);
  in.frames = frames;
  in.summary = summarizeSchedule(frames);
  in.mapTime = frames.back().time;
  in.wallPositions.assign(world.walls.x.begin(), world.walls.x.end());
  in.wallOilFraction = lastFractions.oilFraction;
  in.wallWetting = lastFractions.wetting;
  in.wallRegions = s.retina.regions;
  for (const auto& e : pipeline.timers().entries()) {
    ReportStage st{e.name, true, "", e.seconds, e.calls};
    for (const auto& dcs : pipeline.decisions())
      if (dcs.name == e.name) st.reason = dcs.reason;
    in.stages.push_back(st);
  }
  for (const auto& dcs : pipeline.decisions())
    if (!dcs.active) in.stages.push_back({dcs.name, false, dcs.reason, 0.0, 0});
  if (protocol.outputs.report.value) writeReport(in, options.outputFolder);

  RunSummary summary;
  summary.frames = frames.size();
  summary.steps = world.stepCount;
  summary.simulatedTime = world.time;
  summary.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  summary.retinaCoverage = in.summary.regions[0];
  return summary;
}

}  // namespace protocols
