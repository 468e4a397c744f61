#include "protocols/run/scenario_report_input.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "protocols/assembly/pipeline_options.h"
#include "protocols/report/report_format.h"

namespace protocols {
namespace {

// What accuracy.solver_tolerance does under the scene's solver: the implicit solves stop at it
// (scenario.cpp), the explicit solvers have no solve to stop.
std::string solverToleranceMeaning(const std::string& solver) {
  if (isImplicitSolver(solver))
    return "mean relative density error at which the " + solver +
           " pressure solve stops (or at its 100-iteration cap; what it reached: 'pressure solve "
           "(achieved)')";
  return "not used: " + solver +
         " is explicit; its speed of sound bounds the density error near 1 %";
}

constexpr int kOutlinePoints = 96;  // points per closed outline on the map

// Ring of wall points at chord distance `radius` [m] from the wall point at theta = 0 (the
// fovea lies on the axis, eye.h), by bisection on theta per meridian (chord grows with theta).
std::vector<sim::Vec3> ringAroundPole(const anatomy::Eye& eye, double radius) {
  const anatomy::CavityShape& shape = eye.cavity();
  std::vector<sim::Vec3> out;
  for (int k = 0; k < kOutlinePoints; ++k) {
    const double m = 2.0 * std::numbers::pi * k / kOutlinePoints;
    const sim::Vec3 centre = shape.wallPoint({0.0, m});
    double lo = 0.0, hi = shape.rimTheta();
    for (int it = 0; it < 50; ++it) {
      const double mid = 0.5 * (lo + hi);
      ((shape.wallPoint({mid, m}) - centre).norm() < radius ? lo : hi) = mid;
    }
    out.push_back(shape.wallPoint({lo, m}));
  }
  return out;
}

std::string millimetres(double metres) { return formatNumber(metres * 1e3, 3) + " mm"; }

std::string tissueCounts(const Scenario& s) {
  std::string text;
  for (const TissueBody& t : s.tissues)
    if (t.count > 0) text += ", " + std::to_string(t.count) + " " + t.name;
  return text;
}

// "0.0123 %": three significant digits (density errors span 1e-5 to 1e-2).
std::string percentOf(double fraction) { return formatNumber(100.0 * fraction, 3) + " %"; }

}  // namespace

std::string pressureSolveValue(const ReportPressureSolve& solve) {
  return "mean density error " + percentOf(solve.meanDensityError) + ", " +
         formatNumber(solve.meanIterations, 3) + " iterations per step";
}

std::string pressureSolveNote(const ReportPressureSolve& solve) {
  std::string note =
      "over " + std::to_string(solve.steps) + " steps, weighted by their time steps; ";
  if (solve.capFraction > 0.0)
    note += percentOf(solve.capFraction) + " of the steps stopped at the " +
            std::to_string(solve.iterationCap) + "-iteration cap above the tolerance of " +
            percentOf(solve.tolerance);
  else
    note += "every step reached the tolerance of " + percentOf(solve.tolerance);
  return note + "; worst step " + percentOf(solve.maxStepDensityError) +
         " (the oil is about 3 % lighter than the aqueous: errors well below that keep its "
         "buoyancy)";
}

namespace {

std::string eyeSentence(const Protocol& p, const Scenario& s) {
  std::ostringstream eye;
  eye << "Eye: " << (p.eye.side.value == EyeSide::kOd ? "right (OD)" : "left (OS)") << ", "
      << toString(p.eye.kind.value) << " vitreous cavity of "
      << formatNumber(s.cavityVolume * 1e6, 3) << " mL";
  if (p.eye.axialLength) eye << ", axial length " << millimetres(p.eye.axialLength->value);
  if (p.eye.staphylomaDepth)
    eye << ", staphyloma " << millimetres(p.eye.staphylomaDepth->value) << " deep";
  eye << ". " << p.eye.breaks.size() << (p.eye.breaks.size() == 1 ? " break." : " breaks.");
  return eye.str();
}

std::string tamponadeSentence(const Protocol& p, const Scenario& s) {
  std::ostringstream fill;
  const FluidPhase& oil = s.phases[1];
  fill << "Tamponade: " << oil.material << " (" << formatNumber(oil.density, 4) << " kg/m\u00b3, "
       << formatNumber(oil.dynamicViscosity, 3) << " Pa s), "
       << formatPercent(p.tamponade.fill.value) << " fill; the rest is aqueous ("
       << formatNumber(s.phases[0].density, 4) << " kg/m\u00b3). The "
       << (oil.density < s.phases[0].density ? "oil floats (lighter than aqueous)."
                                             : "tamponade sinks (heavier than aqueous).");
  fill << " Kinematic viscosity " << formatNumber(oil.dynamicViscosity / oil.density * 1e6, 4)
       << " cSt (aqueous "
       << formatNumber(s.phases[0].dynamicViscosity / s.phases[0].density * 1e6, 3) << " cSt).";
  if (oil.interfacialTension)
    fill << " Interfacial tension against aqueous "
         << formatNumber(*oil.interfacialTension * 1e3, 3) << " mN/m.";
  if (oil.contactAngleThroughAqueous)
    fill << " Contact angle on the retina " << formatNumber(*oil.contactAngleThroughAqueous, 3)
         << "\u00b0 through the aqueous ("
         << formatNumber(180.0 - *oil.contactAngleThroughAqueous, 3)
         << "\u00b0 through the tamponade).";
  return fill.str();
}

// Whether posture `k` is simulated right after a posture at its equilibrium (a mixed schedule):
// it starts from that equilibrium (protocols/equilibrium/start_from_equilibrium.h).
bool startsFromEquilibrium(const Scenario& s, std::size_t k) {
  return k > 0 && !s.schedule[k].equilibrium && s.schedule[k - 1].equilibrium;
}

std::string scheduleSentence(const Scenario& s) {
  std::ostringstream schedule;
  schedule << "Posture schedule:";
  for (std::size_t k = 0; k < s.schedule.size(); ++k) {
    const ScheduledPosture& posture = s.schedule[k];
    const std::string seconds = formatNumber(posture.duration, 4) + " s";
    schedule << (k == 0 ? " " : ", then ") << posture.label;
    if (posture.equilibrium)
      schedule << " at its static equilibrium";
    else if (!posture.untilSteady)
      schedule << " for " << seconds;
    else if (!posture.endedSteady)
      schedule << " until steady, at most " << seconds;
    else if (*posture.endedSteady)
      schedule << " until steady (reached after " << seconds << ")";
    else
      schedule << " until steady (not reached; stopped at the maximum, " << seconds << ")";
    if (startsFromEquilibrium(s, k))
      schedule << ", simulated from the " << s.schedule[k - 1].label << " equilibrium";
  }
  schedule << ".";
  return schedule.str();
}

// The scenario in words, one paragraph each.
std::vector<std::string> scenarioParagraphs(const Protocol& p, const Scenario& s) {
  std::vector<std::string> paragraphs{eyeSentence(p, s), tamponadeSentence(p, s),
                                      scheduleSentence(s)};
  if (p.description) paragraphs.push_back(p.description->value);
  for (const auto& note : s.notes) paragraphs.push_back("Note: " + note + ".");
  return paragraphs;
}

// A break: where it is in words, and a ring of its radius around its centre in the tangent
// plane, projected to the wall.
ReportBreak reportBreak(const anatomy::RetinalBreak& br, const anatomy::CavityShape& shape) {
  ReportBreak rb;
  rb.name = br.name();
  std::ostringstream where;
  const anatomy::ClinicalPosition& pos = br.spec().position;
  where << formatNumber(pos.clockHour, 3) << " o'clock, " << millimetres(pos.distance)
        << " posterior to the "
        << (pos.from == anatomy::DistanceReference::kLimbus ? "limbus" : "ora serrata") << ", "
        << millimetres(br.spec().diameter) << " across";
  rb.where = where.str();
  const sim::Vec3 c = br.centre().position, n = br.centre().normal;
  const sim::Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  const double r = 0.5 * br.spec().diameter;
  for (int k = 0; k < 32; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 32;
    const sim::Vec3 q = c + r * (std::cos(a) * t1 + std::sin(a) * t2);
    rb.outline.push_back(shape.wallPoint(shape.closestWallCoordinate(q)));
  }
  return rb;
}

// The fundus map's landmarks: ora serrata, equator, posterior pole and macula.
std::vector<ReportOutline> landmarkOutlines(const anatomy::Eye& eye) {
  const anatomy::CavityShape& shape = eye.cavity();
  ReportOutline ora{"ora serrata", {}, true}, equator{"equator", {}, true};
  for (int k = 0; k < kOutlinePoints; ++k) {
    const double m = 2.0 * std::numbers::pi * k / kOutlinePoints;
    ora.points.push_back(shape.wallPoint(eye.wallCoordinateAt(m, eye.landmarks().oraFromLimbus)));
    equator.points.push_back(shape.wallPoint({0.5 * std::numbers::pi, m}));
  }
  return {std::move(ora),
          std::move(equator),
          {"posterior pole", ringAroundPole(eye, eye.landmarks().posteriorPoleRadius), true},
          {"macula", ringAroundPole(eye, 0.5 * eye.landmarks().maculaDiameter), true}};
}

std::vector<ReportSetting> accuracyRows(const Scenario& s) {
  const AccuracySettings& a = s.accuracy;
  return {
      {"preset", a.preset, "draft / standard / fine (docs/accuracy.md)"},
      {"particle spacing", millimetres(a.particleSpacing),
       "coverage boundaries are resolved to about one spacing; the flat-interface test bounds "
       "the whole-retina coverage error by |z0| d / R^2 + 1 % (tests/protocols/test_coverage.cpp)"},
      {"kernel support radius", millimetres(2.0 * a.particleSpacing), "h = 2 d, cubic spline"},
      {"solver tolerance", formatNumber(a.solverTolerance, 3),
       solverToleranceMeaning(s.pipelineOptions.solver)},
      {"time step bounds",
       formatNumber(a.minTimeStep, 3) + " s to " + formatNumber(a.maxTimeStep, 3) + " s",
       "CFL 0.4 and the stages' limits choose the step inside these bounds"},
      {"cavity wall", s.layeredWalls ? "layered (3 lattice layers)" : "single layer",
       s.layeredWalls
           ? "the wall model the contact angle was validated on (accuracy.wall_model; "
             "docs/methods/interface.md, validation 5)"
           : "one Akinci layer: holds the contact angle less well (accuracy.wall_model)"},
      {"particles",
       std::to_string(s.phases[0].count) + " aqueous, " + std::to_string(s.phases[1].count) +
           " tamponade, " + std::to_string(s.world->walls.size()) + " wall" + tissueCounts(s),
       "fluid started at " + formatNumber(s.fillCompression, 3) +
           " x rest density so that it fills the cavity (protocols/scenario/scenario.h MassRule)"},
  };
}

}  // namespace

ReportInput makeReportInput(const Protocol& p, const Scenario& s) {
  ReportInput in;
  in.title = s.title;
  in.eyeSide = std::string(toString(p.eye.side.value));
  in.scenario = scenarioParagraphs(p, s);
  double t = 0.0;
  for (std::size_t k = 0; k < s.schedule.size(); ++k) {
    const ScheduledPosture& posture = s.schedule[k];
    in.postures.push_back({posture.label, t, t + posture.duration,
                           posture.untilSteady ? posture.endedSteady : std::nullopt});
    if (startsFromEquilibrium(s, k))
      in.postures.back().startsFromEquilibriumOf = s.schedule[k - 1].label;
    t += posture.duration;
  }
  for (const anatomy::RetinalBreak& br : s.breaks)
    in.breaks.push_back(reportBreak(br, s.eye->cavity()));
  if (s.eye) in.outlines = landmarkOutlines(*s.eye);
  in.accuracy = accuracyRows(s);
  return in;
}

}  // namespace protocols
