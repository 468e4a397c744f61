#include "protocols/run/scenario_run.h"

#include <bit>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "protocols/assembly/assemble_scenario.h"
#include "protocols/equilibrium/posture_equilibrium.h"
#include "protocols/io/checkpoint.h"
#include "protocols/io/frame_reader.h"
#include "protocols/io/io_error.h"
#include "protocols/report/write_report.h"
#include "protocols/run/rebuild_report.h"
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

ScenarioRun::ScenarioRun(const Protocol& protocol, Scenario& scenario, const RunOptions& options)
    : protocol_(protocol),
      s_(scenario),
      world_(*scenario.world),
      options_(options),
      wallStart_(std::chrono::steady_clock::now()),
      pipeline_(sim::assemblePipeline(world_, scenario.pipelineOptions)),
      criteria_(options.steady ? *options.steady : steadyCriteriaOf(protocol)),
      columns_(seriesColumns(scenario.retina)),
      interval_(protocol.outputs.frameInterval.value) {
  pipeline_.attach(world_);
  for (const auto& e : pipeline_.timers().entries()) stageNames_.push_back(e.name);
}

void ScenarioRun::open() {
  if (!options_.resume) requireStartTimeStep(s_, pipeline_.chooseTimeStep(world_));  // no files yet
  solveLeadingEquilibria();
  state_.nextFrame = world_.time + interval_;
  if (options_.resume)
    resume();
  else
    start();
  sim::DeterministicReducer r;
  totalMass_ =
      r.sum(world_.particles.size(), [&](std::size_t i) { return world_.particles.mass[i]; });
  if (!options_.resume) record();
}

// A mixed schedule: the postures at equilibrium it begins with, solved before the first step
// (their frames come first; their interfaces are written once) and again on resume, for the
// report. The simulation starts at the end of their nominal seconds, on the schedule's clock.
void ScenarioRun::solveLeadingEquilibria() {
  const std::size_t count = equilibriaBeforeSimulation(s_);
  if (count == 0) return;
  equilibria_ = solveEquilibriumPostures(
      protocol_, s_, count, options_.resume ? std::filesystem::path() : options_.outputFolder,
      options_.equilibriumProgress);
  frames_ = equilibria_.frames;
  simulatedStart_ = equilibria_.end;
  if (options_.resume) return;  // the checkpoint holds the clock and the posture
  world_.time = simulatedStart_;
  state_.posture = count;
  state_.postureStart = simulatedStart_;
  state_.nextSample = simulatedStart_;
}

void ScenarioRun::start() {
  RunMetadata metadata;
  metadata.protocolText = readText(protocol_.file);
  metadata.strings["protocol_file"] = protocol_.file.string();
  metadata.strings["accuracy"] = s_.accuracy.preset;
  metadata.strings["accuracy_override"] = options_.accuracyOverride;
  metadata.strings["solver"] = s_.pipelineOptions.solver;
  metadata.numbers["particle_spacing [m]"] = s_.accuracy.particleSpacing;
  metadata.numbers["steady window [s]"] = criteria_.window;
  metadata.numbers["steady kinetic energy per mass [J/kg]"] = criteria_.kineticEnergyPerMass;
  metadata.numbers["steady coverage change [1]"] = criteria_.coverageChange;
  writer_.emplace(options_.outputFolder / "frames.h5", metadata);
  writer_->writeStatic("wall", world_.walls.fields);
}

