#include "protocols/scenario/run_scenario.h"

#include <chrono>
#include <optional>
#include <fstream>
#include <sstream>

#include "protocols/io/checkpoint.h"
#include "protocols/io/frame_reader.h"
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
  const std::filesystem::path h5 = options.outputFolder / "frames.h5";
  const std::filesystem::path checkpointPath = options.outputFolder / "checkpoint.h5";
  const long sortInterval = world.parameters().zSortInterval;  // [steps]

  const std::vector<std::string> columns = seriesColumns(s.retina);
  std::vector<FrameCoverage> frames;
  WallOilFractions lastFractions;
  std::vector<sim::Vec3> fluidPositions;
  std::vector<std::int32_t> fluidMaterials;
  std::vector<std::string> stageNames;
  for (const auto& e : pipeline.timers().entries()) stageNames.push_back(e.name);
  const double interval = protocol.outputs.frameInterval.value;  // [s]
  double nextFrame = world.time + interval;                      // [s]
  std::size_t firstPosture = 0;

  std::optional<FrameWriter> writer;
  if (options.resume) {
    // Continue from checkpoint.h5: restore the particle state and the run's counters, recompute
    // the coverage of the frames written so far, drop anything written after the checkpoint.
    CheckpointState state = readCheckpoint(checkpointPath, {{"fluid", &world.particles.fields}});
    world.time = state.time;
    world.stepCount = state.step;
    world.lastTimeStep = state.dt;
    firstPosture = static_cast<std::size_t>(state.integerCounters.at("posture"));
    nextFrame = state.realCounters.at("next_frame");
    for (std::size_t k = 0; k < stageNames.size(); ++k) {
      const auto it = state.realCounters.find("stage:" + stageNames[k]);
      if (it != state.realCounters.end()) pipeline.timers().add(static_cast<int>(k), it->second);
    }
    {
      const FrameReader reader(h5);
      std::vector<sim::Vec3> x;
      for (const FrameInfo& f : reader.frames()) {
        if (f.step > state.step) continue;
        const FieldData position = reader.readField(f.index, "fluid", sim::field::kPosition);
        const FieldData material = reader.readField(f.index, "fluid", sim::field::kMaterial);
        x.resize(position.rows);
        for (std::size_t i = 0; i < position.rows; ++i)
          x[i] = sim::Vec3(position.real(i, 0), position.real(i, 1), position.real(i, 2));
        lastFractions = measureWallFractions(s, x, material.integers);
        frames.push_back(measureFrameCoverage(s.retina, lastFractions, f.time));
      }
    }
    writer.emplace(FrameWriter::resume(h5, state.step, state.time));
  } else {
    RunMetadata metadata;
    metadata.protocolText = readText(protocol.file);
    metadata.strings["protocol_file"] = protocol.file.string();
    metadata.strings["accuracy"] = s.accuracy.preset;
    metadata.strings["accuracy_override"] = options.accuracyOverride;
    metadata.strings["solver"] = s.pipelineOptions.solver;
    metadata.numbers["particle_spacing [m]"] = s.accuracy.particleSpacing;
    writer.emplace(h5, metadata);
    writer->writeStatic("wall", world.walls.fields);
  }

  auto record = [&]() {
    if (!frames.empty() && !(world.time > frames.back().time)) return;
    writer->writeFrame(world.time, world.stepCount, {{"fluid", &world.particles.fields}});
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
    writer->appendSeries("coverage", world.time, row, columns);
    // Stage times so far (`tamponade report DIR` reads the last row).
    std::vector<double> seconds, calls;
    for (const auto& e : pipeline.timers().entries()) {
      seconds.push_back(e.seconds);
      calls.push_back(static_cast<double>(e.calls));
    }
    writer->appendSeries("stage_seconds", world.time, seconds, stageNames);
    writer->appendSeries("stage_calls", world.time, calls, stageNames);
  };
  // Checkpoints are taken only at steps that are multiples of the Z-sort interval: World keeps
  // its sort counter privately and a resumed World starts it at 0 (World::initialize), which is
  // what the continuous run's counter is at exactly those steps; with the particle order and
  // every checkpointed field restored, the resumed run repeats the same floating-point sums.
  auto checkpoint = [&](std::size_t posture) {
    CheckpointState state;
    state.time = world.time;
    state.step = world.stepCount;
    state.dt = world.lastTimeStep;
    state.integerCounters["posture"] = static_cast<std::int64_t>(posture);
    state.realCounters["next_frame"] = nextFrame;
    for (const auto& e : pipeline.timers().entries()) state.realCounters["stage:" + e.name] = e.seconds;
    state.groups["fluid"] = &world.particles.fields;
    writer->flush();
    writeCheckpoint(checkpointPath, state);
  };

  const double endTime = s.totalDuration();
  if (!options.resume) record();
  double postureEnd = 0.0;
  for (std::size_t k = 0; k < firstPosture; ++k) postureEnd += s.schedule[k].duration;
  RunSummary summary;
  for (std::size_t k = firstPosture; k < s.schedule.size() && !summary.stopped; ++k) {
    const ScheduledPosture& posture = s.schedule[k];
    world.gravity = posture.gravity;
    postureEnd += posture.duration;
    while (world.time < postureEnd) {
      pipeline.step(world);
      if (world.time >= nextFrame) {
        record();
        while (nextFrame <= world.time) nextFrame += interval;
      }
      if (options.progress) options.progress({world.time, endTime, world.stepCount, posture.label});
      if (world.stepCount % sortInterval != 0) continue;
      const bool stop = (options.stopRequested != nullptr && options.stopRequested->load()) ||
                        (options.stopAfterSteps > 0 && world.stepCount >= options.stopAfterSteps);
      if (stop || world.stepCount % options.checkpointInterval == 0) checkpoint(k);
      if (stop) {
        summary.stopped = true;
        break;
      }
    }
  }
  summary.frames = frames.size();
  summary.steps = world.stepCount;
  summary.simulatedTime = world.time;
  if (summary.stopped) {
    writer->close();
    summary.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    return summary;
  }
  record();  // the end state (skipped when the last step already wrote it)
  writer->close();

  // Report.
  RunResults results{frames, lastFractions, pipeline.timers().entries(), pipeline.decisions()};
  const ReportInput in = makeRunReportInput(protocol, s, results);
  if (protocol.outputs.report.value) writeReport(in, options.outputFolder);

  summary.frames = frames.size();
  summary.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  summary.retinaCoverage = in.summary.regions[0];
  return summary;
}

}  // namespace protocols
