#include "protocols/report/write_report.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "protocols/io/io_error.h"
#include "protocols/report/render_coverage_chart.h"
#include "protocols/report/render_fundus_map.h"
#include "protocols/report/render_oil_edge.h"
#include "protocols/report/report_format.h"

namespace protocols {
namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:60em;margin:2em auto;color:#222;line-height:1.4}"
    "table{border-collapse:collapse;margin:1em 0}"
    "th,td{border:1px solid #bbb;padding:0.25em 0.6em;text-align:left}"
    "td.n{text-align:right}th{background:#eee}"
    ".yes{color:#00804a;font-weight:bold}.no{color:#c00000;font-weight:bold}"
    "h1{font-size:1.6em}h2{font-size:1.25em;margin-top:1.6em}";

// Minimum of a series over the frames.
template <class F>
double minimumOver(const std::vector<FrameCoverage>& frames, F value) {
  double m = 1.0;
  for (const auto& f : frames) m = std::min(m, value(f));
  return frames.empty() ? 0.0 : m;
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out)
    throw IoError(path.string(), "", "cannot open the report file for writing",
                  "check that the output folder exists and is writable");
  out << text;
  out.close();
  if (!out)
    throw IoError(path.string(), "", "writing the report file failed", "check the free disk space");
}

// Equilibrium runs: each posture's coverage per region and break, then its fundus map.
void renderEquilibria(const ReportInput& in, std::ostringstream& s) {
  s << "<h2>Coverage at each posture's equilibrium</h2>\n<table>\n<tr><th>region</th>";
  for (const auto& e : in.equilibria) s << "<th>" << escapeXml(e.label) << "</th>";
  s << "</tr>\n";
  for (std::size_t r = 0; r < kReportedRegions.size(); ++r) {
    s << "<tr><td>" << kReportedRegions[r].name << "</td>";
    for (const auto& e : in.equilibria)
      s << "<td class=\"n\">" << formatPercent(e.coverage.regions[r].fraction) << "</td>";
    s << "</tr>\n";
  }
  for (std::size_t b = 0; b < in.breaks.size(); ++b) {
    s << "<tr><td>break " << escapeXml(in.breaks[b].name) << "</td>";
    for (const auto& e : in.equilibria) {
      const bool covered = b < e.coverage.breaks.size() && e.coverage.breaks[b].covered;
      s << "<td class=\"" << (covered ? "yes\">covered" : "no\">open") << " ("
        << formatPercent(b < e.coverage.breaks.size() ? e.coverage.breaks[b].area.fraction : 0.0)
        << ")</td>";
    }
    s << "</tr>\n";
  }
  s << "</table>\n<p>Each posture's static equilibrium: where the oil-aqueous interface comes to "
       "rest when the posture is held (docs/methods/equilibrium.md). A wall point counts as "
       "oil-covered when the equilibrium interface, extended to the wall at the contact angle, "
       "leaves it on the oil side; a break counts as covered when at least "
    << formatPercent(kBreakCoveredFraction) << " of its area is.</p>\n";
  s << renderOilEdgeTable(in);
  for (const auto& e : in.equilibria) {
    ReportInput map = in;
    map.wallOilFraction = e.wallOilFraction;
    map.wallWetting = e.wallWetting;
    s << "<h2>Fundus map: " << escapeXml(e.label) << "</h2>\n" << renderFundusMap(map);
  }
  s << "<p>The retina unrolled around the posterior pole (azimuthal equidistant projection: the "
       "distance from the centre is the angle from the posterior pole, seen from the front, "
       "superior up); dashed lines separate the quadrants.</p>\n";
}

