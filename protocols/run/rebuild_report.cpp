#include "protocols/run/rebuild_report.h"

#include "protocols/run/run_scenario.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "protocols/assembly/assemble_scenario.h"
#include "protocols/equilibrium/posture_equilibrium.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/io/frame_reader.h"
#include "protocols/io/io_error.h"
#include "protocols/report/write_report.h"
#include "protocols/run/equilibrium_postures.h"
#include "protocols/run/scenario_report_input.h"
#include "protocols/run/unsteady_postures.h"
#include "protocols/tissue/tissue_measures.h"
#include "sim/world/stage_registry.h"

namespace protocols {

ReportInput makeRunReportInput(const Protocol& protocol, const Scenario& s, const RunResults& r) {
  ReportInput in = makeReportInput(protocol, s);
  in.frames = r.frames;
  in.summary = summarizeSchedule(r.frames);
  in.mapTime = r.frames.back().time;
  in.wallPositions = s.retinaSamples.restPositions;  // the map is drawn at rest
  in.tissue = tissueReportLines(s, r.lastTissue, r.frames.back().time, r.meanTimeStep);
  in.wallOilFraction = r.lastFractions.oilFraction;
  in.wallWetting = r.lastFractions.wetting;
  in.wallRegions = s.retina.regions;
  addUnsteadyPostureDistances(protocol, s, in);
  for (const auto& e : r.timers) {
    ReportStage st{e.name, true, "", e.seconds, e.calls};
    for (const auto& d : r.decisions)
      if (d.name == e.name) st.reason = d.reason;
    in.stages.push_back(st);
  }
  for (const auto& d : r.decisions)
    if (!d.active) in.stages.push_back({d.name, false, d.reason, 0.0, 0});
  const PressureSolveTotals& solve = r.pressureSolve;
  if (solve.steps > 0 && solve.implicitSolve()) {
    in.pressureSolve = ReportPressureSolve{s.accuracy.solverTolerance,
                                           solve.meanDensityError(),
                                           solve.maxStepDensityError,
                                           solve.meanIterations(),
                                           solve.capFraction(),
                                           solve.iterationCap,
                                           solve.steps};
    in.accuracy.push_back({"pressure solve (achieved)", pressureSolveValue(*in.pressureSolve),
                           pressureSolveNote(*in.pressureSolve)});
  }
  return in;
}

WallOilFractions measureWallFractions(const Scenario& s, const std::vector<sim::Vec3>& positions,
                                      const std::vector<std::int32_t>& material,
                                      const std::vector<std::int32_t>& ids) {
  const double d = s.accuracy.particleSpacing;
  const sim::Kernel kernel(sim::KernelKind::kCubicSpline, coverageSupportRadius(d, 1.2 * d));
  std::vector<sim::Vec3> x;
  std::vector<std::uint8_t> flags;
  std::vector<double> volumes;  // [m^3] rest volume m / rho0 of each particle's phase
  x.reserve(positions.size());
  flags.reserve(positions.size());
  volumes.reserve(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const bool oil = material[i] == s.phases[1].materialIndex;
    if (!oil && material[i] != s.phases[0].materialIndex) continue;  // tissue
    const FluidPhase& phase = oil ? s.phases[1] : s.phases[0];
    x.push_back(positions[i]);
    flags.push_back(phase.isTamponade ? 1 : 0);
    volumes.push_back(phase.particleMass / phase.density);
  }
  const std::vector<sim::Vec3> retina = s.retinaSamples.moves() && !ids.empty()
                                            ? retinaPositions(s, positions, ids)
                                            : s.retinaSamples.restPositions;
  return computeWallOilFractions(retina, {&x, &flags, &volumes}, kernel);
}

namespace {

// Whether the run behind `reader` ended all `postures` of its schedule: the runner appends a row
// to the "postures" series as each posture ends, so a run stopped early lacks the last one. Runs
// written before that series existed are judged by their last frame: a finished run's is at the
// schedule's end (`scheduled` [s], to the rounding of a sum of durations).
bool ranWholeSchedule(const FrameReader& reader, std::size_t postures, double lastFrameTime,
                      double scheduled) {
  const std::vector<std::string> names = reader.seriesNames();
  if (std::find(names.begin(), names.end(), "postures") == names.end())
    return !(lastFrameTime < scheduled * (1 - 1e-9));
  const std::vector<double> ended = reader.readSeries("postures").column("posture");
  return std::find(ended.begin(), ended.end(), static_cast<double>(postures - 1)) != ended.end();
}

// Every frame's coverage (and tissue state) recomputed from its fluid positions and materials,
// appended to r.frames; r.lastFractions and r.lastTissue are the last frame's.
void measureRunFrames(const FrameReader& reader, const Scenario& s, RunResults& r) {
  std::vector<sim::Vec3> x;
  std::vector<std::int32_t> ids;
  const bool tissue = std::find(s.outputFields.begin(), s.outputFields.end(), sim::field::kId) !=
                          s.outputFields.end() &&
                      s.retinaSamples.moves();
  for (const FrameInfo& f : reader.frames()) {
    const FieldData position = reader.readField(f.index, "fluid", sim::field::kPosition);
    const FieldData material = reader.readField(f.index, "fluid", sim::field::kMaterial);
    x.resize(position.rows);
    for (std::size_t i = 0; i < position.rows; ++i)
      x[i] = sim::Vec3(position.real(i, 0), position.real(i, 1), position.real(i, 2));
    if (tissue) ids = reader.readField(f.index, "fluid", sim::field::kId).integers;
    if (!s.tissues.empty()) {
      if (!tissue) {
        ids.resize(x.size());
        for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<std::int32_t>(i);
      }
      r.lastTissue = measureTissues(s, x, ids);
    }
    r.lastFractions = measureWallFractions(s, x, material.integers, ids);
    r.frames.push_back(measureFrameCoverage(s.retina, r.lastFractions, f.time));
  }
}

}  // namespace

Protocol loadRunProtocol(const std::filesystem::path& folder, ScenarioOptions& options) {
  const RunInfo info = FrameReader(folder / "frames.h5").runInfo();
  std::filesystem::path protocolPath;
  const auto original = info.strings.find("protocol_file");
  if (original != info.strings.end() && std::filesystem::exists(original->second)) {
    std::ifstream in(original->second, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (text.str() == info.protocolText) protocolPath = original->second;
  }
  if (protocolPath.empty()) {
    protocolPath = folder / "protocol.toml";
    std::ofstream(protocolPath, std::ios::binary) << info.protocolText;
  }
  const auto override = info.strings.find("accuracy_override");
  if (override != info.strings.end() && !override->second.empty())
    for (std::size_t p = 0; p < kAccuracyPresetNames.size(); ++p)
      if (kAccuracyPresetNames[p] == override->second)
        options.accuracy = static_cast<AccuracyPreset>(p);
  return parseProtocol(protocolPath.string());
}

void rebuildReport(const std::filesystem::path& folder) {
  const std::filesystem::path h5 = folder / "frames.h5";
  ScenarioOptions options;
  const Protocol protocol = loadRunProtocol(folder, options);
  const FrameReader reader(h5);
  const RunInfo info = reader.runInfo();
  Scenario s = assembleScenario(protocol, options);
  applyRecordedPostureEnds(reader, s);  // "until steady" postures that ended early
  const FieldData walls = reader.readStaticField("wall", sim::field::kPosition);
  if (walls.rows != s.world->walls.size())
    throw IoError(
        h5.string(), "/static/wall/position",
        "the run has " + std::to_string(walls.rows) +
            " wall particles, the re-assembled "
            "scenario " +
            std::to_string(s.world->walls.size()),
        "rebuild the report with the toolkit version that ran it (" + info.toolkitVersion + ")");

  // A mixed schedule's postures at equilibrium are solved again (deterministic, seconds): their
  // frames come before the simulated ones.
  const std::size_t leading = equilibriaBeforeSimulation(s);
  const SolvedEquilibria equilibria =
      leading > 0 ? solveEquilibriumPostures(protocol, s, leading, {}, {}) : SolvedEquilibria{};
  RunResults r;
  r.frames = equilibria.frames;
  measureRunFrames(reader, s, r);
  if (reader.frames().empty())
    throw IoError(h5.string(), "/frames", "the run has no complete frame", "run it again");
  const FrameInfo& lastFrame = reader.frames().back();
  if (lastFrame.step > 0)
    r.meanTimeStep = (lastFrame.time - equilibria.end) / static_cast<double>(lastFrame.step);
  const SeriesData stages = reader.readSeries("stage_seconds");
  for (std::size_t c = 1; c < stages.columns.size(); ++c)
    r.timers.push_back(
        {stages.columns[c], stages.values[(stages.rows - 1) * stages.columns.size() + c], 0});
  const SeriesData calls = reader.readSeries("stage_calls");
  for (std::size_t c = 1; c < calls.columns.size() && c - 1 < r.timers.size(); ++c)
    r.timers[c - 1].calls =
        static_cast<long>(calls.values[(calls.rows - 1) * calls.columns.size() + c]);
  const std::vector<std::string> series = reader.seriesNames();
  if (std::find(series.begin(), series.end(), "pressure_solve") != series.end()) {
    const SeriesData solve = reader.readSeries("pressure_solve");
    const std::size_t width = solve.columns.size();
    if (solve.rows > 0 && width > 1)
      r.pressureSolve = PressureSolveTotals::fromRow(std::vector<double>(
          solve.values.begin() + static_cast<std::ptrdiff_t>((solve.rows - 1) * width + 1),
          solve.values.begin() + static_cast<std::ptrdiff_t>(solve.rows * width)));
  }
  r.decisions = sim::assemblePipeline(*s.world, s.pipelineOptions).decisions();
  ReportInput in = makeRunReportInput(protocol, s, r);
  if (leading > 0) addLeadingEquilibria(equilibria, in);
  const double scheduled = s.totalDuration();  // [s]
  if (!ranWholeSchedule(reader, s.schedule.size(), lastFrame.time, scheduled)) {
    in.incomplete = true;
    in.scheduledDuration = scheduled;
  }
  writeReport(in, folder);
}

}  // namespace protocols
