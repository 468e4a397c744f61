// Benchmark (not a test): first bending mode of a clamped plate, the set-up of Gray, Monaghan &
// Swift 2001 ("SPH elastic dynamics", CMAME 190, section 6.1): L = 0.2 m, H = 0.02 m,
// rho = 1000 kg/m^3, E = 2 MPa, nu = 0.3975, started with the first mode's velocity profile
// v_y(x) = V_f c_s F(x) / F(L), kL = 1.875. Here in 3D, 3 particles wide with free side faces, so
// the reference is the narrow-beam frequency omega^2 = E H^2 k^4 / (12 rho) (Gray's 2D plane-strain
// value divides E by 1 - nu^2; both are printed). Prints one markdown table row.
//
// Usage: solid_plate_bench [particles through the thickness = 5] [steps per period = 100]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "tests/sim/solid_fixtures.h"

using namespace sim;
using namespace sim::testing;

int main(int argc, char** argv) {
  const int thick = argc > 1 ? std::atoi(argv[1]) : 5;
  const int stepsPerPeriod = argc > 2 ? std::atoi(argv[2]) : 100;
  const Real L = 0.2, H = 0.02, rho = 1000, E = 2e6, nu = 0.3975;  // [m], [m], [kg/m^3], [Pa], [1]
  const Real d = H / thick;
  const int n = static_cast<int>(std::lround(L / d)), wide = 3, clamp = 3;
  const Real kL = 1.875, k = kL / L;
  const Real omega = k * k * std::sqrt(E * H * H / (12 * rho));  // [rad/s] narrow beam
  const Real omegaPlate =
      k * k * std::sqrt(E * H * H / (12 * rho * (1 - nu * nu)));  // plane strain
  const Real period = 2 * M_PI / omega;

  WorldParameters params =
      solidWorldParameters(d, Box(Vec3(-0.05, -0.1, -0.05), Vec3(0.3, 0.1, 0.05)), Vec3::Zero());
  params.maxTimeStep = period / stepsPerPeriod;
  World world(params);
  const int mat = world.materials.add(elasticMaterial("plate", rho, E, nu));
  addLattice(world, Vec3(-clamp * d, -0.5 * H, 0), Eigen::Vector3i(n + clamp, thick, wide), d, mat);
  world.initialize();
  // Mode shape of a clamped-free beam, x from the clamp.
  auto F = [&](Real x) {
    return (std::cos(kL) + std::cosh(kL)) * (std::cosh(k * x) - std::cos(k * x)) +
           (std::sin(kL) - std::sinh(kL)) * (std::sinh(k * x) - std::sin(k * x));
  };
  const Real cs = std::sqrt(E / (3 * (1 - 2 * nu)) / rho);  // [m/s] bulk sound speed (Gray)
  const Real vf = 0.001;  // [1] small: tip amplitude ~ vf cs / omega = 2.5 mm = 1.3 % of L
  for (Index i = 0; i < world.particles.size(); ++i) {
    const Real x = world.particles.x[i].x();
    if (x < 0)
      setFixed(world.particles, i);
    else
      world.particles.v[i].y() = vf * cs * F(x) / F(L);
  }
  ElasticityParameters elastic;
  elastic.waveCourantNumber = 1e6;  // dt is set by the period (accuracy), not the wave speed
  Pipeline pipeline = solidPipeline(world, elastic);

  const auto start = std::chrono::steady_clock::now();
  std::vector<Real> crossings;  // [s] times where the tip displacement changes sign
  Real previous = 0, previousTime = 0;
  long iterations = 0;
  while (world.time < 2.2 * period) {
    pipeline.step(world);
    iterations += elasticStage(pipeline).stats().iterations;
    const auto& reference = world.particles.fields.get<Vec3>(field::kReferencePosition);
    Real tip = 0;
    int count = 0;
    for (Index i = 0; i < world.particles.size(); ++i)
      if (reference[i].x() > L - d) {
        tip += world.particles.x[i].y() - reference[i].y();
        ++count;
      }
    tip /= count;
    if (world.stepCount > 1 && (tip > 0) != (previous > 0))
      crossings.push_back(previousTime + (world.time - previousTime) * previous / (previous - tip));
    previous = tip;
    previousTime = world.time;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (crossings.size() < 2) {
    std::printf("no oscillation found (%zu zero crossings)\n", crossings.size());
    return 1;
  }
  // Half periods between successive zero crossings (the first crossing is at T/2: the tip starts
  // at zero displacement moving up).
  const Real simulatedPeriod =
      2 * (crossings.back() - crossings.front()) / static_cast<Real>(crossings.size() - 1);
  const Real f = 1 / simulatedPeriod, f0 = omega / (2 * M_PI);
  std::printf(
      "| particles | thickness | dt [s] | f SPH [Hz] | f beam [Hz] | error | f plane strain "
      "[Hz] | CG iterations/step | wall [s] |\n|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| %zu | %d d | %.3g | %.4f | %.4f | %+.2f %% | %.4f | %.0f | %.1f |\n",
              world.particles.size(), thick, params.maxTimeStep, f, f0, 100 * (f / f0 - 1),
              omegaPlate / (2 * M_PI), static_cast<double>(iterations) / world.stepCount, wall);
  return 0;
}