// A posture that stopped at its maximum before it settled, in the headline: its figures are a
// transient's, and how far that is from where the posture comes to rest.
void renderUnsteadyPosture(const ReportPosture& p, std::ostringstream& s) {
  s << "<p><strong>Not steady:</strong> the posture " << escapeXml(p.label)
    << " reached its maximum (" << formatNumber(p.end - p.start, 4)
    << " s) before it settled, so its figures are those of a transient.";
  if (p.retinaAtEnd && p.equilibriumRetina) {
    const double points = 100.0 * (*p.retinaAtEnd - *p.equilibriumRetina);
    s << " At its end oil covered " << formatPercent(*p.retinaAtEnd)
      << " of the retina; at the posture's static equilibrium it covers "
      << formatPercent(*p.equilibriumRetina) << ", " << formatNumber(std::abs(points), 3)
      << " points " << (points >= 0.0 ? "less" : "more")
      << ". <code>duration = \"equilibrium\"</code> gives the resting state in seconds.";
  }
  s << "</p>\n";
}

// The headline of a run that simulated: the schedule's means and the end; a mixed schedule says
// how its postures at equilibrium enter the means.
void renderSimulatedHeadline(const ReportInput& in, std::ostringstream& s) {
  const std::size_t atEquilibrium = in.equilibria.size();
  s << "<p>Over "
    << (in.incomplete ? "the part of the schedule simulated (" : "the whole schedule (");
  if (atEquilibrium > 0 && atEquilibrium < in.postures.size())
    s << atEquilibrium
      << (atEquilibrium == 1 ? " posture at equilibrium as one nominal second"
                             : " postures at equilibrium, one nominal second each")
      << ", then " << formatNumber(in.frames.back().time - in.postures[atEquilibrium].start, 4)
      << " s simulated";
  else
    s << formatNumber(in.summary.duration, 4) << " s simulated";
  s << ") oil covered on average <strong>" << formatPercent(in.summary.regions[0])
    << "</strong> of the retina; at the end " << formatPercent(in.frames.back().retina().fraction)
    << ".";
  for (std::size_t b = 0; b < in.breaks.size() && b < in.summary.breakTimeCovered.size(); ++b)
    s << " Break " << escapeXml(in.breaks[b].name) << " was covered "
      << formatPercent(in.summary.breakTimeCovered[b]) << " of the time.";
  s << "</p>\n";
}

// The document head, the title, and the notes above the scenario (an incomplete run, unsteady
// postures).
void renderHead(const ReportInput& in, std::ostringstream& s) {
  s << "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n"
    << "<meta charset=\"utf-8\"/>\n<title>" << escapeXml(in.title) << "</title>\n<style>" << kStyle
    << "</style>\n</head>\n<body>\n";
  s << "<h1>" << escapeXml(in.title) << (in.incomplete ? " (incomplete run)" : "") << "</h1>\n";
  if (in.incomplete)
    s << "<p><strong>Incomplete run:</strong> it stopped at "
      << formatNumber(in.summary.duration, 4) << " s of the schedule's "
      << formatNumber(in.scheduledDuration, 4)
      << " s, so every figure below covers only the part simulated. Continue it with "
         "<code>tamponade run --resume</code> on its folder for the whole schedule.</p>\n";
  for (const ReportPosture& posture : in.postures)
    if (posture.endedSteady && !*posture.endedSteady) renderUnsteadyPosture(posture, s);
}

// The scenario's lines and the headline: the mean coverage over the schedule.
void renderScenario(const ReportInput& in, std::ostringstream& s) {
  s << "<h2>Scenario</h2>\n";
  for (const auto& p : in.scenario) s << "<p>" << escapeXml(p) << "</p>\n";
  const bool equilibrium = isEquilibriumReport(in);
  const bool mixed = !equilibrium && !in.equilibria.empty();
  if (equilibrium) {
    s << "<p>Over the schedule's " << in.equilibria.size()
      << " postures at equilibrium (each weighted alike; the transients between postures are "
         "neglected) oil covered on average <strong>"
      << formatPercent(in.summary.regions[0]) << "</strong> of the retina; in the last posture "
      << formatPercent(in.frames.back().retina().fraction) << ".</p>\n";
    renderEquilibria(in, s);
  } else if (!in.frames.empty()) {
    renderSimulatedHeadline(in, s);
    if (mixed) renderEquilibria(in, s);
  }
}