// Continue from checkpoint.h5: restore the particle state and the run's state, recompute the
// coverage of the frames written so far, drop anything written after the checkpoint. The walls'
// group holds their solver state (INDSPH's wall stiffness on layered walls).
void ScenarioRun::resume() {
  const std::filesystem::path path = options_.outputFolder / "checkpoint.h5";
  CheckpointState checkpoint =
      readCheckpoint(path, {{"fluid", &world_.particles.fields}, {"wall", &world_.walls.fields}});
  if (checkpoint.blobs[kIdentityBlob] != scenarioIdentity(protocol_, s_))
    throw IoError(path.string(), std::string("/blobs/") + kIdentityBlob,
                  "the checkpoint belongs to another protocol or accuracy than this run's "
                  "frames.h5 (it was copied from another run folder?)",
                  "resume the folder the checkpoint was written in, or start this run afresh");
  world_.time = checkpoint.time;
  world_.stepCount = checkpoint.step;
  world_.lastTimeStep = checkpoint.dt;
  state_ = RunState::restore(checkpoint);
  for (std::size_t k = 0; k < stageNames_.size(); ++k) {
    const auto it = state_.stageSeconds.find(stageNames_[k]);
    if (it != state_.stageSeconds.end()) pipeline_.timers().add(static_cast<int>(k), it->second);
  }
  remeasureFrames(checkpoint);
  writer_.emplace(
      FrameWriter::resume(options_.outputFolder / "frames.h5", checkpoint.step, checkpoint.time));
}

void ScenarioRun::remeasureFrames(const CheckpointState& checkpoint) {
  const FrameReader reader(options_.outputFolder / "frames.h5");
  applyRecordedPostureEnds(reader, s_, checkpoint.time);
  std::vector<sim::Vec3> x;
  for (const FrameInfo& f : reader.frames()) {
    if (f.step > checkpoint.step) continue;
    const FieldData position = reader.readField(f.index, "fluid", sim::field::kPosition);
    const FieldData material = reader.readField(f.index, "fluid", sim::field::kMaterial);
    x.resize(position.rows);
    for (std::size_t i = 0; i < position.rows; ++i)
      x[i] = sim::Vec3(position.real(i, 0), position.real(i, 1), position.real(i, 2));
    std::vector<std::int32_t> ids;
    if (s_.retinaSamples.moves())
      ids = reader.readField(f.index, "fluid", sim::field::kId).integers;
    lastFractions_ = measureWallFractions(s_, x, material.integers, ids);
    if (!s_.tissues.empty() && !ids.empty()) lastTissue_ = measureTissues(s_, x, ids);
    frames_.push_back(measureFrameCoverage(s_.retina, lastFractions_, f.time));
  }
}

void ScenarioRun::snapshotParticles() {
  fluidPositions_.assign(world_.particles.x.begin(), world_.particles.x.end());
  fluidMaterials_.assign(world_.particles.material.begin(), world_.particles.material.end());
  fluidIds_.assign(world_.particles.id.begin(), world_.particles.id.end());
}

void ScenarioRun::record() {
  if (!frames_.empty() && !(world_.time > frames_.back().time)) return;
  snapshotParticles();
  if (world_.particles.fields.has(kTissueDisplacementField))
    updateTissueDisplacement(s_, fluidPositions_, fluidIds_,
                             world_.particles.fields.get<sim::Vec3>(kTissueDisplacementField));
  writer_->writeFrame(world_.time, world_.stepCount,
                      {{"fluid", &world_.particles.fields, s_.outputFields}});
  lastFractions_ = measureWallFractions(s_, fluidPositions_, fluidMaterials_, fluidIds_);
  if (!s_.tissues.empty()) appendTissueSeries();
  frames_.push_back(measureFrameCoverage(s_.retina, lastFractions_, world_.time));
  appendRunSeries();
}

void ScenarioRun::appendTissueSeries() {
  lastTissue_ = measureTissues(s_, fluidPositions_, fluidIds_);
  std::vector<double> row = lastTissue_.maxDisplacement;
  std::vector<std::string> names;
  for (const TissueBody& t : s_.tissues) names.push_back(t.name + " max displacement [m]");
  row.push_back(lastTissue_.retinaMaxDisplacement);
  names.emplace_back("retina max displacement [m]");
  row.push_back(lastTissue_.cavityVolumeChange);
  names.emplace_back("cavity volume change [m^3]");
  if (!s_.retinaSamples.scleraLayer.empty()) {  // the leak counter (tissue_measures.h)
    row.push_back(static_cast<double>(lastTissue_.fluidInTissue));
    names.emplace_back("fluid particles in the tissue [1]");
    row.push_back(static_cast<double>(lastTissue_.fluidThroughTissue));
    names.emplace_back("fluid particles beyond the tissue layer [1]");
  }
  writer_->appendSeries("tissue", world_.time, row, names);
}

