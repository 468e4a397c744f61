// The solver comparison's tables (`tamponade bench solvers`) on made-up numbers: the
// benchmark itself is not a test, but what it writes must be right.
#include <catch2/catch.hpp>

#include <filesystem>

#include "protocols/bench/solver_comparison.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"

namespace {

protocols::SolverComparisonRun fakeRun(const std::string& solver, double ratio, bool stable) {
  protocols::SolverComparisonRun r;
  r.solver = solver;
  r.densityRatio = ratio;
  r.particles = 1024;
  r.duration = 0.3;
  r.stable = stable;
  r.failedAt = stable ? -1.0 : 0.0125;
  r.failure = stable ? "" : "a particle left the tank, at the \"top\"";
  r.simulatedTime = stable ? 0.3 : 0.0125;
  r.steps = 2;
  r.meanAverageCompression = 2.5e-4;
  r.maxCompression = 3.5e-3;
  r.meanIterations = 7.5;
  r.meanInterfaceGap = 1.02;
  r.finalInterfaceGap = 1.04;
  r.meanInterfaceDensityRatio = 0.985;
  r.peakEnergyRatio = 0.25;
  r.wallSeconds = 1.5;
  r.series = {{0.001, 1, 1e-4, 2e-3, 5, 5, 1.0}, {0.002, 2, 4e-4, 5e-3, 10, 15, 1.04}};
  return r;
}

}  // namespace

TEST_CASE("bench solvers: CSV and markdown tables from made-up runs", "[unit][bench]") {
  const std::vector<protocols::SolverComparisonRun> runs = {fakeRun("indsph", 75, true),
                                                            fakeRun("number_density", 3, false)};
  const std::string csv = protocols::solverComparisonCsv(runs);
  CHECK(csv ==
        "solver,density_ratio,particles,stable,failed_at_s,failure,simulated_s,steps,"
        "mean_average_compression,max_compression,mean_iterations,mean_interface_gap_d,"
        "final_interface_gap_d,interface_density_ratio,peak_kinetic_over_potential,wall_s,"
        "wall_per_simulated_s\n"
        "indsph,1:75,1024,yes,,,0.3,2,0.00025,0.0035,7.5,1.02,1.04,0.985,0.25,1.5,5\n"
        // the failure text is made CSV-safe (no commas or quotes); 1.5 s / 0.0125 s = 120
        "number_density,1:3,1024,no,0.0125,a particle left the tank; at the ;top;,0.0125,2,0.00025,"
        "0.0035,7.5,1.02,1.04,0.985,0.25,1.5,120\n");
  const std::string md = protocols::solverComparisonMarkdown(runs);
  CHECK(
      md.find(
          "| indsph | 1:75 | yes | 2.50e-04 / 3.50e-03 | 7.5 | 1.02 / 1.04 | 0.985 | 0.25 | 5 |") !=
      std::string::npos);
  CHECK(md.find("| number_density | 1:3 | no (0.0125 s: a particle left the tank") !=
        std::string::npos);
  CHECK(protocols::runFileStem(runs[0]) == "indsph_1-75");
  CHECK(protocols::compressionSeriesCsv(runs[0]) ==
        "time_s,step,average_compression,max_compression\n0.001,1,0.0001,0.002\n0.002,2,0.0004,0."
        "005\n");
  CHECK(protocols::iterationSeriesCsv(runs[0]) ==
        "time_s,step,iterations,cumulative_iterations,interface_gap_d\n0.001,1,5,5,1\n0.002,2,10,"
        "15,1.04\n");

  const tamponade_test::ScratchDirectory dir("tamponade_bench_tables");
  protocols::writeSolverComparison(runs, dir / "out");
  CHECK(tamponade_test::readText(dir / "out" / "solvers.csv") == csv);
  CHECK(tamponade_test::readText(dir / "out" / "solvers.md") == md);
  CHECK(std::filesystem::exists(dir / "out" / "compression_number_density_1-3.csv"));
  CHECK(std::filesystem::exists(dir / "out" / "iterations_indsph_1-75.csv"));
}
