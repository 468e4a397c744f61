#include "protocols/format/describe_protocol.h"

#include <algorithm>

#include <fmt/format.h>

#include "protocols/format/stage_names.h"
#include "protocols/format/units.h"

namespace protocols {

namespace {

class Lines {
 public:
  // `key = text` with a note saying where the value came from.
  void add(const std::string& key, const std::string& text, const SourceLocation& where) {
    std::string line = key + " = " + text;
    line.resize(std::max<std::size_t>(line.size() + 2, 52), ' ');
    line += where.isInFile() ? "# line " + std::to_string(where.line) : std::string("# default");
    text_ += line + "\n";
  }
  void addPlain(const std::string& text) { text_ += text + "\n"; }
  template <class T>
  void add(const std::string& key, const std::optional<Located<T>>& v, Dimension d) {
    if (v) add(key, formatQuantity(v->value, d), v->where);
  }
  std::string take() { return std::move(text_); }

 private:
  std::string text_;
};

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

void addTissue(Lines& out, const std::string& prefix, const std::optional<TissueSpec>& tissue) {
  if (!tissue) return;
  out.add(prefix + ".material", quoted(tissue->material.value), tissue->material.where);
  out.add(prefix + ".youngs_modulus", tissue->youngsModulus, Dimension::kPressure);
  if (tissue->poissonRatio)
    out.add(prefix + ".poisson_ratio",
            formatQuantity(tissue->poissonRatio->value, Dimension::kFraction),
            tissue->poissonRatio->where);
  out.add(prefix + ".density", tissue->density, Dimension::kDensity);
  out.add(prefix + ".thickness", tissue->thickness, Dimension::kLength);
  out.add(prefix + ".mode", quoted(std::string(toString(tissue->mode.value))), tissue->mode.where);
  out.add(prefix + ".anchoring", quoted(std::string(toString(tissue->anchoring.value))),
          tissue->anchoring.where);
}

void addEye(Lines& out, const EyeSpec& e) {
  out.add("eye.kind", quoted(std::string(toString(e.kind.value))), e.kind.where);
  out.add("eye.side", quoted(std::string(toString(e.side.value))), e.side.where);
  out.add("eye.axial_length", e.axialLength, Dimension::kLength);
  out.add("eye.staphyloma_depth", e.staphylomaDepth, Dimension::kLength);
  out.add("eye.staphyloma_width", e.staphylomaWidth, Dimension::kLength);
  if (e.mesh) {
    out.add("eye.mesh", quoted(e.mesh->path.value.string()), e.mesh->path.where);
    out.add("eye.mesh_units",
            quoted(e.mesh->units.value) + " (" +
                formatQuantity(e.mesh->metresPerUnit, Dimension::kLength) + " per unit)",
            e.mesh->units.where);
  }
  for (std::size_t k = 0; k < e.breaks.size(); ++k) {
    const RetinalBreak& b = e.breaks[k];
    const std::string prefix = "eye.breaks[" + std::to_string(k + 1) + "]";
    out.add(prefix + ".name", quoted(b.name.value), b.name.where);
    out.add(prefix + ".clock_hour", formatIn(b.clockHour.value, ""), b.clockHour.where);
    out.add(prefix + (b.reference == DistanceReference::kLimbus ? ".posterior_to_limbus"
                                                                : ".posterior_to_ora"),
            formatQuantity(b.distance.value, Dimension::kLength), b.distance.where);
    out.add(prefix + ".diameter", formatQuantity(b.diameter.value, Dimension::kLength),
            b.diameter.where);
  }
  addTissue(out, "eye.sclera", e.sclera);
  addTissue(out, "eye.orbital_fat", e.orbitalFat);
}

void addTamponade(Lines& out, const TamponadeSpec& t) {
  out.add("tamponade.agent", quoted(t.agent.value), t.agent.where);
  out.add("tamponade.fill", formatQuantity(t.fill.value, Dimension::kFraction), t.fill.where);
  out.add("tamponade.density", t.density, Dimension::kDensity);
  if (t.viscosity) {
    const bool dynamic = t.viscosity->value.kind == ViscosityKind::kDynamic;
    out.add("tamponade.viscosity",
            formatQuantity(t.viscosity->value.value, dynamic ? Dimension::kDynamicViscosity
                                                             : Dimension::kKinematicViscosity) +
                (dynamic ? " (dynamic)" : " (kinematic)"),
            t.viscosity->where);
  }
  out.add("tamponade.interfacial_tension", t.interfacialTension, Dimension::kSurfaceTension);
  if (t.contactAngle)
    out.add("tamponade.contact_angle",
            formatQuantity(t.contactAngle->value, Dimension::kAngle) + " (" +
                formatIn(t.contactAngle->value, "deg") + ", through the aqueous)",
            t.contactAngle->where);
  if (!t.isCustom())
    out.addPlain("# properties not given above come from the material library entry '" +
                 t.agent.value + "'");
}

// The schedule's settings, each posture, and a line with the postures' count and total time.
void addSchedule(Lines& out, const ScheduleSpec& schedule) {
  out.add("schedule.gravity", formatQuantity(schedule.gravity.value, Dimension::kAcceleration),
          schedule.gravity.where);
  if (schedule.start.value != StartName::kFillPlane)
    out.add("schedule.start", quoted(std::string(toString(schedule.start.value))),
            schedule.start.where);
  bool anySteady = false;
  for (const Posture& posture : schedule.postures) anySteady = anySteady || posture.untilSteady;
  if (anySteady) {
    out.add("schedule.steady_window",
            formatQuantity(schedule.steadyWindow.value, Dimension::kDuration),
            schedule.steadyWindow.where);
    out.add("schedule.steady_coverage_change",
            formatQuantity(schedule.steadyCoverageChange.value, Dimension::kFraction),
            schedule.steadyCoverageChange.where);
  }
  double total = 0.0;  // [s]
  for (std::size_t k = 0; k < schedule.postures.size(); ++k) {
    const Posture& s = schedule.postures[k];
    const std::string prefix = "schedule.postures[" + std::to_string(k + 1) + "]";
    if (s.name.value == PostureName::kCustom) {
      const auto& g = s.gravityDirection.value;
      out.add(prefix + ".gravity_direction",
              fmt::format("[{}, {}, {}] (eye frame)", formatIn(g[0], ""), formatIn(g[1], ""),
                          formatIn(g[2], "")),
              s.gravityDirection.where);
    } else {
      out.add(prefix + ".name", quoted(std::string(toString(s.name.value))), s.name.where);
    }
    out.add(prefix + ".label", quoted(s.label.value), s.label.where);
    out.add(prefix + ".duration",
            s.untilSteady
                ? "until steady, at most " + formatQuantity(s.duration.value, Dimension::kDuration)
                : formatQuantity(s.duration.value, Dimension::kDuration),
            s.duration.where);
    total += s.duration.value;
  }
  out.addPlain("# schedule: " + std::to_string(schedule.postures.size()) +
               (schedule.postures.size() == 1 ? " posture" : " postures") + ", at most " +
               formatQuantity(total, Dimension::kDuration) + " (" + formatIn(total, "min") +
               ") simulated");
}

void addEffects(Lines& out, const EffectSwitches& effects) {
  const std::span<const std::string_view> names = effectSwitchNames();
  for (std::size_t k = 0; k < names.size(); ++k)
    out.add(fmt::format("effects.{}", names[k]),
            std::string(toString(effects.settings[k].value)) +
                (effects.settings[k].value == EffectSetting::kAuto ? " (inferred from the scene)"
                                                                   : " (forced)"),
            effects.settings[k].where);
}

void addAccuracy(Lines& out, const AccuracySpec& a) {
  out.add("accuracy.preset", quoted(std::string(toString(a.preset.value))), a.preset.where);
  out.add("accuracy.particle_spacing", formatQuantity(a.particleSpacing.value, Dimension::kLength),
          a.particleSpacing.where);
  out.add("accuracy.solver_tolerance",
          formatQuantity(a.solverTolerance.value, Dimension::kFraction), a.solverTolerance.where);
  out.add("accuracy.min_time_step", formatQuantity(a.minTimeStep.value, Dimension::kDuration),
          a.minTimeStep.where);
  out.add("accuracy.max_time_step", formatQuantity(a.maxTimeStep.value, Dimension::kDuration),
          a.maxTimeStep.where);
  out.add("accuracy.surface_stress", quoted(std::string(toString(a.surfaceStress.value))),
          a.surfaceStress.where);
  out.add("accuracy.wall_model", quoted(std::string(toString(a.wallModel.value))),
          a.wallModel.where);
}

void addOutputs(Lines& out, const OutputsSpec& o) {
  out.add("outputs.folder", quoted(o.folder.value), o.folder.where);
  out.add("outputs.frame_interval", formatQuantity(o.frameInterval.value, Dimension::kDuration),
          o.frameInterval.where);
  std::string fields;
  for (const auto& f : o.fields) fields += (fields.empty() ? "" : ", ") + quoted(f.value);
  out.add("outputs.fields", "[" + fields + "]",
          o.fields.empty() ? SourceLocation{} : o.fields.front().where);
  out.add("outputs.report", o.report.value ? "true" : "false", o.report.where);
}

}  // namespace

std::string describeProtocol(const Protocol& p) {
  Lines out;
  out.addPlain("# " + p.file.string() + ": valid, format version " +
               std::to_string(p.formatVersion.value) + "; values in SI units");
  if (p.title) out.add("title", quoted(p.title->value), p.title->where);
  out.add("solver", quoted(p.solver.value), p.solver.where);
  addEye(out, p.eye);
  addTamponade(out, p.tamponade);
  addSchedule(out, p.schedule);
  addEffects(out, p.effects);
  addAccuracy(out, p.accuracy);
  addOutputs(out, p.outputs);
  return out.take();
}

}  // namespace protocols
