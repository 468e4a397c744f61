#include "protocols/scenario/run_scenario.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "protocols/io/checkpoint.h"
#include "protocols/io/frame_reader.h"
#include "protocols/io/frame_writer.h"
#include "protocols/io/io_error.h"
#include "protocols/report/write_report.h"
#include "protocols/scenario/rebuild_report.h"
#include "sim/core/reduction.h"
#include "sim/measure/diagnostics.h"

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

// What a checkpoint belongs to: the protocol text and the accuracy the scene was assembled at
// (a command-line preset changes the particles, not the text). A checkpoint copied from another
// run's folder carries another one and is refused.
std::vector<std::uint8_t> scenarioIdentity(const Protocol& protocol, const Scenario& s) {
  const std::uint64_t hash =
      textChecksum(readText(protocol.file) + '\0' + s.accuracy.preset + '\0' +
                   std::to_string(std::bit_cast<std::uint64_t>(s.accuracy.particleSpacing)));
  std::vector<std::uint8_t> bytes(sizeof hash);
  std::memcpy(bytes.data(), &hash, sizeof hash);
  return bytes;
}

constexpr const char* kIdentityBlob = "protocol_hash";

}  // namespace

double nextTimeAfter(double next, double interval, double now) {
  // Stepping by `interval` keeps the times on the schedule's grid (start + k interval) as before;
  // far behind (an interval much shorter than the step) or stalled (next + interval == next in
  // floating point) the next time is taken from now instead, so this always ends.
  constexpr int kMostIncrements = 64;
  for (int k = 0; k < kMostIncrements && next <= now; ++k) {
    const double advanced = next + interval;
    if (!(advanced > next)) break;
    next = advanced;
  }
  if (next > now) return next;
  const double fromNow = now + interval;
  return fromNow > now ? fromNow : std::nextafter(now, std::numeric_limits<double>::infinity());
}

void applyRecordedPostureEnds(const FrameReader& reader, Scenario& s, double upTo) {
  const std::vector<std::string> names = reader.seriesNames();
  if (std::find(names.begin(), names.end(), "postures") == names.end()) return;
  const SeriesData ends = reader.readSeries("postures");
  const std::vector<double> times = ends.column("time"), index = ends.column("posture"),
                            steady = ends.column("steady"), start = ends.column("start");
  for (std::size_t r = 0; r < ends.rows; ++r) {
    const auto k = static_cast<std::size_t>(index[r]);
    if (times[r] > upTo || k >= s.schedule.size()) continue;
    s.schedule[k].endedSteady = steady[r] > 0;
    if (steady[r] > 0) s.schedule[k].duration = times[r] - start[r];
  }
}

