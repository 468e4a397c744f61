// The oil edge by clock hour (protocols/coverage/oil_edge_by_clock_hour.h) against a known answer:
// in the emmetropic eye, oil above a horizontal plane y = y0 covers each upper meridian from the
// ora serrata to the point where the wall crosses that plane. That point is found here with the
// forward map (clinical position -> wall point, anatomy::Eye::wallPointAt), independently of the
// inverse map the function uses.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "anatomy/eye.h"
#include "anatomy/retinal_regions.h"
#include "anatomy/vitreous_cavity.h"
#include "protocols/coverage/oil_edge_by_clock_hour.h"
#include "protocols/report/render_oil_edge.h"

using namespace protocols;

namespace {

struct Samples {
  std::vector<sim::Vec3> positions;
  std::vector<double> oil;
  std::vector<anatomy::RegionSet> regions;
};

// Wall points every 0.02 h and 0.1 mm from the ora to the posterior pole, oil above y = y0.
Samples samplesAbovePlane(const anatomy::Eye& eye, double y0) {
  Samples s;
  for (double hour = 0.01; hour < 12.0; hour += 0.02) {
    for (double d = 0.05e-3;; d += 0.1e-3) {
      anatomy::WallPoint p;
      try {
        p = eye.wallPointAt({hour, d, anatomy::DistanceReference::kOraSerrata});
      } catch (const std::exception&) {
        break;  // past the posterior pole
      }
      s.positions.push_back(p.position);
      s.oil.push_back(p.position.y() > y0 ? 1.0 : 0.0);
      s.regions.push_back(anatomy::kRetina);
    }
  }
  return s;
}

// Distance posterior to the ora where the meridian of `hour` crosses y = y0 (bisection).
double crossing(const anatomy::Eye& eye, double hour, double y0, double length) {
  double lo = 0.0, hi = length - 1e-6;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    const double y =
        eye.wallPointAt({hour, mid, anatomy::DistanceReference::kOraSerrata}).position.y();
    (y > y0 ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

TEST_CASE("oil edge by clock hour: oil above a horizontal plane in the emmetropic eye",
          "[unit][coverage]") {
  const anatomy::Eye eye(anatomy::Laterality::kRight,
                         anatomy::CavityShape(anatomy::emmetropicGeometry({})));
  const double y0 = 4e-3;  // [m] the oil covers the wall above this height
  const Samples s = samplesAbovePlane(eye, y0);
  const std::vector<ClockHourOilEdge> edges =
      oilEdgeByClockHour(eye, s.positions, s.oil, s.regions);
  REQUIRE(edges.size() == 12);
  CHECK(edges[0].clockHour == 12);
  CHECK(edges[3].clockHour == 3);
  for (int hour : {11, 12, 1}) {
    const ClockHourOilEdge& e = edges[hour % 12];
    INFO("clock hour " << hour);
    REQUIRE(e.oil.size() == 1);
    CHECK(e.oil[0].from == 0.0);
    // The edge is placed to within one bin (kOilEdgeBin, 0.5 mm); the quarter-hour wedge moves
    // the crossing by less than 0.1 mm at these hours.
    CHECK(std::abs(e.oil[0].to - crossing(eye, hour, y0, e.meridianLength)) <= kOilEdgeBin);
    CHECK(describeOilStretches(e).rfind("ora to ", 0) == 0);
  }
  // Below the plane at every hour from 3 to 9: the horizontal meridians lie at y = 0 < y0.
  for (int hour = 3; hour <= 9; ++hour) {
    INFO("clock hour " << hour);
    CHECK(edges[hour].oil.empty());
    CHECK(describeOilStretches(edges[hour]) == "none");
  }
}

TEST_CASE("oil edge by clock hour: a retina all oil or all aqueous", "[unit][coverage]") {
  const anatomy::Eye eye(anatomy::Laterality::kLeft,
                         anatomy::CavityShape(anatomy::emmetropicGeometry({})));
  Samples s = samplesAbovePlane(eye, -1.0);  // every sample above y = -1 m: all oil
  for (const ClockHourOilEdge& e : oilEdgeByClockHour(eye, s.positions, s.oil, s.regions)) {
    REQUIRE(e.oil.size() == 1);
    CHECK(describeOilStretches(e) == "ora to pole");
  }
  for (double& f : s.oil) f = 0.0;
  for (const ClockHourOilEdge& e : oilEdgeByClockHour(eye, s.positions, s.oil, s.regions))
    CHECK(e.oil.empty());
  // Samples outside the retina (region set 0) are not read.
  for (double& f : s.oil) f = 1.0;
  for (auto& r : s.regions) r = 0;
  for (const ClockHourOilEdge& e : oilEdgeByClockHour(eye, s.positions, s.oil, s.regions))
    CHECK(e.oil.empty());
}
