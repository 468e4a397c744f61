// Benchmark (not a test) of validation 3, the contact angle: what a sessile droplet's
// angle is worth at each resolution, and what it costs. For each requested angle, each resolution
// R0 / d and each start (the requested cap, or the hemisphere so the contact line has to travel)
// it runs the sessile droplet of interface_sessile.h (INDSPH, 0.2 d jitter, R0 = 3 mm, sigma
// 0.04 N/m, no gravity unless --gravity) on a floor of three wall layers (the tests' wall) or of
// one Akinci layer (the eye wall next to elastic tissue, --walls single) or of elastic tissue
// (--walls tissue), and writes one row: the angle measured (window mean over the last fifth), at
// the end, its error, the tolerance (+-5 deg for 30-150, +-10 outside), particles, steps
// and wall time. The cap fit measures up to 150 deg; above, it cannot tell 165 from 180 and the
// footprint measure (capAngleOfFootprint) is used; the table names which.
//
// Files: DIR/contact_angle_bench.csv and DIR/contact_angle_bench.md, rewritten after every run,
// so an interrupted sweep keeps the rows it finished (the markdown says how many of how many).
//
// usage: sim_contact_angle_bench [--angles 60,120,150,165] [--resolutions 6,8] [--time 0.3]
//                                [--start cap|hemisphere|both] [--viscosity 0.005]
//                                [--walls layered|single|tissue|both|all] [--gravity G]
//                                [--droplet-density RHO] [--out DIR]
// With --gravity the droplet (heavier than the aqueous) is pressed onto the floor and the angle
// is the Young-Laplace shape fit's (sim/measure/sessile_young_laplace.h: angle and capillary
// constant both free) at every angle; the table adds the outline fit with c held at its nominal
// value and the shape fit's sigma_eff / sigma (docs/methods/interface.md validation 3).
// Threads: OMP_NUM_THREADS. Numbers depend on the machine and its load.
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/sim/interface_sessile.h"

using namespace sim;

namespace {

constexpr const char* kUsage =
    "usage: sim_contact_angle_bench [--angles 60,120,150,165] [--resolutions 6,8] [--time 0.3]\n"
    "                               [--start cap|hemisphere|both] [--viscosity 0.005]\n"
    "                               [--walls layered|single|tissue|both|all] [--gravity G]\n"
    "                               [--droplet-density RHO] [--out DIR]\n"
    "  --angles       requested contact angles through the oil [deg], each in [1, 179]\n"
    "  --resolutions  R0 / d, droplet radius over particle spacing, each in [4, 24]\n"
    "  --time         simulated time per run [s] (a capillary time is 26 ms)\n"
    "  --start        cap: the droplet starts as the requested cap; hemisphere: as a hemisphere\n"
    "  --viscosity    dynamic viscosity of both liquids [Pa s]; contact lines move at the "
    "capillary\n"
    "                 speed sigma / viscosity: 150 deg from the hemisphere at R0/8 reads 148 at\n"
    "                 0.2 s with 0.005, and 142 at 1 s with 0.05\n"
    "  --walls        layered: three wall layers, the wall the [contact_angle] tests use; single:\n"
    "                 one Akinci layer, the wall of eye scenes with elastic tissue and of\n"
    "                 accuracy.wall_model = \"single_layer\" (docs/methods/interface.md,\n"
    "                 validation 3); tissue: three layers of elastic tissue (50 kPa, top layer\n"
    "                 free)\n"
    "                 on the layered wall, its top layer wetted, as the retina over an elastic\n"
    "                 sclera; both: layered and single; all: the three\n"
    "  --gravity      [m/s^2] towards the floor (default 0); the droplet must then be heavier\n"
    "                 than the aqueous (1000 kg/m^3), and the angle is read by fitting the\n"
    "                 Young-Laplace outline of its volume with the angle and the capillary\n"
    "                 constant free (drop shape analysis; the table adds the fit with c held\n"
    "                 and sigma_eff / sigma: docs/methods/interface.md, validation 3)\n"
    "  --droplet-density  [kg/m^3] default 970 (silicone oil); 1760 is perfluoro-n-octane\n"
    "  --out          folder for contact_angle_bench.csv and .md (default: .)\n";

struct Options {
  std::vector<double> angles{60, 120, 150, 165};
  std::vector<double> resolutions{6, 8};
  double time = 0.3;
  std::vector<std::string> starts{"cap"};
  double viscosity = 0.005;
  std::vector<std::string> walls{"layered"};
  double gravity = 0;           // [m/s^2]
  double dropletDensity = 970;  // [kg/m^3]
  std::string out = ".";
};

struct Row {
  double requested = 0, resolution = 0;
  std::string start, walls, measure;
  testing::SessileResult result;
  double tolerance() const { return requested >= 30 && requested <= 150 ? 5 : 10; }
  bool gravity = false;  // read by the shape fit (c free); the outline fit (c held) alongside
  double angle() const { return gravity ? result.shapeAngle : result.angle; }
  double finalAngle() const { return gravity ? result.shapeFinalAngle : result.finalAngle; }
  double error() const { return angle() - requested; }
};

std::vector<double> parseList(const std::string& flag, const std::string& text, double lo,
                              double hi) {
  std::vector<double> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !(v >= lo && v <= hi)) {
      char range[64];
      std::snprintf(range, sizeof range, "[%g, %g]", lo, hi);
      throw std::invalid_argument(flag + ": '" + item + "' is not a number in " + range);
    }
    values.push_back(v);
  }
  if (values.empty()) throw std::invalid_argument(flag + " needs at least one value");
  return values;
}