RunSummary runScenario(const Protocol& protocol, Scenario& s, const RunOptions& options) {
  const auto wallStart = std::chrono::steady_clock::now();
  sim::World& world = *s.world;
  sim::Pipeline pipeline = sim::assemblePipeline(world, s.pipelineOptions);
  pipeline.attach(world);
  if (!options.resume) requireStartTimeStep(s, pipeline.chooseTimeStep(world));  // before files
  const std::filesystem::path h5 = options.outputFolder / "frames.h5";
  const std::filesystem::path checkpointPath = options.outputFolder / "checkpoint.h5";
  const long sortInterval = world.parameters().zSortInterval;  // [steps]
  const SteadyCriteria criteria = options.steady ? *options.steady : steadyCriteriaOf(protocol);

  const std::vector<std::string> columns = seriesColumns(s.retina);
  std::vector<FrameCoverage> frames;
  WallOilFractions lastFractions;
  std::vector<sim::Vec3> fluidPositions;
  std::vector<std::int32_t> fluidMaterials, fluidIds;
  TissueMeasures lastTissue;  // of the last frame (tissue_particles.h)
  const bool tissue = !s.tissues.empty();
  std::vector<std::string> stageNames;
  for (const auto& e : pipeline.timers().entries()) stageNames.push_back(e.name);
  const double interval = protocol.outputs.frameInterval.value;  // [s]
  double nextFrame = world.time + interval;                      // [s]
  std::size_t firstPosture = 0;
  double postureStart = 0.0;          // [s] simulated time the current posture began
  double nextSample = 0.0;            // [s] next steady-state sample (until steady)
  std::vector<SteadySample> samples;  // of the current posture, trimmed to one window
  PressureSolveTotals solve;          // since the run's start (carried over a resume)

  std::optional<FrameWriter> writer;
  if (options.resume) {
    // Continue from checkpoint.h5: restore the particle state and the run's counters, recompute
    // the coverage of the frames written so far, drop anything written after the checkpoint.
    // The walls' group holds their solver state (INDSPH's wall stiffness on layered walls).
    CheckpointState state = readCheckpoint(
        checkpointPath, {{"fluid", &world.particles.fields}, {"wall", &world.walls.fields}});
    if (state.blobs[kIdentityBlob] != scenarioIdentity(protocol, s))
      throw IoError(checkpointPath.string(), std::string("/blobs/") + kIdentityBlob,
                    "the checkpoint belongs to another protocol or accuracy than this run's "
                    "frames.h5 (it was copied from another run folder?)",
                    "resume the folder the checkpoint was written in, or start this run afresh");
    world.time = state.time;
    world.stepCount = state.step;
    world.lastTimeStep = state.dt;
    firstPosture = static_cast<std::size_t>(state.integerCounters.at("posture"));
    nextFrame = state.realCounters.at("next_frame");
    postureStart = state.realCounters.at("posture_start");
    nextSample = state.realCounters.at("next_sample");
    const auto count = state.integerCounters.at("steady_samples");
    for (std::int64_t k = 0; k < count; ++k) {
      const std::string key = "steady:" + std::to_string(k) + ":";
      SteadySample restored{
          state.realCounters.at(key + "time"), state.realCounters.at(key + "energy"), {}};
      const auto values = state.integerCounters.at(key + "coverages");
      for (std::int64_t c = 0; c < values; ++c)
        restored.coverage.push_back(state.realCounters.at(key + "coverage:" + std::to_string(c)));
      samples.push_back(std::move(restored));
    }
    solve = PressureSolveTotals::restore(state.realCounters);
    for (std::size_t k = 0; k < stageNames.size(); ++k) {
      const auto it = state.realCounters.find("stage:" + stageNames[k]);
      if (it != state.realCounters.end()) pipeline.timers().add(static_cast<int>(k), it->second);
    }
    {
      const FrameReader reader(h5);
      applyRecordedPostureEnds(reader, s, state.time);
      std::vector<sim::Vec3> x;
      for (const FrameInfo& f : reader.frames()) {
        if (f.step > state.step) continue;
        const FieldData position = reader.readField(f.index, "fluid", sim::field::kPosition);
        const FieldData material = reader.readField(f.index, "fluid", sim::field::kMaterial);
        x.resize(position.rows);
        for (std::size_t i = 0; i < position.rows; ++i)
          x[i] = sim::Vec3(position.real(i, 0), position.real(i, 1), position.real(i, 2));
        std::vector<std::int32_t> ids;
        if (s.retinaSamples.moves())
          ids = reader.readField(f.index, "fluid", sim::field::kId).integers;
        lastFractions = measureWallFractions(s, x, material.integers, ids);
        if (tissue && !ids.empty()) lastTissue = measureTissues(s, x, ids);
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
    metadata.numbers["steady window [s]"] = criteria.window;
    metadata.numbers["steady kinetic energy per mass [J/kg]"] = criteria.kineticEnergyPerMass;
    metadata.numbers["steady coverage change [1]"] = criteria.coverageChange;
    writer.emplace(h5, metadata);
    writer->writeStatic("wall", world.walls.fields);
  }

  auto record = [&]() {
    if (!frames.empty() && !(world.time > frames.back().time)) return;
    fluidPositions.assign(world.particles.x.begin(), world.particles.x.end());
    fluidMaterials.assign(world.particles.material.begin(), world.particles.material.end());
    fluidIds.assign(world.particles.id.begin(), world.particles.id.end());
    if (world.particles.fields.has(kTissueDisplacementField))
      updateTissueDisplacement(s, fluidPositions, fluidIds,
                               world.particles.fields.get<sim::Vec3>(kTissueDisplacementField));
    writer->writeFrame(world.time, world.stepCount,
                       {{"fluid", &world.particles.fields, s.outputFields}});
    lastFractions = measureWallFractions(s, fluidPositions, fluidMaterials, fluidIds);
    if (tissue) {
      lastTissue = measureTissues(s, fluidPositions, fluidIds);
      std::vector<double> row = lastTissue.maxDisplacement;
      std::vector<std::string> names;
      for (const TissueBody& t : s.tissues) names.push_back(t.name + " max displacement [m]");
      row.push_back(lastTissue.retinaMaxDisplacement);
      names.emplace_back("retina max displacement [m]");
      row.push_back(lastTissue.cavityVolumeChange);
      names.emplace_back("cavity volume change [m^3]");
      if (!s.retinaSamples.scleraLayer.empty()) {  // the leak counter (tissue_particles.h)
        row.push_back(static_cast<double>(lastTissue.fluidInTissue));
        names.emplace_back("fluid particles in the tissue [1]");
        row.push_back(static_cast<double>(lastTissue.fluidThroughTissue));
        names.emplace_back("fluid particles beyond the tissue layer [1]");
      }
      writer->appendSeries("tissue", world.time, row, names);
    }
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
    writer->appendSeries("pressure_solve", world.time, solve.row(), PressureSolveTotals::columns());
  };
  // Checkpoints are taken only at steps that are multiples of the Z-sort interval: World keeps
  // its sort counter privately and a resumed World starts it at 0 (World::initialize), which is
  // what the continuous run's counter is at exactly those steps; with the particle order and
  // every checkpointed field restored, the resumed run repeats the same floating-point sums.
  // `posture` is the posture the resumed run continues with (the next one if this step ended one).
  auto checkpoint = [&](std::size_t posture) {
    CheckpointState state;
    state.time = world.time;
    state.step = world.stepCount;
    state.dt = world.lastTimeStep;
    state.integerCounters["posture"] = static_cast<std::int64_t>(posture);
    state.realCounters["next_frame"] = nextFrame;
    state.realCounters["posture_start"] = postureStart;
    state.realCounters["next_sample"] = nextSample;
    state.integerCounters["steady_samples"] = static_cast<std::int64_t>(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
      const std::string key = "steady:" + std::to_string(k) + ":";
      state.realCounters[key + "time"] = samples[k].time;
      state.realCounters[key + "energy"] = samples[k].kineticEnergyPerMass;
      state.integerCounters[key + "coverages"] =
          static_cast<std::int64_t>(samples[k].coverage.size());
      for (std::size_t c = 0; c < samples[k].coverage.size(); ++c)
        state.realCounters[key + "coverage:" + std::to_string(c)] = samples[k].coverage[c];
    }
    for (const auto& e : pipeline.timers().entries())
      state.realCounters["stage:" + e.name] = e.seconds;
    solve.save(state.realCounters);
    state.blobs[kIdentityBlob] = scenarioIdentity(protocol, s);
    state.groups["fluid"] = &world.particles.fields;
    state.groups["wall"] = &world.walls.fields;
    writer->flush();
    writeCheckpoint(checkpointPath, state);
  };
  // One steady-state sample: the fluid's kinetic energy per mass and every region's and break's
  // coverage now.
  double totalMass = 0.0;  // [kg] constant
  {
    sim::DeterministicReducer r;
    totalMass =
        r.sum(world.particles.size(), [&](std::size_t i) { return world.particles.mass[i]; });
  }
  auto sample = [&]() {
    fluidPositions.assign(world.particles.x.begin(), world.particles.x.end());
    fluidMaterials.assign(world.particles.material.begin(), world.particles.material.end());
    fluidIds.assign(world.particles.id.begin(), world.particles.id.end());
    const FrameCoverage c = measureFrameCoverage(
        s.retina, measureWallFractions(s, fluidPositions, fluidMaterials, fluidIds), world.time);
    SteadySample out{world.time, sim::kineticEnergy(world) / totalMass, {}};
    for (const auto& r : c.regions) out.coverage.push_back(r.fraction);
    for (const auto& b : c.breaks) out.coverage.push_back(b.area.fraction);
    return out;
  };

  if (!options.resume) record();
  RunSummary summary;
  for (std::size_t k = firstPosture; k < s.schedule.size() && !summary.stopped; ++k) {
    ScheduledPosture& posture = s.schedule[k];
    world.gravity = posture.gravity;
    const double postureEnd = postureStart + posture.duration;  // [s] at the latest
    bool ended = !(world.time < postureEnd);
    // Ends the posture now: a row in "postures" and the next posture's start. A posture that ran
    // its duration ends on the schedule's clock (its nominal end, so the last step's overshoot
    // does not accumulate over the schedule, as before "until steady" existed); a steady one ends
    // now, and its duration in the schedule becomes what was run.
    auto endPosture = [&](bool steady) {
      writer->appendSeries("postures", world.time,
                           {static_cast<double>(k), steady ? 1.0 : 0.0, postureStart},
                           {"posture", "steady", "start"});
      if (steady) posture.duration = world.time - postureStart;
      posture.endedSteady = steady;
      postureStart = steady ? world.time : postureEnd;
      nextSample = postureStart;
      samples.clear();
      ended = true;
    };
    if (ended) endPosture(false);
    while (!ended) {
      pipeline.step(world);
      solve.add(pipeline.solver().stats(), world.lastTimeStep);
      if (world.time >= nextFrame) {
        record();
        nextFrame = nextTimeAfter(nextFrame, interval, world.time);
      }
      const double endTime = s.totalDuration();
      if (options.progress) options.progress({world.time, endTime, world.stepCount, posture.label});
      bool steady = false;
      if (posture.untilSteady && world.time >= nextSample) {
        samples.push_back(sample());
        nextSample = nextTimeAfter(nextSample, criteria.sampleInterval, world.time);
        steady = isSteady(samples, postureStart, criteria);
        // Keep one window: the newest sample at or before the window's start and all after it.
        std::size_t keep = 0;
        while (keep + 1 < samples.size() && samples[keep + 1].time <= world.time - criteria.window)
          ++keep;
        samples.erase(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(keep));
      }
      if (steady || world.time >= postureEnd) endPosture(steady);
      if (world.stepCount % sortInterval != 0) continue;
      const bool stop = (options.stopRequested != nullptr && options.stopRequested->load()) ||
                        (options.stopAfterSteps > 0 && world.stepCount >= options.stopAfterSteps);
      if (stop || world.stepCount % options.checkpointInterval == 0) checkpoint(ended ? k + 1 : k);
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
    summary.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    return summary;
  }
  record();  // the end state (skipped when the last step already wrote it)
  writer->close();

  // Report.
  RunResults results{frames,
                     lastFractions,
                     pipeline.timers().entries(),
                     pipeline.decisions(),
                     lastTissue,
                     world.stepCount > 0 ? world.time / static_cast<double>(world.stepCount) : 0.0,
                     solve};
  const ReportInput in = makeRunReportInput(protocol, s, results);
  if (protocol.outputs.report.value) writeReport(in, options.outputFolder);

  summary.frames = frames.size();
  summary.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  summary.retinaCoverage = in.summary.regions[0];
  summary.pressureSolve = solve;
  summary.coverage = in.summary;
  return summary;
}

}  // namespace protocols