// The coverage of the frame just recorded, the stage times so far (`tamponade report DIR` reads
// the last row) and the pressure-solve totals.
void ScenarioRun::appendRunSeries() {
  std::vector<double> row;
  for (const auto& r : frames_.back().regions) row.push_back(r.fraction);
  for (const auto& b : frames_.back().breaks) {
    row.push_back(b.area.fraction);
    row.push_back(b.covered ? 1.0 : 0.0);
  }
  writer_->appendSeries("coverage", world_.time, row, columns_);
  std::vector<double> seconds, calls;
  for (const auto& e : pipeline_.timers().entries()) {
    seconds.push_back(e.seconds);
    calls.push_back(static_cast<double>(e.calls));
  }
  writer_->appendSeries("stage_seconds", world_.time, seconds, stageNames_);
  writer_->appendSeries("stage_calls", world_.time, calls, stageNames_);
  writer_->appendSeries("pressure_solve", world_.time, state_.solve.row(),
                        PressureSolveTotals::columns());
}

// Checkpoints are taken only at steps that are multiples of the Z-sort interval: World keeps
// its sort counter privately and a resumed World starts it at 0 (World::initialize), which is
// what the continuous run's counter is at exactly those steps; with the particle order and
// every checkpointed field restored, the resumed run repeats the same floating-point sums.
// `posture` is the posture the resumed run continues with (the next one if this step ended one).
void ScenarioRun::checkpoint(std::size_t posture) {
  CheckpointState checkpoint;
  checkpoint.time = world_.time;
  checkpoint.step = world_.stepCount;
  checkpoint.dt = world_.lastTimeStep;
  RunState saved = state_;
  saved.posture = posture;
  saved.stageSeconds.clear();
  for (const auto& e : pipeline_.timers().entries()) saved.stageSeconds[e.name] = e.seconds;
  saved.save(checkpoint);
  checkpoint.blobs[kIdentityBlob] = scenarioIdentity(protocol_, s_);
  checkpoint.groups["fluid"] = &world_.particles.fields;
  checkpoint.groups["wall"] = &world_.walls.fields;
  writer_->flush();
  writeCheckpoint(options_.outputFolder / "checkpoint.h5", checkpoint);
}

// One steady-state sample: the fluid's kinetic energy per mass and every region's and break's
// coverage now.
SteadySample ScenarioRun::sample() {
  snapshotParticles();
  const FrameCoverage c = measureFrameCoverage(
      s_.retina, measureWallFractions(s_, fluidPositions_, fluidMaterials_, fluidIds_),
      world_.time);
  SteadySample out{world_.time, sim::kineticEnergy(world_) / totalMass_, {}};
  for (const auto& r : c.regions) out.coverage.push_back(r.fraction);
  for (const auto& b : c.breaks) out.coverage.push_back(b.area.fraction);
  return out;
}

bool ScenarioRun::stopRequested() const {
  return (options_.stopRequested != nullptr && options_.stopRequested->load()) ||
         (options_.stopAfterSteps > 0 && world_.stepCount >= options_.stopAfterSteps);
}

