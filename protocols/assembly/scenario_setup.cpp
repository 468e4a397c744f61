#include "protocols/assembly/scenario_setup.h"

#include "anatomy/posture.h"
#include "protocols/report/report_format.h"
#include "protocols/scenario/scenario_error.h"

namespace protocols {

namespace {

const AccuracyPresetValues& draftPreset() {
  return kAccuracyPresets[static_cast<std::size_t>(AccuracyPreset::kDraft)];
}

// Coarser than the draft preset the coverage is a trial figure: measured on tiny.toml
// (docs/accuracy.md, "Spacing against tolerance"), 1.2 mm read the whole-retina
// coverage 3.5 points above 0.6 mm and 0.8 mm 0.4 points.
std::string coarseSpacingNote(double spacing) {
  const std::string draft = formatNumber(draftPreset().particleSpacing * 1e3, 3);
  return "particle spacing " + formatNumber(spacing * 1e3, 3) +
         " mm is coarser than the draft preset's " + draft +
         " mm: a trial run, not a figure to publish (tiny.toml: 1.2 mm reads the coverage 3.5 "
         "points above 0.6 mm; docs/accuracy.md)";
}

sim::Vec3 gravityOf(const Posture& posture, double magnitude) {
  if (posture.name.value == PostureName::kCustom) {
    const auto& g = posture.gravityDirection.value;
    return magnitude * sim::Vec3(g[0], g[1], g[2]).normalized();
  }
  return magnitude * anatomy::gravityDirection(anatomy::parsePosture(toString(posture.name.value)));
}

AccuracySettings accuracyOf(const Protocol& p, const ScenarioOptions& options) {
  const AccuracySpec& a = p.accuracy;
  AccuracySettings s;
  if (options.accuracy) {
    const AccuracyPresetValues& v = kAccuracyPresets[static_cast<std::size_t>(*options.accuracy)];
    s = {std::string(v.name), v.particleSpacing, v.solverTolerance,
         v.minTimeStep,       v.maxTimeStep,     {}};
  } else {
    s = {std::string(toString(a.preset.value)),
         a.particleSpacing.value,
         a.solverTolerance.value,
         a.minTimeStep.value,
         a.maxTimeStep.value,
         {}};
  }
  s.minTimeStepWhere = a.minTimeStep.where.isInFile() ? a.minTimeStep.where : spacingSource(p);
  return s;
}

}  // namespace

void setUpScenario(const Protocol& p, const ScenarioOptions& options, Scenario& s) {
  s.title = p.title ? p.title->value : p.file.filename().string();
  s.accuracy = accuracyOf(p, options);
  const double d = s.accuracy.particleSpacing;  // [m]
  if (d > 1.001 * draftPreset().particleSpacing) s.notes.push_back(coarseSpacingNote(d));
  for (const Posture& posture : p.schedule.postures)
    s.schedule.push_back({posture.label.value,
                          gravityOf(posture, p.schedule.gravity.value),
                          posture.duration.value,
                          posture.untilSteady,
                          {},
                          posture.equilibrium});
  if (s.schedule.empty())
    failAt(p.file.empty() ? SourceLocation{} : SourceLocation{p.file.string(), 0, 0},
           "the schedule has no postures", "add at least one [[schedule.postures]]");
}

}  // namespace protocols