// One of `choices`, or "both" (the first two), or with three choices "all".
std::vector<std::string> parseChoice(const std::string& flag, const std::string& value,
                                     const std::vector<std::string>& choices) {
  if (value == "both") return {choices[0], choices[1]};
  if (value == "all" && choices.size() > 2) return choices;
  for (const std::string& c : choices)
    if (value == c) return {value};
  std::string accepted = choices[0] + ", " + choices[1];
  if (choices.size() == 2) {
    accepted += " or both";
  } else {
    for (std::size_t k = 2; k < choices.size(); ++k) accepted += ", " + choices[k];
    accepted += ", both (" + choices[0] + " and " + choices[1] + ") or all";
  }
  throw std::invalid_argument(flag + " must be " + accepted + ", not '" + value + "'");
}

Options parse(int argc, char** argv) {
  Options o;
  for (int k = 1; k < argc; ++k) {
    const std::string flag = argv[k];
    if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    if (k + 1 >= argc) throw std::invalid_argument("option " + flag + " needs a value");
    const std::string value = argv[++k];
    if (flag == "--angles")
      o.angles = parseList(flag, value, 1, 179);
    else if (flag == "--resolutions")
      o.resolutions = parseList(flag, value, 4, 24);
    else if (flag == "--time")
      o.time = parseList(flag, value, 1e-3, 10).front();
    else if (flag == "--viscosity")
      o.viscosity = parseList(flag, value, 1e-4, 10).front();
    else if (flag == "--start")
      o.starts = parseChoice(flag, value, {"cap", "hemisphere"});
    else if (flag == "--walls")
      o.walls = parseChoice(flag, value, {"layered", "single", "tissue"});
    else if (flag == "--gravity")
      o.gravity = parseList(flag, value, 0, 1000).front();
    else if (flag == "--droplet-density")
      o.dropletDensity = parseList(flag, value, 100, 30000).front();
    else if (flag == "--out")
      o.out = value;
    else
      throw std::invalid_argument("unknown option '" + flag + "'");
  }
  return o;
}