bool ScenarioRun::runPosture(std::size_t k) {
  ScheduledPosture& posture = s_.schedule[k];
  world_.gravity = posture.gravity;
  const double postureEnd = state_.postureStart + posture.duration;  // [s] at the latest
  bool ended = !(world_.time < postureEnd);
  // Ends the posture now: a row in "postures" and the next posture's start. A posture that ran
  // its duration ends on the schedule's clock (its nominal end, so the last step's overshoot
  // does not accumulate over the schedule, as before "until steady" existed); a steady one ends
  // now, and its duration in the schedule becomes what was run.
  auto endPosture = [&](bool steady) {
    writer_->appendSeries("postures", world_.time,
                          {static_cast<double>(k), steady ? 1.0 : 0.0, state_.postureStart},
                          {"posture", "steady", "start"});
    if (steady) posture.duration = world_.time - state_.postureStart;
    posture.endedSteady = steady;
    state_.postureStart = steady ? world_.time : postureEnd;
    state_.nextSample = state_.postureStart;
    state_.samples.clear();
    ended = true;
  };
  if (ended) endPosture(false);
  while (!ended) {
    pipeline_.step(world_);
    state_.solve.add(pipeline_.solver().stats(), world_.lastTimeStep);
    if (world_.time >= state_.nextFrame) {
      record();
      state_.nextFrame = nextTimeAfter(state_.nextFrame, interval_, world_.time);
    }
    if (options_.progress)
      options_.progress({world_.time - simulatedStart_, s_.totalDuration() - simulatedStart_,
                         world_.stepCount, posture.label});
    bool steady = false;
    if (posture.untilSteady && world_.time >= state_.nextSample) steady = sampleSteadiness();
    if (steady || world_.time >= postureEnd) endPosture(steady);
    if (world_.stepCount % world_.parameters().zSortInterval != 0) continue;
    const bool stop = stopRequested();
    if (stop || world_.stepCount % options_.checkpointInterval == 0) checkpoint(ended ? k + 1 : k);
    if (stop) return false;
  }
  return true;
}

// Takes a steady-state sample and keeps one window: the newest sample at or before the window's
// start and all after it. Returns whether the posture is steady.
bool ScenarioRun::sampleSteadiness() {
  state_.samples.push_back(sample());
  state_.nextSample = nextTimeAfter(state_.nextSample, criteria_.sampleInterval, world_.time);
  const bool steady = isSteady(state_.samples, state_.postureStart, criteria_);
  std::size_t keep = 0;
  while (keep + 1 < state_.samples.size() &&
         state_.samples[keep + 1].time <= world_.time - criteria_.window)
    ++keep;
  state_.samples.erase(state_.samples.begin(),
                       state_.samples.begin() + static_cast<std::ptrdiff_t>(keep));
  return steady;
}

RunSummary ScenarioRun::summary(bool stopped) const {
  RunSummary summary;
  summary.stopped = stopped;
  summary.frames = frames_.size();
  summary.steps = world_.stepCount;
  summary.simulatedTime = world_.time - simulatedStart_;
  summary.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
  return summary;
}

RunSummary ScenarioRun::stop() {
  writer_->close();
  return summary(true);
}

RunSummary ScenarioRun::finish() {
  record();  // the end state (skipped when the last step already wrote it)
  writer_->close();
  const double meanStep =
      world_.stepCount > 0 ? (world_.time - simulatedStart_) / static_cast<double>(world_.stepCount)
                           : 0.0;
  const RunResults results{
      frames_,  lastFractions_, pipeline_.timers().entries(), pipeline_.decisions(), lastTissue_,
      meanStep, state_.solve};
  ReportInput in = makeRunReportInput(protocol_, s_, results);
  if (!equilibria_.postures.empty()) addLeadingEquilibria(equilibria_, in);
  if (protocol_.outputs.report.value) writeReport(in, options_.outputFolder);
  RunSummary out = summary(false);
  out.retinaCoverage = in.summary.regions[0];
  out.pressureSolve = state_.solve;
  out.coverage = in.summary;
  for (const ReportPosture& p : in.postures)
    out.retinaAtPostureEnd.push_back(
        retinaCoverageAt(frames_, p.end).value_or(std::numeric_limits<double>::quiet_NaN()));
  return out;
}

}  // namespace protocols
