// Hand-run benchmark of the Laplace droplet (the `[laplace]` scene, docs/methods/interface.md
// validation 1) under any solver, printing every fifth step: the pressure jump, the interface's
// area sum V |gradC| (what the surface stress acts through), the jump the explicit forces ask for
// (sum -m a.e_r / (4 pi r^2)) and the largest speed. `analytic=1` replaces the tension by an exact
// radial gradient force of the same jump, which any consistent projection must hold (the solver
// check of docs/methods/interface.md, validation 1b).
//   sim_laplace_bench [solver=indsph] [R=3 (mm)] [perR=6] [sigma=0.04] [taus=1.5] [excess=0]
//                     [layers=0] [analytic=0] [bg=auto|off|PA] [bgk=K (K sigma / d)] [dtmax=S]
//                     [warm=] [tol=] [miniter=] [maxiter=] [expansion=0|1] [divergence=0|1]
//                     [omega=] [xsph=] [jitter=0 (d, start lattice)]
//                     [form=auto|corrected|symmetric (surface stress)]
//                     [density=970 (the droplet's, kg/m^3; the aqueous is 1000)]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sim/measure/droplet_pressure_jump.h"
#include "tests/sim/interface_fixtures.h"
#include "tools/bench/bench_options.h"

using namespace sim;

namespace {

// Exact answer p = phi(r), phi = jump (1 - S((r - R) / w)) with S rising smoothly from 0 to 1
// over [-1, 1] (S' = (1 + cos(pi s)) / (2 w)); at rest rho a = grad p, so a = phi'(r) e_r / rho.
class RadialStepForce final : public Effect {
 public:
  RadialStepForce(Vec3 centre, Real radius, Real halfWidth, Real jump)
      : centre_(centre), radius_(radius), halfWidth_(halfWidth), jump_(jump) {}
  std::string_view name() const override { return "radial_step"; }
  void apply(World& world, const StepContext&) override {
    auto& p = world.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 d = p.x[i] - centre_;
      const Real r = d.norm();
      const Real s = (r - radius_) / halfWidth_;
      if (std::abs(s) >= 1 || r == 0) continue;
      const Real dphidr = -jump_ * 0.5 * (1 + std::cos(std::numbers::pi * s)) / halfWidth_;
      p.a[i] += (dphidr / (p.density[i] * r)) * d;
    }
  }

 private:
  Vec3 centre_;
  Real radius_, halfWidth_, jump_;  // [m], [m], [Pa]
};

// The pipeline the scene's rules choose, with the radial force first when `analytic`.
Pipeline buildPipeline(const World& w, const PipelineOptions& options, bool analytic,
                       const Vec3& centre, Real radius, Real halfWidth, Real jump) {
  if (!analytic) return assemblePipeline(w, options);
  std::unique_ptr<PressureSolver> solver;
  for (const auto& e : solverRegistry())
    if (e.name == options.solver) solver = e.create(w, options);
  require(solver != nullptr, "unknown solver " + options.solver);
  std::vector<std::unique_ptr<Effect>> effects;
  std::vector<StageDecision> decisions;
  effects.push_back(std::make_unique<RadialStepForce>(centre, radius, halfWidth, jump));
  decisions.push_back({"radial_step", true, false, "analytic=1: exact gradient force"});
  for (const auto& entry : effectRegistry()) {
    StageDecision d = entry.needed(w, options);
    if (!d.active) continue;
    effects.push_back(entry.create(w, options));
    decisions.push_back(std::move(d));
  }
  return Pipeline(std::move(solver), std::move(effects), std::move(decisions));
}

}  // namespace

