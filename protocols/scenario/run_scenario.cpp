#include "protocols/scenario/run_scenario.h"

#include <chrono>
#include <fstream>
#include <sstream>

#include "protocols/io/frame_writer.h"
#include "protocols/report/write_report.h"
#include "protocols/scenario/rebuild_report.h"

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
  metadata.strings["accuracy_override"] = options.accuracyOverride;
  metadata.strings["solver"] = s.pipelineOptions.solver;
  metadata.numbers["particle_spacing [m]"] = s.accuracy.particleSpacing;
  FrameWriter writer(options.outputFolder / "frames.h5", metadata);
  writer.writeStatic("wall", world.walls.fields);

  const std::vector<std::string> columns = seriesColumns(s.retina);
  std::vector<FrameCoverage> frames;
  WallOilFractions lastFractions;
  std::vector<sim::Vec3> fluidPositions;
  std::vector<std::int32_t> fluidMaterials;
  std::vector<std::string> stageNames;
  for (const auto& e : pipeline.timers().entries()) stageNames.push_back(e.name);

  auto record = [&]() {
    if (!frames.empty() && !(world.time > frames.back().time)) return;
    writer.writeFrame(world.time, world.stepCount, {{"fluid", &world.particles.fields}});
    fluidPositions.assign(world.particles.x.begin(), world.particles.x.end());
    fluidMaterials.assign(world.particles.material.begin(), world.particles.material.end());
    lastFractions = measureWallFractions(s, fluidPositions, fluidMaterials);
    frames.push_back(measureFrameCoverage(s.retina, lastFractions, world.time));
    std::vector<double> row;
    for (const auto& r : frames.back().regions) row.push_back(r.fraction);
    for (const auto& b : frames.back().breaks) {
      row.push_back(b.area.fraction);
      row.push_back(b.covered ? 1.0 : 0.0);
    }
    writer.appendSeries("coverage", world.time, row, columns);
    // Stage times so far (`tamponade report DIR` reads the last row).
    std::vector<double> seconds, calls;
    for (const auto& e : pipeline.timers().entries()) {
      seconds.push_back(e.seconds);
      calls.push_back(static_cast<double>(e.calls));
    }
    writer.appendSeries("stage_seconds", world.time, seconds, stageNames);
    writer.appendSeries("stage_calls", world.time, calls, stageNames);
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
  RunResults results{frames, lastFractions, pipeline.timers().entries(), pipeline.decisions()};
  const ReportInput in = makeRunReportInput(protocol, s, results);
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
