// Benchmark (not a test): explicit (Monaghan 2005) against implicit (Weiler 2018) viscosity for a
// silicone-oil column collapsing in a tank under gravity, DFSPH, d = 2 mm. For each particle count
// and each treatment it runs the same simulated time and writes bench_viscosity.csv and
// bench_viscosity.md: steps, mean dt, wall time per step and per simulated second, the viscosity
// stage's share and the mean CG iterations. Numbers depend on the machine and its load.
//
// usage: sim_bench_viscosity [--particles 10000,30000] [--viscosity 1e-3] [--time 0.05] [--out DIR]
// Threads: OMP_NUM_THREADS (set OMP_WAIT_POLICY=passive on a shared machine).
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scene_fixtures.h"
#include "sim/effects/viscosity_weiler2018.h"

using namespace sim;

namespace {

struct BenchRow {
  std::string treatment;
  std::size_t particles = 0;
  long steps = 0;
  long rejected = 0;
  double meanDt = 0;           // [s]
  double wallSeconds = 0;      // [s]
  double viscositySeconds = 0; // [s] time in the viscosity stage
  double cgIterations = 0;     // mean per solve (implicit only)
  double simulated = 0;        // [s]
};

BenchRow runOne(long targetParticles, Real nu, Real simulatedTime, bool implicitViscosity) {
  const Real d = 0.002;  // [m]
  const Real a = std::cbrt(static_cast<Real>(targetParticles) / 1.5) * d;  // column a x 1.5a x a
  const Real gap = (testing::kWallGap - 0.5) * d;
  TankSpec tank;
  tank.innerMax = Vec3(2 * a + 2 * gap, 2 * a, a + 2 * gap);
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = tankDomain(tank, d);
  World w(params);
  Material oil;
  oil.name = "silicone_oil";
  oil.restDensity = 970;                    // [kg/m^3]
  oil.dynamicViscosity = nu * oil.restDensity;  // [Pa s]
  w.materials.add(oil);
  addTankWalls(w, tank, d);
  addFluidBlock(w, Vec3::Constant(gap), Vec3(gap + a, gap + 1.5 * a, gap + a), d, 0);
  w.initialize();
  PipelineOptions options;
  options.solver = "dfsph";
  options.forced["viscosity"] = implicitViscosity ? Force::kOff : Force::kOn;
  options.forced["implicit_viscosity"] = implicitViscosity ? Force::kOn : Force::kOff;
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  const auto start = std::chrono::steady_clock::now();
  while (w.time < simulatedTime) pipeline.step(w);
  BenchRow row;
  row.treatment = implicitViscosity ? "implicit (Weiler 2018)" : "explicit (Monaghan 2005)";
  row.particles = w.particles.size();
  row.steps = w.stepCount;
  row.rejected = pipeline.rejectedSteps();
  row.simulated = w.time;
  row.meanDt = w.time / static_cast<double>(w.stepCount);
  row.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& e : pipeline.timers().entries())
    if (e.name == "viscosity" || e.name == "implicit_viscosity") row.viscositySeconds += e.seconds;
  for (const auto& e : pipeline.effects())
    if (e->name() == "implicit_viscosity") {
      const auto& v = dynamic_cast<const ViscosityWeiler2018&>(*e);
      row.cgIterations = static_cast<double>(v.totalIterations()) / std::max(1L, v.solves());
    }
  if (!allFinite(w)) throw SimError("benchmark run became non-finite");
  return row;
}

std::vector<long> parseList(const std::string& text) {
  std::vector<long> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) values.push_back(std::stol(item));
  return values;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<long> particles{10000, 30000};
  Real nu = 1e-3, simulatedTime = 0.05;  // [m^2/s], [s]
  std::string out = ".";
  try {
    for (int k = 1; k + 1 < argc; k += 2) {
      const std::string key = argv[k], value = argv[k + 1];
      if (key == "--particles") particles = parseList(value);
      else if (key == "--viscosity") nu = std::stod(value);
      else if (key == "--time") simulatedTime = std::stod(value);
      else if (key == "--out") out = value;
      else throw std::invalid_argument("unknown option " + key);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sim_bench_viscosity: %s\nusage: sim_bench_viscosity [--particles N,M] "
                         "[--viscosity M2_PER_S] [--time S] [--out DIR]\n", e.what());
    return 2;
  }
  std::vector<BenchRow> rows;
  try {
    for (long n : particles)
      for (bool implicitViscosity : {false, true}) {
        rows.push_back(runOne(n, nu, simulatedTime, implicitViscosity));
        const BenchRow& r = rows.back();
        std::printf("%-26s %7zu particles: %5ld steps (%ld rejected), dt %.2e s, %.3f s/step, "
                    "viscosity %.0f %%, CG %.1f\n",
                    r.treatment.c_str(), r.particles, r.steps, r.rejected, r.meanDt,
                    r.wallSeconds / r.steps, 100 * r.viscositySeconds / r.wallSeconds,
                    r.cgIterations);
        std::fflush(stdout);
      }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sim_bench_viscosity: run failed: %s\n", e.what());
    return 1;
  }
  std::ofstream csv(out + "/bench_viscosity.csv"), md(out + "/bench_viscosity.md");
  if (!csv || !md) {
    std::fprintf(stderr, "sim_bench_viscosity: cannot write to %s\n", out.c_str());
    return 1;
  }
  csv << "treatment,particles,steps,rejected,mean_dt_s,wall_s,s_per_step,wall_s_per_simulated_s,"
         "viscosity_share,cg_iterations\n";
  md << "Viscosity benchmark: oil column (nu = " << nu << " m^2/s, d = 2 mm) in a tank, DFSPH, "
     << simulatedTime << " s simulated, " << omp_get_max_threads() << " thread(s).\n\n"
     << "| treatment | particles | steps | rejected | mean dt [s] | s/step | wall s per simulated s "
        "| viscosity share | CG iterations |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const double perStep = r.wallSeconds / r.steps, perSimulated = r.wallSeconds / r.simulated;
    csv << r.treatment << ',' << r.particles << ',' << r.steps << ',' << r.rejected << ','
        << r.meanDt << ',' << r.wallSeconds << ',' << perStep << ',' << perSimulated << ','
        << r.viscositySeconds / r.wallSeconds << ',' << r.cgIterations << '\n';
    md << "| " << r.treatment << " | " << r.particles << " | " << r.steps << " | " << r.rejected
       << " | " << r.meanDt << " | " << perStep << " | " << perSimulated << " | "
       << static_cast<int>(100 * r.viscositySeconds / r.wallSeconds + 0.5) << " % | "
       << r.cgIterations << " |\n";
  }
  return 0;
}