void renderCoverageOverTime(const ReportInput& in, std::ostringstream& s) {
  const bool equilibrium = isEquilibriumReport(in);
  const bool mixed = !equilibrium && !in.equilibria.empty();
  s << "<h2>Oil coverage over time</h2>\n" << renderCoverageChart(in);
  if (equilibrium)
    s << "<p>Shaded bands are the postures of the schedule, each shown over one nominal second "
         "at its equilibrium.</p>\n";
  else
    s << "<p>Shaded bands are the postures of the schedule"
      << (mixed ? "; each posture at its equilibrium is shown over one nominal second" : "")
      << ". A wall point counts as oil-covered "
         "when the SPH-weighted oil fraction of the fluid next to it is at least "
      << formatPercent(kOilCoveredThreshold) << "; a break counts as covered when at least "
      << formatPercent(kBreakCoveredFraction) << " of its area is oil-covered.</p>\n";
}

void renderRegionTable(const ReportInput& in, std::ostringstream& s) {
  s << "<h2>Coverage by region</h2>\n<table>\n<tr><th>region</th><th>area [mm&#178;]</th>"
       "<th>mean over time</th><th>minimum</th><th>at the end</th><th>dry at the end</th></tr>\n";
  for (std::size_t r = 0; r < kReportedRegions.size(); ++r) {
    const AreaCoverage last = in.frames.empty() ? AreaCoverage{} : in.frames.back().regions[r];
    s << "<tr><td>" << kReportedRegions[r].name << "</td><td class=\"n\">"
      << formatNumber(last.area * 1e6, 4) << "</td><td class=\"n\">"
      << formatPercent(in.summary.regions[r]) << "</td><td class=\"n\">"
      << formatPercent(
             minimumOver(in.frames, [r](const FrameCoverage& f) { return f.regions[r].fraction; }))
      << "</td><td class=\"n\">" << formatPercent(last.fraction) << "</td><td class=\"n\">"
      << formatPercent(last.area > 0 ? last.dryArea / last.area : 0.0) << "</td></tr>\n";
  }
  s << "</table>\n";
}

void renderTissue(const ReportInput& in, std::ostringstream& s) {
  s << "<h2>Tissue</h2>\n";
  if (in.tissue.empty()) {
    s << "<p>no tissue in the protocol: rigid cavity wall</p>\n";
  } else if (in.tissue.size() == 1) {
    s << "<p>" << escapeXml(in.tissue.front()) << "</p>\n";
  } else {
    s << "<ul>\n";
    for (const auto& line : in.tissue) s << "<li>" << escapeXml(line) << "</li>\n";
    s << "</ul>\n<p>Displacements from the rest state; the coverage above is measured on the "
         "retina where the tissue has carried it (protocols/tissue/tissue_particles.h).</p>\n";
  }
}

void renderBreakTable(const ReportInput& in, std::ostringstream& s) {
  s << "<h2>Retinal breaks</h2>\n";
  if (in.breaks.empty()) {
    s << "<p>The protocol has no retinal breaks.</p>\n";
  } else {
    s << "<table>\n<tr><th>break</th><th>position</th><th>mean area covered</th>"
         "<th>time covered</th><th>covered at the end</th></tr>\n";
    for (std::size_t b = 0; b < in.breaks.size(); ++b) {
      const bool coveredAtEnd = !in.frames.empty() && b < in.frames.back().breaks.size() &&
                                in.frames.back().breaks[b].covered;
      s << "<tr><td>" << escapeXml(in.breaks[b].name) << "</td><td>"
        << escapeXml(in.breaks[b].where) << "</td><td class=\"n\">"
        << formatPercent(b < in.summary.breakFraction.size() ? in.summary.breakFraction[b] : 0.0)
        << "</td><td class=\"n\">"
        << formatPercent(b < in.summary.breakTimeCovered.size() ? in.summary.breakTimeCovered[b]
                                                                : 0.0)
        << "</td><td class=\"" << (coveredAtEnd ? "yes\">yes" : "no\">no") << "</td></tr>\n";
    }
    s << "</table>\n";
  }
}

