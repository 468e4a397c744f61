// Dam break (validation 2): the surge front of a collapsing water column of width a and
// height 2a against Martin & Moyce (1952), Phil. Trans. R. Soc. A 244:312, Part IV, Table 2
// (data/reference/martin_moyce_1952.csv, with its sources and normalisation):
// Z = z/a versus T = n t sqrt(g/a), n = sqrt(2).
//
// Scene (sim/scenes/dam_break.h): quasi-2D slab 4 spacings deep, free-slip walls, a = 5 cm (the
// experiment used 2.25 in = 5.7 cm; the front in these units does not depend on a at this scale:
// Martin & Moyce's 1.125 in and 2.25 in columns fall on one curve, Fig. 3), d = a/16.
//
// The band. Two effects shift the simulated front against the measured one, and the band allows
// exactly these, no more:
//  1. Time origin. The experiment released the column by removing a diaphragm; its time origin
//     is uncertain by 0.15-0.25 in T and the measured front lags an instantaneous release (the
//     CSV caveat; Lethe shifts its simulations by +0.175). The simulation releases instantly, so it
//     may lead the data by up to kTimeOriginLead = 0.25 in T, and must not lag.
//  2. Resolution and data. The lattice column starts 0.7 d further from the back wall than the
//     ideal column (kWallGap, so the walls do not start with a pressure shock); the front is
//     located to half a spacing (the edge of the furthest particle's cell); the transcribed table
//     agrees with an independent digitisation to +-0.02 in Z. Together delta = 0.7 d/a +
//     0.5 d/a + 0.02 = 0.095 at d = a/16.
// So for every published point (T_e, Z_e) inside the run:
//     Z_e - delta  <=  Z_sph(T_e)  <=  Z_exp(T_e + kTimeOriginLead) + delta
// with Z_exp the table interpolated linearly.
#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "sim/scenes/dam_break.h"

using namespace sim;

namespace {

struct Point {
  Real T, Z;
};

// Rows of one dataset of the reference CSV (tests run in the source root, see
// TamponadeTests.cmake).
std::vector<Point> loadMartinMoyce(const std::string& datasetId) {
  const std::string path = "data/reference/martin_moyce_1952.csv";
  std::ifstream in(path);
  REQUIRE(in.good());
  std::vector<Point> points;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream row(line);
    std::string id, quantity, n2, aIn, T, value;
    std::getline(row, id, ',');
    if (id != datasetId) continue;
    std::getline(row, quantity, ',');
    std::getline(row, n2, ',');
    std::getline(row, aIn, ',');
    std::getline(row, T, ',');
    std::getline(row, value, ',');
    points.push_back({std::stod(T), std::stod(value)});
  }
  REQUIRE(points.size() >= 10);
  return points;
}

Real interpolate(const std::vector<Point>& curve, Real T) {
  if (T <= curve.front().T) return curve.front().Z;
  for (std::size_t k = 1; k < curve.size(); ++k)
    if (T <= curve[k].T) {
      const Real s = (T - curve[k - 1].T) / (curve[k].T - curve[k - 1].T);
      return curve[k - 1].Z + s * (curve[k].Z - curve[k - 1].Z);
    }
  return curve.back().Z;
}

// Runs the scene to T = endT and returns the front history (T, Z) after every step.
// One OpenMP thread: the result does not depend on the thread count (bit-identical, see the
// determinism test below), and with 2048 particles on a shared, oversubscribed 2-core CI machine
// the OpenMP barriers cost more than the second thread gains (measured at load 6: 270 s with 2
// threads and the default spin-wait policy, 19 s with 1 thread).
std::vector<Point> runDamBreak(const std::string& solver, Real endT) {
  const int previousThreads = omp_get_max_threads();
  omp_set_num_threads(1);
  DamBreakSpec spec;
  spec.solver = solver;
  DamBreakScene scene = buildDamBreak(spec);
  Pipeline pipeline = assemblePipeline(*scene.world, scene.options);
  pipeline.attach(*scene.world);
  std::vector<Point> history{{0.0, surgeFront(scene)}};
  while (scene.world->time < endT * scene.timeScale) {
    pipeline.step(*scene.world);
    history.push_back({scene.world->time / scene.timeScale, surgeFront(scene)});
  }
  omp_set_num_threads(previousThreads);
  std::printf("dam break %s: %zu particles, %ld steps, %ld rejected\n", solver.c_str(),
              scene.world->particles.size(), scene.world->stepCount, pipeline.rejectedSteps());
  return history;
}

constexpr Real kTimeOriginLead = 0.25;  // [1] in T, see the file comment
constexpr Real kEndT = 2.6;             // [1] covers the table up to T = 2.51

