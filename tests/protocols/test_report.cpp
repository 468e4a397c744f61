// The coverage report: report.html and its SVG are well-formed XML and print the run's numbers;
// coverage.csv and summary.json hold the same numbers.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include <nlohmann/json.hpp>

#include "protocols/report/render_fundus_map.h"
#include "protocols/report/report_format.h"
#include "protocols/report/write_report.h"
#include "tests/support/scratch_directory.h"
#include "xml_checker.h"

using namespace protocols;
using protocols_test::checkXml;

namespace {

// A constructed run: a sphere of wall particles (Fibonacci points), oil above a plane that
// rises over three frames, one break at the top (covered) and one at the bottom (never).
ReportInput constructedRun() {
  constexpr double kR = 0.011;  // [m]
  ReportInput in;
  in.title = "Test eye <OD> & 90 % fill";
  in.eyeSide = "OD";
  in.scenario = {"Emmetropic right eye, silicone oil 1000 cSt, 90 % fill.",
                 "Face-down for 2 s, then upright for 2 s."};
  in.postures = {{"face-down", 0.0, 2.0}, {"upright", 2.0, 4.0}};
  const int n = 600;
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / n, r = std::sqrt(1 - z * z);
    const double phi = k * std::numbers::pi * (3.0 - std::sqrt(5.0));
    in.wallPositions.push_back(kR * sim::Vec3(r * std::cos(phi), z, r * std::sin(phi)));
  }
  in.wallRegions.assign(n, anatomy::kRetina);
  RetinaMap map;
  map.areas.assign(n, 4 * std::numbers::pi * kR * kR / n);
  map.regions = in.wallRegions;
  map.breakNames = {"superior tear", "inferior hole"};
  map.breakWalls = {{0, 1, 2}, {static_cast<std::size_t>(n - 1)}};
  for (double t : {0.0, 2.0, 4.0}) {
    WallOilFractions f;
    const double level = kR * (0.2 - 0.1 * t);  // [m] interface height y; oil spreads downward
    for (const auto& p : in.wallPositions) {
      const bool oil = p.y() >= level;
      f.oilFraction.push_back(oil ? 1.0 : 0.0);
      f.wetting.push_back(oil ? WallWetting::kOil : WallWetting::kAqueous);
    }
    in.frames.push_back(measureFrameCoverage(map, f, t));
    in.wallOilFraction = f.oilFraction;
    in.wallWetting = f.wetting;
  }
  in.mapTime = 4.0;
  in.summary = summarizeSchedule(in.frames);
  for (std::size_t b = 0; b < 2; ++b) {
    ReportBreak rb;
    rb.name = map.breakNames[b];
    rb.where = b == 0 ? "12 o'clock, 8 mm from the limbus" : "6 o'clock, 2 mm from the ora";
    const sim::Vec3 centre = in.wallPositions[map.breakWalls[b].front()];
    for (int k = 0; k < 12; ++k)
      rb.outline.push_back(
          (centre + 1e-3 * sim::Vec3(std::cos(k * 0.52), 0, std::sin(k * 0.52))).normalized() * kR);
    in.breaks.push_back(rb);
  }
  ReportOutline ora{"ora serrata", {}, true};
  for (int k = 0; k < 36; ++k)
    ora.points.push_back(kR * sim::Vec3(0.8 * std::cos(k * std::numbers::pi / 18),
                                        0.8 * std::sin(k * std::numbers::pi / 18), 0.6));
  in.outlines.push_back(ora);
  in.stages = {{"dfsph", true, "incompressible solver chosen by the protocol", 12.5, 100},
               {"interfacial_tension", false, "not needed: one fluid", 0.0, 0}};
  in.accuracy = {{"particle spacing", "0.8 mm", "draft preset"}};
  return in;
}

std::vector<std::string> svgBlocks(const std::string& html) {
  std::vector<std::string> out;
  for (std::size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1))
    out.push_back(html.substr(at, html.find("</svg>", at) + 6 - at));
  return out;
}

}  // namespace

TEST_CASE("the XML checker rejects malformed markup", "[unit][report]") {
  CHECK(checkXml("<a><b x=\"1\"/>t &amp; &#8212;</a>").empty());
  CHECK_THAT(checkXml("<a><b></a>"), Catch::Contains("</a> closes <b>"));
  CHECK_THAT(checkXml("<a>1 < 2</a>"), Catch::Contains("'<' not starting a tag"));
  CHECK_THAT(checkXml("<a>R&D</a>"), Catch::Contains("bad entity"));
  CHECK_THAT(checkXml("<a x=1></a>"), Catch::Contains("without a quoted value"));
  CHECK_THAT(checkXml("<a></a><b></b>"), Catch::Contains("second root"));
  CHECK_THAT(checkXml("<a>"), Catch::Contains("never closed"));
  CHECK_THAT(checkXml("<a x=\"1\" x=\"2\"></a>"), Catch::Contains("duplicate attribute"));
}