// Rewrites both tables with the rows finished so far; false if the folder cannot be written.
bool writeTables(const Options& o, const std::vector<Row>& rows, std::size_t planned) {
  std::ofstream csv(o.out + "/contact_angle_bench.csv"), md(o.out + "/contact_angle_bench.md");
  if (!csv || !md) return false;
  csv << "requested_deg,start,walls,R0_per_d,time_s,measure,measured_deg,end_deg,error_deg,"
         "tolerance_deg,within,particles,steps,wall_s,finite,c_held_deg,sigma_eff_over_sigma\n";
  md << "Contact angle benchmark (validation 3): sessile droplet, INDSPH, R0 = 3 mm, sigma = 0.04 "
        "N/m, viscosity "
     << o.viscosity << " Pa s, droplet " << o.dropletDensity << " kg/m^3, gravity " << o.gravity
     << " m/s^2, " << o.time << " s simulated, " << omp_get_max_threads() << " thread(s). "
     << rows.size() << " of " << planned << " runs done.\n\n"
     << "| requested [deg] | start | walls | R0/d | measure | measured [deg] | at the end | "
        "error | tolerance | within | particles | steps | wall [s] | c held [deg] | "
        "sigma_eff/sigma |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows) {
    const bool within = r.result.finite && std::abs(r.error()) <= r.tolerance();
    char line[512];
    // Under gravity: the outline fit with c held at its nominal value, and the shape fit's
    // sigma_eff / sigma (empty without gravity).
    char heldCsv[64] = ",", heldMd[64] = "- | -";
    if (r.gravity) {
      std::snprintf(heldCsv, sizeof heldCsv, "%.2f,%.3f", r.result.angle, r.result.shapeSigmaRatio);
      std::snprintf(heldMd, sizeof heldMd, "%.1f | %.3f", r.result.angle, r.result.shapeSigmaRatio);
    }
    std::snprintf(line, sizeof line, "%g,%s,%s,%g,%g,%s,%.2f,%.2f,%+.2f,%g,%d,%zu,%ld,%.1f,%d,%s\n",
                  r.requested, r.start.c_str(), r.walls.c_str(), r.resolution, o.time,
                  r.measure.c_str(), r.angle(), r.finalAngle(), r.error(), r.tolerance(),
                  within ? 1 : 0, r.result.particles, r.result.steps, r.result.seconds,
                  r.result.finite ? 1 : 0, heldCsv);
    csv << line;
    std::snprintf(
        line, sizeof line,
        "| %g | %s | %s | %g | %s | %.1f | %.1f | %+.1f | +-%g | %s | %zu | %ld | %.0f | %s |\n",
        r.requested, r.start.c_str(), r.walls.c_str(), r.resolution, r.measure.c_str(), r.angle(),
        r.finalAngle(), r.error(), r.tolerance(),
        !r.result.finite ? "no (not finite)" : (within ? "yes" : "no"), r.result.particles,
        r.result.steps, r.result.seconds, heldMd);
    md << line;
  }
  return static_cast<bool>(csv) && static_cast<bool>(md);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  try {
    o = parse(argc, argv);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "sim_contact_angle_bench: %s\n\n%s", e.what(), kUsage);
    return 2;
  }
  if (o.gravity > 0 && o.dropletDensity <= 1000) {
    std::fprintf(stderr,
                 "sim_contact_angle_bench: --gravity needs a droplet heavier than the aqueous "
                 "(1000 kg/m^3) or it floats off the floor: give --droplet-density, e.g. 1760\n");
    return 2;
  }
  const std::size_t planned =
      o.walls.size() * o.angles.size() * o.resolutions.size() * o.starts.size();
  std::vector<Row> rows;
  if (!writeTables(o, rows, planned)) {
    std::fprintf(stderr, "sim_contact_angle_bench: cannot write to '%s' (does the folder exist?)\n",
                 o.out.c_str());
    return 1;
  }
  for (const std::string& walls : o.walls)
    for (const double resolution : o.resolutions)
      for (const std::string& start : o.starts)
        for (const double angle : o.angles) {
          testing::SessileCase c;
          c.theta = angle;
          c.startCos = start == "cap" ? -std::cos(angle * std::numbers::pi / 180) : 0.0;
          c.solver = "indsph";
          c.wallLayers = walls == "single" ? 0 : 3;
          if (walls == "tissue") testing::useTissueFloor(c);
          c.jitter = 0.2;
          c.perR = resolution;
          // The fixture widens the box further where a cap's contact line would come within 2 h
          // of the side walls (below about 40 deg at R0 / 8).
          c.halfWidthPerR = angle < 90 ? 2.0 : 1.5;
          c.viscosity = o.viscosity;
          c.tEnd = o.time;
          c.gravity = o.gravity;
          c.dropletDensity = o.dropletDensity;
          // Without gravity the cap fit cannot resolve steeper caps; the outline fit under
          // gravity is read at every angle.
          c.footprint = angle > 150 && o.gravity == 0;
          std::printf("run %zu of %zu: %g deg from the %s, %s walls, R0 = %g d ...\n",
                      rows.size() + 1, planned, angle, start.c_str(), walls.c_str(), resolution);
          std::fflush(stdout);
          Row row{angle,
                  resolution,
                  start,
                  walls,
                  c.footprint ? "footprint" : (o.gravity > 0 ? "shape fit (c free)" : "cap fit"),
                  testing::runSessile(c),
                  o.gravity > 0};
          std::printf("  %.1f deg (%.1f at the end), %zu particles, %ld steps, %.0f s\n",
                      row.angle(), row.finalAngle(), row.result.particles, row.result.steps,
                      row.result.seconds);
          rows.push_back(row);
          if (!writeTables(o, rows, planned)) {
            std::fprintf(stderr, "sim_contact_angle_bench: cannot write to '%s'\n", o.out.c_str());
            return 1;
          }
        }
  std::printf("wrote %s/contact_angle_bench.csv and .md\n", o.out.c_str());
  return 0;
}
