// Benchmark (not a test): explicit (Monaghan 2005) against implicit (Weiler 2018) viscosity for a
// silicone-oil scene, DFSPH, d = 2 mm. Scene "settle": the column fills
// the tank's width and settles (slow flow, the tamponade's regime: the CFL step is far above the
// explicit viscous limit); scene "collapse": the column stands in half of a tank twice as wide and
// collapses (a dam break, speeds of tenths of m/s, where the CFL step approaches the explicit
// limit); scene "shear": a cube of oil between two plates, no gravity, with a decaying sinusoidal
// shear profile (slow flow without the pressure solver's jitter at rest under gravity, so the step
// is the CFL one and the comparison isolates the viscosity treatment). For each particle count and
// each treatment it runs the same simulated time and writes bench_viscosity.csv and
// bench_viscosity.md: steps, mean dt, wall time per step and per simulated second, the viscosity
// stage's share and the mean CG iterations. Numbers depend on the machine and its load.
//
// usage: sim_bench_viscosity [--particles 10000,30000] [--viscosity 1e-3] [--time 0.05]
//                            [--scene settle|collapse|shear] [--out DIR]
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

#include "sim/effects/viscosity_weiler2018.h"
#include "tests/sim/scene_fixtures.h"

using namespace sim;

namespace {

struct BenchRow {
  std::string treatment;
  std::size_t particles = 0;
  long steps = 0;
  long rejected = 0;
  double meanDt = 0;            // [s]
  double wallSeconds = 0;       // [s]
  double viscositySeconds = 0;  // [s] time in the viscosity stage
  double cgIterations = 0;      // mean per solve (implicit only)
  double simulated = 0;         // [s]
  std::string failure;          // empty, or why the run stopped (an unstable run is a result too)
};

// Builds the scene into `w` (see the file comment). Column sizes are whole numbers of spacings so
// that the lattice fits the tank exactly with the usual wall gap (scene_fixtures.h).
void buildScene(World& w, const std::string& scene, long targetParticles, Real nu) {
  const Real d = w.particleSpacing();
  const Real gap = (testing::kWallGap - 0.5) * d;
  Material oil;
  oil.name = "silicone_oil";
  oil.restDensity = 970;                        // [kg/m^3]
  oil.dynamicViscosity = nu * oil.restDensity;  // [Pa s]
  w.materials.add(oil);
  if (scene == "shear") {
    // A cube of oil between two plates (free side faces, no gravity) with the shear profile
    // u_x = U sin(pi y / H), U = 1 cm/s, decaying at rate nu pi^2 / H^2.
    const int layers = static_cast<int>(std::lround(std::cbrt(static_cast<Real>(targetParticles))));
    const Real length = layers * d, height = length + 2 * gap + d;  // plate to plate
    for (int a = -4; a <= layers + 4; ++a)
      for (int c = -4; c <= layers + 4; ++c) {
        w.walls.add(Vec3(a * d, 0, c * d), Vec3(0, -1, 0));
        w.walls.add(Vec3(a * d, height, c * d), Vec3(0, 1, 0));
      }
    addFluidBlock(w, Vec3(0, gap + 0.5 * d, 0), Vec3(length, height - gap - 0.5 * d, length), d, 0);
    for (Index i = 0; i < w.particles.size(); ++i)
      w.particles.v[i] =
          Vec3(0.01 * std::sin(3.14159265358979 * w.particles.x[i].y() / height), 0, 0);
  } else {
    const int columns =
        static_cast<int>(std::lround(std::cbrt(static_cast<Real>(targetParticles) / 1.5)));
    const Real a = columns * d;  // column a x 1.5a x a
    TankSpec tank;
    tank.innerMax = Vec3((scene == "collapse" ? 2 * a : a) + 2 * gap, 2 * a, a + 2 * gap);
    addTankWalls(w, tank, d);
    addFluidBlock(w, Vec3::Constant(gap), Vec3(gap + a, gap + 1.5 * a, gap + a), d, 0);
  }
  w.initialize();
}

WorldParameters sceneParameters(const std::string& scene, long targetParticles) {
  const Real d = 0.002;                                                              // [m]
  const Real size = 2 * std::cbrt(static_cast<Real>(targetParticles)) * d + 20 * d;  // generous
  WorldParameters params;
  params.particleSpacing = d;
  params.domain = Box(Vec3::Constant(-12 * d), Vec3::Constant(size));
  if (scene == "shear") params.gravity = Vec3::Zero();
  return params;
}

BenchRow runOne(const std::string& scene, long targetParticles, Real nu, Real simulatedTime,
                bool implicitViscosity) {
  World w(sceneParameters(scene, targetParticles));
  buildScene(w, scene, targetParticles, nu);
  PipelineOptions options;
  options.solver = "dfsph";
  options.forced["viscosity"] = implicitViscosity ? StageOverride::kOff : StageOverride::kOn;
  options.forced["implicit_viscosity"] =
      implicitViscosity ? StageOverride::kOn : StageOverride::kOff;
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  const auto start = std::chrono::steady_clock::now();
  BenchRow row;
  try {
    while (w.time < simulatedTime) pipeline.step(w);
    if (!allFinite(w)) throw SimError("the state became non-finite");
  } catch (const SimError& e) {
    row.failure = "at t = " + std::to_string(w.time) + " s: " + e.what();
  }
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
  std::string out = ".", scene = "settle";
  try {
    for (int k = 1; k + 1 < argc; k += 2) {
      const std::string key = argv[k], value = argv[k + 1];
      if (key == "--particles")
        particles = parseList(value);
      else if (key == "--viscosity")
        nu = std::stod(value);
      else if (key == "--time")
        simulatedTime = std::stod(value);
      else if (key == "--out")
        out = value;
      else if (key == "--scene" && (value == "settle" || value == "collapse" || value == "shear"))
        scene = value;
      else
        throw std::invalid_argument("unknown option " + key);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr,
                 "sim_bench_viscosity: %s\nusage: sim_bench_viscosity [--particles N,M] "
                 "[--viscosity M2_PER_S] [--time S] [--scene settle|collapse|shear] [--out DIR]\n",
                 e.what());
    return 2;
  }
  std::vector<BenchRow> rows;
  try {
    for (long n : particles)
      for (bool implicitViscosity : {false, true}) {
        rows.push_back(runOne(scene, n, nu, simulatedTime, implicitViscosity));
        const BenchRow& r = rows.back();
        std::printf(
            "%-26s %7zu particles: %5ld steps (%ld rejected), dt %.2e s, %.3f s/step, "
            "viscosity %.0f %%, CG %.1f\n",
            r.treatment.c_str(), r.particles, r.steps, r.rejected, r.meanDt,
            r.wallSeconds / r.steps, 100 * r.viscositySeconds / r.wallSeconds, r.cgIterations);
        if (!r.failure.empty()) std::printf("  FAILED %s\n", r.failure.c_str());
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
         "viscosity_share,cg_iterations,failure\n";
  md << "Viscosity benchmark, scene '" << scene << "': silicone oil (nu = " << nu
     << " m^2/s, d = 2 mm), DFSPH, " << simulatedTime << " s simulated, " << omp_get_max_threads()
     << " thread(s).\n\n"
     << "| treatment | particles | steps | rejected | mean dt [s] | s/step | wall s per simulated "
        "s "
        "| viscosity share | CG iterations | failure "
        "|\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const double perStep = r.wallSeconds / r.steps, perSimulated = r.wallSeconds / r.simulated;
    csv << r.treatment << ',' << r.particles << ',' << r.steps << ',' << r.rejected << ','
        << r.meanDt << ',' << r.wallSeconds << ',' << perStep << ',' << perSimulated << ','
        << r.viscositySeconds / r.wallSeconds << ',' << r.cgIterations << ",\"" << r.failure
        << "\"\n";
    md << "| " << r.treatment << " | " << r.particles << " | " << r.steps << " | " << r.rejected
       << " | " << r.meanDt << " | " << perStep << " | " << perSimulated << " | "
       << static_cast<int>(100 * r.viscositySeconds / r.wallSeconds + 0.5) << " % | "
       << r.cgIterations << " | " << (r.failure.empty() ? "-" : r.failure) << " |\n";
  }
  return 0;
}