// A simulated run's map at its last frame (an equilibrium report draws its maps per posture).
void renderFundusSection(const ReportInput& in, std::ostringstream& s) {
  if (isEquilibriumReport(in)) return;
  ReportInput last = in;  // the map of the last frame, not of an equilibrium
  last.equilibria.clear();
  s << "<h2>Fundus map of oil coverage</h2>\n" << renderFundusMap(last);
  s << "<p>The retina unrolled around the posterior pole (azimuthal equidistant projection: "
       "the distance from the centre is the angle from the posterior pole, seen from the "
       "front, superior up). Dots are wall particles at t = "
    << formatNumber(in.mapTime, 4) << " s; dashed lines separate the quadrants.</p>\n";
}

void renderPipelineTable(const ReportInput& in, std::ostringstream& s) {
  if (!in.stages.empty())
    s << "<h2>Pipeline</h2>\n<table>\n<tr><th>stage</th><th>in use</th><th>why</th>"
         "<th>time [s]</th><th>calls</th></tr>\n";
  for (const auto& st : in.stages)
    s << "<tr><td>" << escapeXml(st.name) << "</td><td>" << (st.active ? "yes" : "no")
      << "</td><td>" << escapeXml(st.reason) << "</td><td class=\"n\">"
      << formatNumber(st.seconds, 4) << "</td><td class=\"n\">" << st.calls << "</td></tr>\n";
  if (!in.stages.empty()) s << "</table>\n";
}

void renderAccuracyTable(const ReportInput& in, std::ostringstream& s) {
  s << "<h2>Accuracy settings</h2>\n<table>\n<tr><th>setting</th><th>value</th>"
       "<th>estimated error / source</th></tr>\n";
  for (const auto& a : in.accuracy)
    s << "<tr><td>" << escapeXml(a.name) << "</td><td>" << escapeXml(a.value) << "</td><td>"
      << escapeXml(a.note) << "</td></tr>\n";
  s << "</table>\n";
}

}  // namespace

std::string renderReportHtml(const ReportInput& in) {
  std::ostringstream s;
  renderHead(in, s);
  renderScenario(in, s);
  renderCoverageOverTime(in, s);
  renderRegionTable(in, s);
  renderTissue(in, s);
  renderBreakTable(in, s);
  renderFundusSection(in, s);
  renderPipelineTable(in, s);
  renderAccuracyTable(in, s);
  s << "</body>\n</html>\n";
  return s.str();
}

std::string renderCoverageCsv(const ReportInput& in) {
  std::ostringstream s;
  s << "time_s";
  for (const auto& r : kReportedRegions) {
    std::string name(r.name);
    std::replace(name.begin(), name.end(), ' ', '_');
    name.erase(std::remove_if(name.begin(), name.end(),
                              [](char c) { return c == '(' || c == ')' || c == ','; }),
               name.end());
    s << "," << name;
  }
  for (const auto& b : in.breaks) {
    std::string name = b.name;
    std::replace(name.begin(), name.end(), ',', ';');
    s << "," << name << "_fraction," << name << "_covered";
  }
  s << "\n";
  for (const auto& f : in.frames) {
    s << formatNumber(f.time, 9);
    for (const auto& r : f.regions) s << "," << formatNumber(r.fraction, 6);
    for (const auto& b : f.breaks)
      s << "," << formatNumber(b.area.fraction, 6) << "," << (b.covered ? 1 : 0);
    s << "\n";
  }
  return s.str();
}

void writeReport(const ReportInput& input, const std::filesystem::path& folder) {
  writeFile(folder / "report.html", renderReportHtml(input));
  writeFile(folder / "coverage.csv", renderCoverageCsv(input));
  writeFile(folder / "summary.json", renderSummaryJson(input));
}

}  // namespace protocols