// Checks every published point with T_e in [0.4, kEndT - 0.05]; prints the comparison.
void checkBand(const std::vector<Point>& sph, const std::string& solver) {
  const std::vector<Point> table = loadMartinMoyce("MM52_front_n2-2_a2.25in_table");
  std::vector<Point> points = table;
  const std::vector<Point> fig3 = loadMartinMoyce("MM52_front_n2-2_a2.25in_fig3");
  points.insert(points.end(), fig3.begin(), fig3.end());
  const Real d = DamBreakSpec{}.spacing, a = DamBreakSpec{}.columnWidth;
  const Real delta = 0.7 * d / a + 0.5 * d / a + 0.02;
  int checked = 0;
  std::printf("  %-6s %-6s %-8s %-8s %-8s (%s)\n", "T", "Z_exp", "Z_sph", "low", "high",
              solver.c_str());
  for (const Point& e : points) {
    if (e.T < 0.4 || e.T > kEndT - 0.05) continue;
    const Real zSph = interpolate(sph, e.T);
    const Real low = e.Z - delta;
    const Real high = interpolate(table, e.T + kTimeOriginLead) + delta;
    std::printf("  %-6.3f %-6.3f %-8.3f %-8.3f %-8.3f%s\n", e.T, e.Z, zSph, low, high,
                zSph < low || zSph > high ? "  OUT" : "");
    INFO(solver << " at T = " << e.T << ": Z_sph = " << zSph << ", band [" << low << ", " << high
                << "], Martin & Moyce Z = " << e.Z);
    CHECK(zSph >= low);
    CHECK(zSph <= high);
    ++checked;
  }
  CHECK(checked >= 10);
}

}  // namespace

TEST_CASE("dam break surge front matches Martin & Moyce 1952 (WCSPH)", "[validation][dam_break]") {
  checkBand(runDamBreak("wcsph", kEndT), "wcsph");
}

// DFSPH on the same scene and band. Known problem (docs/benchmarks.md, engine notes): almost every
// DFSPH step is redone once by the displacement guard; the front is still checked in full.
TEST_CASE("dam break surge front matches Martin & Moyce 1952 (DFSPH)", "[validation][dam_break]") {
  checkBand(runDamBreak("dfsph", kEndT), "dfsph");
}

// VSLSPH (Li et al. 2023) on the same scene and band: explicit like WCSPH, at the scene's speed
// of sound, with each particle's support grown where the column thins (the surge's tip).
TEST_CASE("dam break surge front matches Martin & Moyce 1952 (VSLSPH)", "[validation][dam_break]") {
  checkBand(runDamBreak("vslsph", kEndT), "vslsph");
}

// ---- determinism (docs/developer-guide.md principle 7): fixed-order reductions, static OpenMP
// schedules ----

namespace {

// Positions after 24 steps of a coarse dam break (d = a/8: walls, free surface, Z-order sorts
// every 16 steps, so one re-sort in the run), indexed by particle id so the comparison does not
// depend on the sort; the second element is the initial positions (to check that the run did
// something).
std::pair<std::vector<Vec3>, std::vector<Vec3>> coarseRun(const std::string& solver, int threads) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  DamBreakSpec spec;
  spec.solver = solver;
  spec.spacing = spec.columnWidth / 8;
  DamBreakScene scene = buildDamBreak(spec);
  const std::vector<Vec3> initial = scene.world->particles.x;  // ids are creation indices
  Pipeline pipeline = assemblePipeline(*scene.world, scene.options);
  pipeline.attach(*scene.world);
  for (int s = 0; s < 24; ++s) pipeline.step(*scene.world);
  omp_set_num_threads(previous);
  const auto& p = scene.world->particles;
  std::vector<Vec3> byId(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) byId[static_cast<std::size_t>(p.id[i])] = p.x[i];
  return {byId, initial};
}

}  // namespace

TEST_CASE("identical runs are bit-identical, also across thread counts", "[unit][determinism]") {
  for (const std::string solver : {"wcsph", "dfsph", "vslsph"}) {
    // One 2-thread run only: on an oversubscribed CI machine each 2-thread run costs seconds of
    // OpenMP barrier waits, and repeatability plus 1-vs-2-thread equality already pins it down.
    const auto [single, initial] = coarseRun(solver, 1);
    const auto second = coarseRun(solver, 1).first;
    const auto first = coarseRun(solver, 2).first;
    REQUIRE(first.size() == second.size());
    REQUIRE(first.size() == single.size());
    std::size_t sameRepeat = 0, sameThreads = 0, moved = 0;
    for (std::size_t i = 0; i < first.size(); ++i) {
      sameRepeat += single[i] == second[i];  // exact comparison on purpose: bit-identical
      sameThreads += first[i] == single[i];
      moved += single[i] != initial[i];
    }
    INFO(solver);
    CHECK(sameRepeat == first.size());
    CHECK(sameThreads == first.size());
    CHECK(moved == first.size());  // every particle moved: the comparison is not trivial
  }
}