int main(int argc, char** argv) {
  std::string solver = "indsph";
  Real perR = 6, taus = 1.5, excess = 0.0, sigma = 0.04, radius = 0.003;
  int layers = 0;
  Real dtmax = 0, bgk = 0, jitter = 0, dropletDensity = 970;  // [kg/m^3] the droplet's
  std::string background = "auto";
  bool analytic = false;
  PipelineOptions options;
  for (int k = 1; k < argc; ++k) {
    const char* eq = std::strchr(argv[k], '=');
    if (!eq) {
      std::fprintf(
          stderr,
          "usage: sim_laplace_bench [solver=indsph] [R=mm] [perR=6] [sigma=0.04] [taus=1.5] "
          "[excess=0] [layers=0] [analytic=0|1] [bg=auto|off|PA] [bgk=K] [dtmax=S] [warm=] "
          "[tol=] [miniter=] [maxiter=] [expansion=0|1] [divergence=0|1] [omega=] [xsph=]\n");
      return 2;
    }
    const std::string key(static_cast<const char*>(argv[k]), eq), v(eq + 1);
    if (key == "solver")
      solver = v;
    else if (key == "perR")
      perR = std::atof(v.c_str());
    else if (key == "taus")
      taus = std::atof(v.c_str());
    else if (key == "excess")
      excess = std::atof(v.c_str());
    else if (key == "layers")
      layers = std::atoi(v.c_str());
    else if (key == "analytic")
      analytic = v != "0";
    else if (key == "warm")
      options.indsph.warmStartFactor = std::atof(v.c_str());
    else if (key == "tol")
      options.indsph.tolerance = std::atof(v.c_str());
    else if (key == "miniter")
      options.indsph.minIterations = std::atoi(v.c_str());
    else if (key == "maxiter")
      options.indsph.maxIterations = std::atoi(v.c_str());
    else if (key == "expansion")
      options.indsph.correctBulkExpansion = v != "0";
    else if (key == "divergence")
      options.indsph.divergenceSolve = v != "0";
    else if (key == "omega")
      options.indsph.relaxation = std::atof(v.c_str());
    else if (key == "xsph")
      options.velocitySmoothing = std::atof(v.c_str());
    else if (key == "bg")
      background = v;
    else if (key == "bgk")
      bgk = std::atof(v.c_str());
    else if (key == "sigma")
      sigma = std::atof(v.c_str());
    else if (key == "R")
      radius = std::atof(v.c_str()) * 1e-3;
    else if (key == "dtmax")
      dtmax = std::atof(v.c_str());
    else if (key == "jitter")
      jitter = std::atof(v.c_str());
    else if (key == "density" || key == "form") {
      try {
        if (key == "density")
          dropletDensity = testing::benchNumber(key, v, 1, 1e5);
        else
          options.surfaceStress = testing::benchSurfaceStressForm(v);
      } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "sim_laplace_bench: %s\n", e.what());
        return 2;
      }
    } else {
      std::fprintf(
          stderr,
          "unknown option '%s' (see the comment at the top of interface_laplace_bench.cpp)\n",
          argv[k]);
      return 2;
    }
  }
  testing::DropletSpec s;
  s.radius = radius;
  s.spacing = radius / perR;
  const Real h = 2 * s.spacing;
  s.halfWidth = radius + 2 * h + s.spacing;
  s.sigma = analytic ? 0.0 : sigma;
  s.oilViscosity = s.aqueousViscosity = 0.05;
  s.massExcess = excess;
  s.oilDensity = dropletDensity;
  s.wallLayers = layers;
  s.maxTimeStep = dtmax;
  s.jitter = jitter;
  // The box is full: a jittered start reads as a free surface to the automatic rule.
  if (jitter > 0) options.closedDomain = StageOverride::kOn;
  if (bgk > 0) options.backgroundPressure = bgk * sigma / s.spacing;
  if (background == "off")
    options.backgroundPressure = 0;
  else if (background != "auto")
    options.backgroundPressure = std::atof(background.c_str());
  auto scene = testing::dropletScene(s);
  World& w = *scene.world;
  const Real expected = 2 * sigma / scene.radius;
  options.solver = solver;
  options.wcsph.speedOfSound = 12 * std::sqrt(expected / 1000.0);
  options.wcsph.artificialViscosity = 0.5;
  const Vec3 boxCentre = Vec3(0.5 * scene.spec.innerMax);
  Pipeline pipeline = buildPipeline(w, options, analytic, boxCentre, scene.radius, h, expected);
  pipeline.attach(w);
  std::printf("%s\n", pipeline.describe().c_str());
  const auto& pressure = w.particles.fields.get<Real>("pressure");
  const Real tau = std::sqrt(1000.0 * radius * radius * radius / sigma);
  long next = 0;
  while (w.time < taus * tau) {
    pipeline.step(w);
    if (w.stepCount < next) continue;
    next = w.stepCount + 5;
    const Vec3 centre = analytic ? boxCentre : centreOfMaterial(w, scene.oil);
    const auto jump = measureDropletPressureJump(
        w, pressure, {centre, scene.radius, h, scene.oil, scene.radius + 2 * h});
    // The jump the explicit forces of this step ask for: sum over shells of -m a.e_r / (4 pi r^2).
    Real demanded = 0;
    for (Index i = 0; i < w.particles.size(); ++i) {
      const Vec3 r = w.particles.x[i] - centre;
      demanded -= w.particles.mass[i] * w.particles.a[i].dot(r.normalized()) /
                  (4 * std::numbers::pi * r.squaredNorm());
    }
    // sum V |gradC|: the interface's area for a well-formed diffuse layer.
    Real area = 0;
    int strayOil = 0, strayAq = 0;
    if (w.particles.fields.has("colour_gradient")) {
      const auto& gc = w.particles.fields.get<Vec3>("colour_gradient");
      for (Index i = 0; i < w.particles.size(); ++i) {
        area += w.particles.mass[i] / w.particles.density[i] * gc[i].norm();
        const Real r = (w.particles.x[i] - centre).norm();
        if (w.particles.material[i] == scene.oil && r > scene.radius + 0.5 * h) ++strayOil;
        if (w.particles.material[i] != scene.oil && r < scene.radius - 0.5 * h) ++strayAq;
      }
    }
    Real vmax = 0;
    for (const auto& v : w.particles.v) vmax = std::max(vmax, v.norm());
    // Net explicit force over all particles against the sum of magnitudes: 0 for a
    // momentum-conserving force field (walls aside), and the droplet's drift from the box centre.
    Vec3 net = Vec3::Zero();
    Real magnitude = 0;
    for (Index i = 0; i < w.particles.size(); ++i) {
      net += w.particles.mass[i] * w.particles.a[i];
      magnitude += w.particles.mass[i] * w.particles.a[i].norm();
    }
    std::printf("  net force / sum |force| %.2e, droplet centre drift %.3g d\n",
                net.norm() / std::max(magnitude, Real(1e-300)),
                (centreOfMaterial(w, scene.oil) - boxCentre).norm() / w.particleSpacing());
    std::printf(
        "step %4ld t %.4f dt %.2e in %.2f out %.2f jump/expected %.3f vmax %.3g iters %d "
        "demanded %.3f area/4piR2 %.3f stray oil %d aqueous %d\n",
        w.stepCount, w.time, pipeline.lastTimeStep().dt, jump.inside, jump.outside,
        jump.jump / expected, vmax, pipeline.solver().stats().densityIterations,
        demanded / expected, area / (4 * std::numbers::pi * scene.radius * scene.radius), strayOil,
        strayAq);
  }
  return 0;
}