TEST_CASE("report.html and its SVG are well-formed and carry the run's numbers", "[unit][report]") {
  const ReportInput in = constructedRun();
  const std::string html = renderReportHtml(in);
  INFO(html.substr(0, 400));
  CHECK(checkXml(html).empty());
  const auto svgs = svgBlocks(html);
  REQUIRE(svgs.size() == 2);  // the coverage chart and the fundus map
  for (const auto& svg : svgs) CHECK(checkXml(svg) == "");
  // Self-contained: no scripts, no external resources.
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("http://") == html.find("http://www.w3.org"));  // only namespace URIs
  CHECK(html.find("https://") == std::string::npos);
  CHECK(html.find("src=") == std::string::npos);
  // The title is escaped, not injected.
  CHECK(html.find("Test eye &lt;OD&gt; &amp; 90 % fill") != std::string::npos);
  // The run's numbers: mean and final coverage of every region, breaks' time covered.
  for (std::size_t r = 0; r < kReportedRegions.size(); ++r)
    CHECK(html.find(formatPercent(in.summary.regions[r])) != std::string::npos);
  CHECK(html.find(formatPercent(in.frames.back().retina().fraction)) != std::string::npos);
  // Break 0 covered at all three frames, break 1 never: 100 % and 0 % of the time.
  CHECK(in.summary.breakTimeCovered[0] == 1.0);
  CHECK(in.summary.breakTimeCovered[1] == 0.0);
  CHECK(html.find("Break superior tear was covered 100.0 % of the time.") != std::string::npos);
  CHECK(html.find("Break inferior hole was covered 0.0 % of the time.") != std::string::npos);
  CHECK(html.find("12 o&#39;clock, 8 mm from the limbus") != std::string::npos);
  // Postures and pipeline stages with their times.
  CHECK(svgs[0].find(">face-down<") != std::string::npos);
  CHECK(svgs[0].find(">upright<") != std::string::npos);
  CHECK(html.find("<td>dfsph</td><td>yes</td>") != std::string::npos);
  CHECK(html.find(">12.5<") != std::string::npos);
  CHECK(html.find("<td>particle spacing</td><td>0.8 mm</td>") != std::string::npos);
  // The map draws one dot per retinal wall particle (counted inside the wall group; the legend
  // has dots of its own).
  const std::string& map = svgs[1];
  const std::size_t g0 = map.find("<g id=\"wall\">"), g1 = map.find("</g>", g0);
  std::size_t dots = 0;
  for (std::size_t at = map.find("<circle", g0); at < g1; at = map.find("<circle", at + 1)) ++dots;
  CHECK(dots == in.wallPositions.size());
}

TEST_CASE("fundus projection is azimuthal equidistant about the posterior pole", "[unit][report]") {
  // Posterior pole at the centre; the equator (z = 0) at 90 deg; superior (+y) up; angles true.
  const auto pole = projectFundus({0, 0, -1});
  CHECK(std::hypot(pole[0], pole[1]) == Approx(0.0).margin(1e-12));
  const auto sup = projectFundus({0, 1, 0});
  CHECK(sup[0] == Approx(0.0).margin(1e-12));
  CHECK(sup[1] == Approx(90.0).epsilon(1e-12));
  const auto left = projectFundus({std::sin(0.5), 0, -std::cos(0.5)});  // 0.5 rad off the pole
  CHECK(left[0] == Approx(0.5 * 180 / std::numbers::pi).epsilon(1e-12));
}

TEST_CASE("summary.json stays valid JSON when a run has no averages yet", "[unit][report]") {
  // A run stopped before its first frame: its averages are not numbers. JSON has no NaN, so they
  // must read as null, and quotes, backslashes and control characters in names stay strings.
  ReportInput in = constructedRun();
  in.frames.clear();
  in.summary.duration = std::numeric_limits<double>::quiet_NaN();
  for (double& r : in.summary.regions) r = std::numeric_limits<double>::quiet_NaN();
  in.title = "eye \"A\"\\ \n\x01";
  nlohmann::json json;
  REQUIRE_NOTHROW(json = nlohmann::json::parse(renderSummaryJson(in)));
  CHECK(json.at("duration_s").is_null());
  CHECK(json.at("regions").at(0).at("mean_fraction").is_null());
  CHECK(json.at("title").get<std::string>() == in.title);
  CHECK(json.at("frames").get<int>() == 0);
}

TEST_CASE("coverage.csv and summary.json hold the frames and the averages", "[unit][report]") {
  const ReportInput in = constructedRun();
  const tamponade_test::ScratchDirectory scratch("tamponade_test_report");
  const std::filesystem::path& folder = scratch.path();
  writeReport(in, folder);
  for (const char* f : {"report.html", "coverage.csv", "summary.json"})
    CHECK(std::filesystem::file_size(folder / f) > 100);
  std::ifstream csv(folder / "coverage.csv");
  std::string header, line;
  std::getline(csv, header);
  CHECK(header.rfind("time_s,whole_retina,superior_quadrant", 0) == 0);
  CHECK(header.find("superior tear_fraction,superior tear_covered") != std::string::npos);
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    CHECK(std::count(line.begin(), line.end(), ',') ==
          std::count(header.begin(), header.end(), ','));
  }
  CHECK(rows == 3);
  const auto json = nlohmann::json::parse(renderSummaryJson(in));
  CHECK(json.at("regions").at(0).at("mean_fraction").get<double>() ==
        std::stod(formatNumber(in.summary.regions[0], 6)));
  CHECK(json.at("breaks").at(0).at("time_covered").get<double>() == 1.0);
  CHECK(json.at("breaks").at(0).at("covered_at_end").get<bool>());
  CHECK(json.at("title").get<std::string>() == "Test eye <OD> & 90 % fill");
  // Bad folder: IoError naming the file.
  CHECK_THROWS_WITH(writeReport(in, folder / "missing"), Catch::Contains("missing/report.html"));
}
