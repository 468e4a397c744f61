// Longer interface validations that are too costly for CI, run by hand:
//   sim_interface_bench oscillation [R_mm] [d_per_R] [periods] [key=value...]  l = 2 vs Lamb
//   sim_interface_bench sessile THETA_DEG [t_end_s] [start_cos] [solver] [wall_layers] [R_per_d]
//                               [mu_Pa_s] [jitter_d] [relax_steps] [half_width_per_R] [R0_mm]
//                               [box_height_per_R] [cap|footprint] [tissue=N] [free=N] [E=Pa]
//                               [shift=auto|on|off] [density=KG_M3] [g=M_S2]
//                               [gref=KG_M3] [form=auto|corrected|symmetric]
//                                   (tissue: an elastic floor of N layers; density: the droplet's,
//                                   g: gravity towards the floor, read against Young-Laplace;
//                                   gref: gravity relative to that density (1000: the
//                                   aqueous's, as the eye scenes); form: the surface stress's
//                                   discretisation)
//                                                      sessile droplet contact angle
//   sim_interface_bench sessile-static THETA_DEG [R_per_d] [jitter_d] [half_width_per_R] [layers]
//                                      the cap fit on a static cap of exactly THETA
//   sim_interface_bench meniscus THETA_DEG [t_end_s] [H_per_d] [mu_Pa_s] [jitter_d] [depth_per_d]
//                                      the meniscus between two parallel walls (straight contact
//                                      lines)
//   sim_interface_bench ridge THETA_DEG [t_end_s] [start_deg] [R0_per_d] [mu_Pa_s] [depth_per_d]
//                                      the sessile ridge (a cylindrical droplet, straight contact
//                                      lines)
//   sim_interface_bench ridge-static THETA_DEG [R0_per_d] [jitter_d]   its fit on a static segment
//   sim_interface_bench wedge-static THETA_DEG [jitter_d]   a planar interface meeting the floor at
//                                      THETA: each stage's force on the contact line per unit
//                                      length, and the colour gradient by height above the floor
//   sim_interface_bench cavity THETA_DEG|flat [t_end_s] [Rs_per_d] [tilt_deg] [oil_density]
//                              [mu_Pa_s] [sigma_N_m] [wall_friction 0|1] [solver]
//                                      equilibrium tamponade shape in a spherical cavity
// Results and wall times go to stdout; docs/methods/interface.md records the measured numbers.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>
#include <numbers>
#include <vector>

#include "sim/effects/interfacial_tension_hu_adams2006.h"
#include "sim/effects/wall_adhesion_young.h"
#include "sim/fluid/density.h"
#include "sim/measure/droplet_pressure_jump.h"
#include "sim/measure/sessile_contact_angle.h"
#include "sim/measure/wall_nearest_material.h"
#include "tests/sim/interface_fixtures.h"
#include "tests/sim/interface_meniscus.h"
#include "tests/sim/interface_oscillation.h"
#include "tests/sim/interface_ridge.h"
#include "tests/sim/interface_sessile.h"
#include "tests/sim/sphere_wall_reading.h"
#include "tools/bench/bench_options.h"

using namespace sim;

namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Half-periods, both period estimates and the fit, against Lamb's period 2 pi / omega; Q in units
// of q0 = (3/5) eps R^2.
void printAnalysis(const testing::OscillationAnalysis& an, Real omega, Real q0) {
  const Real period = 2 * std::numbers::pi / omega;
  for (std::size_t k = 0; k < an.crossings.size(); ++k)
    std::printf("  zero crossing at t = %.4f s%s\n", an.crossings[k],
                k > 0 ? (" (half-period " +
                         std::to_string((an.crossings[k] - an.crossings[k - 1]) * 1e3) + " ms)")
                            .c_str()
                      : "");
  std::printf(
      "Lamb period %.2f ms\nzero crossings: %zu, period %.2f ms (%+.1f %%)\n"
      "damped-cosine fit: period %.2f ms (%+.1f %%), damping %.2f 1/s, amplitude %.3f of "
      "(3/5) eps R^2, mean %+.3f, drift %+.3f per period (of the same), rms %.3f\n",
      period * 1e3, an.crossings.size(), an.crossingPeriod * 1e3,
      100 * (an.crossingPeriod / period - 1), an.fittedPeriod * 1e3,
      100 * (an.fittedPeriod / period - 1), an.fit.damping, an.fit.amplitude / q0, an.fit.mean / q0,
      an.fit.drift * period / q0, an.fit.rms / q0);
}

// Re-analyses a series written with csv=FILE: R_eq [mm] (printed by the run), eps, start.
int oscillationCsv(const char* file, Real radius, Real eps, bool velocityStart) {
  FILE* f = std::fopen(file, "r");
  if (f == nullptr) return 2;
  std::vector<Real> t, q;
  char line[256];
  if (std::fgets(line, sizeof line, f) == nullptr) return 2;  // header
  double a = 0, b = 0;
  while (std::fscanf(f, "%lf,%lf", &a, &b) == 2) {
    t.push_back(a);
    q.push_back(b);
  }
  std::fclose(f);
  const Real omega = testing::lambOmega(2, 0.04, radius, 970, 1000);
  printAnalysis(testing::analyseOscillation(t, q, omega, velocityStart), omega,
                0.6 * eps * radius * radius);
  return 0;
}

// Validation 2: the l = 2 oscillation against Lamb (tests/sim/interface_oscillation.h).
// Options as key=value after the positional R_mm, d_per_R, periods: solver=indsph|wcsph,
// eps=0.05 (P2 amplitude), start=velocity|displace, relax=100 (velocity-reset steps), xsph=0,
// alpha=0.05 (WCSPH), mu=1e-3, box=2 (half-width / R), expansion=1 (INDSPH corrects expansion
// in the bulk), tol=, miniter=, maxiter=, warm=, omega= (IndsphParameters), bg=off|PA (INDSPH
// background pressure, default automatic 2 sigma / d), form=auto|corrected|symmetric (surface
// stress), csv=FILE (Q(t)).
int oscillation(testing::OscillationSpec o, const std::string& csv) {
  const Real period0 = 2 * std::numbers::pi / testing::lambOmega(2, o.sigma, o.radius, 970, 1000);
  std::printf(
      "oscillation: R = %.2f mm, d = R/%.0f, box half-width %.2f R, solver %s, eps %.3f, "
      "%s start after %d relaxation steps, mu %.1e Pa s, XSPH %.3f, alpha %.3f, bulk expansion "
      "%s; Lamb "
      "period %.2f ms (Rayleigh in vacuum %.2f ms)\n",
      o.radius * 1e3, o.perR, o.halfWidthPerR, o.solver.c_str(), o.amplitude,
      o.velocityStart ? "velocity" : "displacement", o.relaxSteps, o.mu, o.velocitySmoothing,
      o.artificialViscosity, o.bulkExpansion ? "corrected" : "clamped", period0 * 1e3,
      2 * std::numbers::pi / testing::lambOmega(2, o.sigma, o.radius, 970, 0) * 1e3);
  std::fflush(stdout);
  const testing::OscillationRun run = testing::runOscillation(o, true);
  const Real period = 2 * std::numbers::pi / run.omega;
  if (!csv.empty()) {
    FILE* f = std::fopen(csv.c_str(), "w");
    if (f == nullptr) {
      std::fprintf(stderr, "oscillation: cannot write csv=%s (check the folder exists)\n",
                   csv.c_str());
      return 1;
    }
    std::fprintf(f, "t_s,Q_m2\n");
    for (std::size_t k = 0; k < run.t.size(); ++k)
      std::fprintf(f, "%.6e,%.6e\n", run.t[k], run.q[k]);
    std::fclose(f);
  }
  const testing::OscillationAnalysis an =
      testing::analyseOscillation(run.t, run.q, run.omega, o.velocityStart);
  printAnalysis(an, run.omega, run.q0);
  const Real beta = testing::irrotationalDamping(2, run.radius, 970, 1000, o.mu, o.mu);
  const Real layer =
      testing::interfaceLayerDamping(2, run.radius, 970, 1000, o.mu, 1000, run.omega);
  std::printf(
      "R_eq %.3f mm, %zu particles; Lamb period %.2f ms\n"
      "viscous damping (mu %.1e): irrotational %.2f 1/s, + interface shear layer (estimate) "
      "%.2f 1/s = %.2f 1/s; free drop 5 nu / R^2 = %.2f 1/s\n"
      "%ld relaxation + %ld steps (%.1f pressure iterations per step), wall %.1f s\n",
      run.radius * 1e3, run.particles, period * 1e3, o.mu, beta, layer, beta + layer,
      5 * o.mu / 970 / (run.radius * run.radius), run.relaxSteps, run.steps, run.meanIterations,
      run.wallSeconds);
  return 0;
}

int sessile(const testing::SessileCase& c) {
  testing::SessileCase run = c;
  run.print = true;
  const testing::SessileResult r = testing::runSessile(run);
  std::printf(
      "sessile: requested %.1f deg, start %.1f deg, %s, %d wall layers, d = R/%.0f: "
      "measured %.1f deg by the %s (mean of the last fifth; %.1f at the end) after %.3f s; %zu "
      "particles, %ld steps, wall %.1f s%s\n",
      c.theta, std::acos(-c.startCos) * 180 / std::numbers::pi, c.solver.c_str(), c.wallLayers,
      c.perR, r.angle,
      c.footprint ? "footprint" : (c.gravity > 0 ? "Young-Laplace outline fit" : "cap fit"),
      r.finalAngle, c.tEnd, r.particles, r.steps, r.seconds, r.finite ? "" : " (NOT FINITE)");
  if (c.gravity > 0)
    std::printf(
        "  shape fit with c free (mean of the last fifth): %.1f deg, sigma_eff / sigma %.3f\n",
        r.shapeAngle, r.shapeSigmaRatio);
  return r.finite ? 0 : 1;
}

// One stage's accelerations alone on a static scene (densities already set): the stage is
// attached and applied once, every other contribution zeroed first.
void applyStageAlone(World& w, Effect& stage) {
  stage.attach(w);
  for (auto& a : w.particles.a) a.setZero();
  stage.apply(w, StepContext{1e-4});
}

// The measurement alone: a static cap of exactly THETA (the lattice sites inside the sphere cap
// are oil), no step, read by fitSessileCap with several exclusion heights above the floor.
int sessileStatic(const testing::SessileCase& c) {
  testing::SessileCase run = c;
  run.startCos = -std::cos(c.theta * std::numbers::pi / 180);
  auto scene = testing::sessileScene(run);
  const World& w = *scene.world;
  const Real d = w.particleSpacing();
  const WallPlane floor{Vec3(0, scene.floorHeight, 0), Vec3::UnitY()};
  std::printf("static cap %.1f deg, d = R0/%.0f, jitter %.2f d, %zu particles\n", c.theta, c.perR,
              c.jitter, w.particles.size());
  for (const Real exclude : {0.0, 0.5, 1.0, 1.5}) {
    const CapFit fit = fitSessileCap(w, scene.oil, floor, exclude * d);
    std::vector<Vec3> points = interfacePairMidpoints(w, scene.oil);
    std::erase_if(points, [&](const Vec3& x) { return x.y() < exclude * d; });
    const SphereFit geo = fitSphereGeometric(points, fit.sphere);
    const Real geoAngle = std::acos(std::clamp(-geo.centre.y() / geo.radius, Real(-1), Real(1))) *
                          180 / std::numbers::pi;
    std::printf(
        "  exclude %.1f d: volume cap %.2f deg (R = %.3f mm); free sphere: algebraic "
        "%.2f deg (R = %.3f mm, rms %.3f mm), geometric %.2f deg (R = %.3f mm); %zu "
        "points\n",
        exclude, fit.contactAngle, fit.capRadius * 1e3, fit.sphereAngle, fit.sphere.radius * 1e3,
        fit.sphere.rmsResidual * 1e3, geoAngle, geo.radius * 1e3, fit.points.size());
  }
  // Static forces on the cap as built (densities by summation), each stage alone: the radial
  // sums sum_i m_i a_i.e_r over the particles within `reach` of the axis. Exact cap of radius R,
  // angle theta, base a = R sin(theta): Young's wall line force is +2 pi a sigma cos(theta). The
  // tension's sum is printed against -2 pi sigma R theta, the sharp stress sigma (I - n n) delta
  // truncated at the wall; it is a comparison between angles only, not a closed form for this
  // discretisation (the stress form's isotropic part sigma |gradC| / 3 and the wall mirror both
  // add to it), so the contact-line pull is not separated from it.
  World& mw = *scene.world;
  const Real sigma = 0.04, theta = c.theta * std::numbers::pi / 180, u = std::cos(theta);
  const Real capRadius = c.r0 * std::cbrt(2.0 / ((2 + u) * (1 - u) * (1 - u)));
  const Real base = capRadius * std::sin(theta);
  const Vec3 centre(scene.centre.x(), scene.floorHeight, scene.centre.z());
  // Within a + 3 h of the axis, as the hemisphere unit test: the layer's other end, at the
  // floor's edge, stays outside when the box is wide enough (half-width 3 R0 for 30 deg).
  const Real reach = base + 3 * mw.supportRadius();
  auto radialSum = [&] {
    Real f = 0;
    for (Index i = 0; i < mw.particles.size(); ++i) {
      Vec3 r = mw.particles.x[i] - centre;
      r.y() = 0;
      if (r.norm() == 0 || r.norm() > reach) continue;
      f += mw.particles.mass[i] * mw.particles.a[i].dot(r.normalized());
    }
    return f;
  };
  computeDensities(mw, mw.particles.density);
  WallAdhesionYoung adhesion;
  applyStageAlone(mw, adhesion);
  const Real wallForce = radialSum();
  InterfacialTensionHuAdams2006 tension;
  applyStageAlone(mw, tension);
  const Real tensionForce = radialSum();
  const Real line = 2 * std::numbers::pi * base * sigma * u;
  std::printf("  wall line force %.4e N = %.3f x 2 pi a sigma cos(theta) (a = %.2f mm)\n",
              wallForce, wallForce / line, base * 1e3);
  std::printf("  tension radial sum %.4e N = %.3f x -2 pi sigma R theta\n", tensionForce,
              tensionForce / (-2 * std::numbers::pi * sigma * capRadius * theta));
  return 0;
}

// A planar interface meeting the floor at THETA (through the oil) along the line x = x0, y = 0:
// the static lattice, no step, densities by summation. Prints, per unit length of contact line and
// over sigma, the tangential force (along +x, away from the oil's side at 90 deg) that each stage
// puts on the particles within `reach` of the contact line (middle of the depth only). A sharp
// interface pulls the line region with +sigma cos(theta) (along the interface); Young's wall line
// force is -sigma cos(theta_Y). Their sum on the static wedge is what moves the line.
int wedgeStatic(Real thetaDeg, Real jitter) {
  const Real d = 0.0005, h = 2 * d;
  const Real theta = thetaDeg * std::numbers::pi / 180;
  const int nx = 70, ny = 16, nz = 20;
  TankSpec spec;
  spec.innerMin = Vec3::Zero();
  spec.innerMax = Vec3(nx * d, ny * d, nz * d);
  spec.closedTop = true;
  testing::OilAqueousBox box = testing::oilAqueousLayeredBox(spec, d, 0.005);
  World& w = *box.world;
  const int oil = box.oil, aqueous = box.aqueous;
  const Real sigma = w.materials.interfacialTensions().front().sigma;  // [N/m]
  for (std::size_t b = 0; b < w.walls.size(); ++b)
    if (w.walls.normal[b].y() < -0.5) w.walls.tag[b] = testing::kFloorTag;
  const Real x0 = 0.5 * nx * d;
  testing::fillJitteredLattice(w, Vec3::Zero(), nx, ny, nz, d, jitter, 0.0, [&](const Vec3& x) {
    return -std::sin(theta) * (x.x() - x0) + std::cos(theta) * x.y() <= 0 ? oil : aqueous;
  });
  w.materials.setContactAngle(oil, testing::kFloorTag, thetaDeg);
  w.initialize();
  computeDensities(w, w.particles.density);
  const Real zLow = 3 * h, zHigh = nz * d - 3 * h;
  auto lineForce = [&](Real reach) {
    Vec3 f = Vec3::Zero();
    for (Index i = 0; i < w.particles.size(); ++i) {
      const Vec3& x = w.particles.x[i];
      if (x.z() < zLow || x.z() > zHigh || std::hypot(x.x() - x0, x.y()) > reach) continue;
      f += w.particles.mass[i] * w.particles.a[i];
    }
    return Vec3(f / ((zHigh - zLow) * sigma));
  };
  std::printf(
      "static wedge %.1f deg, jitter %.2f d, %zu particles; forces per unit line length / "
      "sigma (x: along the floor, y: normal), cos(theta) = %.4f\n",
      thetaDeg, jitter, w.particles.size(), std::cos(theta));
  // One stage alone on the static wedge; `youngSign` +1 compares with sigma cos(theta) (the
  // interface's pull), -1 with Young's wall force -sigma cos(theta).
  auto applyAlone = [&](Effect& stage, const char* label, Real youngSign) {
    applyStageAlone(w, stage);
    for (const Real reach : {2 * h, 3 * h, 4 * h}) {
      const Vec3 f = lineForce(reach);
      std::printf("  %s within %.0f h: x %+.4f (%.3f x %scos theta), y %+.4f\n", label, reach / h,
                  f.x(), youngSign * f.x() / std::cos(theta), youngSign > 0 ? "" : "-", f.y());
    }
  };
  InterfacialTensionHuAdams2006 tension;
  applyAlone(tension, "tension", 1);
  // The colour gradient by height above the floor: interface strength sum V |gradC| per unit
  // depth and height, times sin(theta) (1 for a sharp interface crossing the slab), and the
  // interface angle read from the normal, acos |n_y| (the sharp wedge: acos |cos theta|).
  const auto& gradC = w.particles.fields.get<Vec3>(field::kColourGradient);
  for (int slab = 0; slab < 8; ++slab) {
    Real strength = 0, angle = 0;  // [1/m^2 ...] sum V |gradC|, and its angle-weighted sum
    for (Index i = 0; i < w.particles.size(); ++i) {
      const Vec3& x = w.particles.x[i];
      if (x.z() < zLow || x.z() > zHigh || x.y() < slab * d || x.y() >= (slab + 1) * d) continue;
      const Real g = gradC[i].norm();
      if (g == 0) continue;
      const Real v = w.particles.mass[i] / w.particles.density[i];
      strength += v * g;
      angle += v * g * std::acos(std::min<Real>(1, std::abs(gradC[i].y()) / g));
    }
    std::printf(
        "  slab y in [%d, %d) d: interface strength %.3f, normal reads %.1f deg (sharp %.1f)\n",
        slab, slab + 1, strength / ((zHigh - zLow) * d) * std::sin(theta),
        strength > 0 ? angle / strength * 180 / std::numbers::pi : 0.0,
        std::acos(std::abs(std::cos(theta))) * 180 / std::numbers::pi);
  }
  WallAdhesionYoung adhesion;
  applyAlone(adhesion, "wall_adhesion", -1);
  return 0;
}

// The coverage read below the spacing (sim/measure/wall_oil_extended.h) with the interface taken
// 1.25 to 4 spacings from the wall: how far from the wall the run's interface departs from the
// closed form (docs/validation.md, open limits). `thetaOil` [deg] through the oil.
void printExtendedCoverage(const World& w, const testing::CavityScene& scene, Real rs,
                           Real thetaOil) {
  const Real d = w.particleSpacing();
  const testref::SphereWallReading reading(rs, d);
  std::vector<std::uint8_t> isOil(w.particles.size());
  for (Index i = 0; i < w.particles.size(); ++i) isOil[i] = w.particles.material[i] == scene.oil;
  reading.printCoverageByOffset(w.particles.x, isOil, (180 - thetaOil) * std::numbers::pi / 180);
}

// Validation 5 (tests/sim/interface_cavity.cpp runs the same scenes for the CI): the oil starts
// as a flat cut of volume fraction 0.3 (tilted by `tiltDeg` from the +y axis) in a spherical
// cavity; mode "lens": sigma 0.04 N/m, contact angle THETA through oil, no gravity; mode "flat":
// no tension, gravity -y, oil density `oilDensity`.
int cavity(bool lens, Real theta, Real tEnd, Real perR, Real tiltDeg, Real oilDensity, Real mu,
           Real sigma, bool friction, const char* solver) {
  testing::CavitySpec s;
  s.cavityRadius = 0.003;
  s.spacing = s.cavityRadius / perR;
  Real v = 0.3;
  if (const char* e = std::getenv("TAMP_CAV_V")) v = std::atof(e);
  s.oilOffset = s.cavityRadius * (1 - 2 * testing::flatCoverage(v));
  const Real tilt = tiltDeg * std::numbers::pi / 180;
  s.oilAxis = Vec3(std::sin(tilt), std::cos(tilt), 0);
  if (const char* e = std::getenv("TAMP_CAV_LAYERS")) s.latticeWallLayers = std::atoi(e);
  // tilt < 0: a vertical column of the same volume fraction, 1 - (1 - a^2)^(3/2) = v
  if (tiltDeg < 0) {
    s.oilAxis = Vec3::UnitY();
    s.oilColumnRadius = s.cavityRadius * std::sqrt(1 - std::pow(1 - v, 2.0 / 3.0));
  }
  // WCSPH: 2 % excess keeps the Tait clamp at p = 0 from acting; an incompressible solver needs
  // rest mass in the closed cavity (the excess could never leave it).
  s.massExcess = std::strcmp(solver, "wcsph") == 0 ? 0.02 : 0.0;
  PipelineOptions options;
  options.solver = solver;
  options.wallFriction = friction;
  options.wcsph.artificialViscosity = 0.1;
  s.sigma = sigma;
  s.viscosity = mu;
  if (lens) {
    options.wcsph.speedOfSound = 2;
  } else {
    s.gravity = Vec3(0, -9.81, 0);
    s.oilDensity = oilDensity;
    options.wcsph.speedOfSound = 3;
  }
  auto scene = testing::cavityScene(s);
  World& w = *scene.world;
  if (lens) w.materials.setContactAngle(scene.oil, 0, theta);
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  const Real expected = lens ? testing::lensCoverage(scene.oilVolumeFraction, theta).coverage
                             : testing::flatCoverage(scene.oilVolumeFraction);
  std::printf(
      "cavity %s: Rs %.1f mm, d = Rs/%.0f, %zu fluid + %zu wall particles, oil fraction "
      "%.4f, closed-form coverage %.4f (flat start %.4f)\n",
      lens ? "lens" : "flat", s.cavityRadius * 1e3, perR, w.particles.size(), w.walls.size(),
      scene.oilVolumeFraction, expected, testing::flatCoverage(scene.oilVolumeFraction));
  const auto t0 = std::chrono::steady_clock::now();
  Real next = 0;
  while (w.time < tEnd) {
    pipeline.step(w);
    if (w.time >= next) {
      const auto m = testing::measureCavity(scene, s.cavityRadius);
      const Vec3 c = centreOfMaterial(w, scene.oil);
      std::printf(
          "  t = %.4f s  coverage %.4f (Shepard %.4f, dry %.4f)  angle %.1f deg  oil centre "
          "(%.2f %.2f %.2f) mm  wall %.1f s\n",
          w.time, m.coverage, m.shepardCoverage, m.dry, m.angle, c.x() * 1e3, c.y() * 1e3,
          c.z() * 1e3, seconds(t0));
      std::fflush(stdout);
      next += tEnd / 20;
    }
  }
  if (lens) printExtendedCoverage(w, scene, s.cavityRadius, theta);
  // The bulk interface against hydrostatics: mean height of the interface points within Rs/2 of
  // the axis, relative to the centre of volume of all the fluid, over the radius of a sphere of
  // the fluid's rest volume; a flat interface of oil fraction v sits at 1 - 2 flatCoverage(v).
  {
    Real ySum = 0;
    int count = 0;
    for (const Vec3& x : interfacePairMidpoints(w, scene.oil))
      if (std::hypot(x.x(), x.z()) < 0.5 * s.cavityRadius) {
        ySum += x.y();
        ++count;
      }
    Vec3 centre = Vec3::Zero();
    Real volume = 0;
    for (Index i = 0; i < w.particles.size(); ++i) {
      centre += w.restVolumeOf(i) * w.particles.x[i];
      volume += w.restVolumeOf(i);
    }
    centre /= volume;
    const Real rEff = std::cbrt(3 * volume / (4 * std::numbers::pi));
    std::printf(
        "bulk interface at y = %.3f mm (%d points), fluid centre y = %.3f mm, R_eff = %.3f "
        "mm: (y - c) / R_eff = %.3f, hydrostatics %.3f\n",
        count ? ySum / count * 1e3 : 0.0, count, centre.y() * 1e3, rEff * 1e3,
        count ? (ySum / count - centre.y()) / rEff : 0.0,
        1 - 2 * testing::flatCoverage(scene.oilVolumeFraction));
  }
  // Where the contact line lies on the wall: histogram of nearest-oil wall particles by height.
  {
    const std::vector<int> nearest = wallNearestMaterial(w);
    const int bins = static_cast<int>(2 * perR);
    std::vector<int> oilWall(bins, 0), allWall(bins, 0);
    for (std::size_t b = 0; b < nearest.size(); ++b) {
      const int k = std::clamp(static_cast<int>((w.walls.x[b].y() + s.cavityRadius) / s.spacing), 0,
                               bins - 1);
      ++allWall[k];
      if (nearest[b] == scene.oil) ++oilWall[k];
    }
    for (int k = bins - 1; k >= 0; --k)
      std::printf("  wall y = %+.2f mm: %3d of %3d nearest oil\n",
                  (-s.cavityRadius + (k + 0.5) * s.spacing) * 1e3, oilWall[k], allWall[k]);
  }
  // Final layering: oil and aqueous particle counts and mean density per slab of height d along y.
  const int slabs = static_cast<int>(2 * perR);
  std::vector<int> oilCount(slabs, 0), aqueousCount(slabs, 0);
  for (Index i = 0; i < w.particles.size(); ++i) {
    const int k = std::clamp(static_cast<int>((w.particles.x[i].y() + s.cavityRadius) / s.spacing),
                             0, slabs - 1);
    (w.particles.material[i] == scene.oil ? oilCount : aqueousCount)[k]++;
  }
  for (int k = slabs - 1; k >= 0; --k)
    std::printf("  y = %+.2f mm: %4d oil %4d aqueous\n",
                (-s.cavityRadius + (k + 0.5) * s.spacing) * 1e3, oilCount[k], aqueousCount[k]);
  std::printf("%ld steps, wall %.1f s\n", w.stepCount, seconds(t0));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "oscillation") == 0) {
    testing::OscillationSpec o;
    std::string csv;
    int positional = 0;
    for (int k = 2; k < argc; ++k) {
      const char* eq = std::strchr(argv[k], '=');
      if (eq == nullptr) {
        const Real v = std::atof(argv[k]);
        if (positional == 0) o.radius = v * 1e-3;
        if (positional == 1) o.perR = v;
        if (positional == 2) o.periods = v;
        ++positional;
        continue;
      }
      const std::string key(static_cast<const char*>(argv[k]), eq), value(eq + 1);
      if (key == "solver")
        o.solver = value;
      else if (key == "eps")
        o.amplitude = std::atof(value.c_str());
      else if (key == "start")
        o.velocityStart = value == "velocity";
      else if (key == "relax")
        o.relaxSteps = std::atoi(value.c_str());
      else if (key == "xsph")
        o.velocitySmoothing = std::atof(value.c_str());
      else if (key == "alpha")
        o.artificialViscosity = std::atof(value.c_str());
      else if (key == "mu")
        o.mu = std::atof(value.c_str());
      else if (key == "box")
        o.halfWidthPerR = std::atof(value.c_str());
      else if (key == "csv")
        csv = value;
      else if (key == "expansion")
        o.bulkExpansion = value != "0";
      else if (key == "tol")
        o.indsph.tolerance = std::atof(value.c_str());
      else if (key == "miniter")
        o.indsph.minIterations = std::atoi(value.c_str());
      else if (key == "maxiter")
        o.indsph.maxIterations = std::atoi(value.c_str());
      else if (key == "warm")
        o.indsph.warmStartFactor = std::atof(value.c_str());
      else if (key == "omega")
        o.indsph.relaxation = std::atof(value.c_str());
      else if (key == "dtmax")
        o.maxTimeStep = std::atof(value.c_str());
      else if (key == "jitter")
        o.jitter = std::atof(value.c_str());
      else if (key == "divergence")
        o.indsph.divergenceSolve = value != "0";
      else if (key == "excess")
        o.massExcess = std::atof(value.c_str());
      else if (key == "relaxfactor")
        o.relaxVelocityFactor = std::atof(value.c_str());
      else if (key == "bg")
        o.backgroundPressure = value == "off" ? 0.0 : std::atof(value.c_str());
      else if (key == "form")
        o.surfaceStress = surfaceStressFormFromName(value);
      else {
        std::fprintf(stderr, "unknown oscillation option '%s'\n", argv[k]);
        return 2;
      }
    }
    return oscillation(o, csv);
  }
  if (argc >= 6 && std::strcmp(argv[1], "oscillation-csv") == 0)
    return oscillationCsv(argv[2], std::atof(argv[3]) * 1e-3, std::atof(argv[4]),
                          std::strcmp(argv[5], "velocity") == 0);
  if (argc >= 3 && std::strcmp(argv[1], "sessile-static") == 0) {
    testing::SessileCase c;
    c.theta = std::atof(argv[2]);
    if (argc > 3) c.perR = std::atof(argv[3]);
    if (argc > 4) c.jitter = std::atof(argv[4]);
    if (argc > 5) c.halfWidthPerR = std::atof(argv[5]);
    c.wallLayers = argc > 6 ? std::atoi(argv[6]) : 3;  // 0: one Akinci layer (the eye scenes')
    c.solver = "indsph";  // the [contact_angle] set-up: rest mass, no excess
    return sessileStatic(c);
  }
  if (argc >= 3 && std::strcmp(argv[1], "sessile") == 0) {
    testing::SessileCase c;
    // key=value options anywhere after the mode; the rest are positional.
    std::vector<char*> positional;
    for (int k = 0; k < argc; ++k) {
      const std::string a = argv[k];
      const auto eq = a.find('=');
      if (k < 2 || eq == std::string::npos) {
        positional.push_back(argv[k]);
        continue;
      }
      const std::string key = a.substr(0, eq), value = a.substr(eq + 1);
      if (key == "tissue")
        c.tissueFloorLayers = std::atoi(value.c_str());
      else if (key == "free")
        c.tissueFreeLayers = std::atoi(value.c_str());
      else if (key == "E")
        c.tissueYoungsModulus = std::atof(value.c_str());
      else if (key == "density")
        c.dropletDensity = std::atof(value.c_str());
      else if (key == "g")
        c.gravity = std::atof(value.c_str());
      else if (key == "shift")
        c.backgroundPressure = value == "off"  ? StageOverride::kOff
                               : value == "on" ? StageOverride::kOn
                                               : StageOverride::kAuto;
      else if (key == "gref" || key == "form") {
        try {
          if (key == "gref")
            c.gravityReferenceDensity = testing::benchNumber(key, value, 0, 1e5);
          else
            c.surfaceStress = testing::benchSurfaceStressForm(value);
        } catch (const std::invalid_argument& e) {
          std::fprintf(stderr, "sessile: %s\n", e.what());
          return 2;
        }
      } else {
        std::fprintf(stderr,
                     "sessile: unknown option '%s' (tissue=N free=N E=Pa shift=auto|on|off "
                     "density=KG_M3 g=M_S2 gref=KG_M3 form=auto|corrected|symmetric)\n",
                     a.c_str());
        return 2;
      }
    }
    argc = static_cast<int>(positional.size());
    argv = positional.data();
    c.theta = std::atof(argv[2]);
    if (argc > 3) c.tEnd = std::atof(argv[3]);
    if (argc > 4) c.startCos = std::atof(argv[4]);
    if (argc > 5) c.solver = argv[5];
    if (argc > 6) c.wallLayers = std::atoi(argv[6]);
    if (argc > 7) c.perR = std::atof(argv[7]);
    if (argc > 8) c.viscosity = std::atof(argv[8]);
    if (argc > 9) c.jitter = std::atof(argv[9]);
    if (argc > 10) c.relaxSteps = std::atoi(argv[10]);
    if (argc > 11) c.halfWidthPerR = std::atof(argv[11]);
    if (argc > 12) c.r0 = std::atof(argv[12]) * 1e-3;
    if (argc > 13) c.boxHeightPerR = std::atof(argv[13]);
    if (argc > 14) c.footprint = std::strcmp(argv[14], "footprint") == 0;
    return sessile(c);
  }
  if (argc >= 3 && std::strcmp(argv[1], "meniscus") == 0) {
    testing::MeniscusCase c;
    c.theta = std::atof(argv[2]);
    if (argc > 3) c.tEnd = std::atof(argv[3]);
    if (argc > 4) c.gapPerD = std::atof(argv[4]);
    if (argc > 5) c.viscosity = std::atof(argv[5]);
    if (argc > 6) c.jitter = std::atof(argv[6]);
    if (argc > 7) c.depthPerD = std::atof(argv[7]);
    const testing::MeniscusResult r = testing::runMeniscus(c);
    std::printf(
        "meniscus: requested %.1f deg, H = %.0f d: measured %.1f deg (mean of the last "
        "fifth; %.1f at the end) after %.3f s; %zu particles, %ld steps, wall %.1f s%s\n",
        c.theta, c.gapPerD, r.angle, r.finalAngle, c.tEnd, r.particles, r.steps, r.seconds,
        r.finite ? "" : " (NOT FINITE)");
    return r.finite ? 0 : 1;
  }
  if (argc >= 3 && std::strcmp(argv[1], "ridge") == 0) {
    testing::RidgeCase c;
    c.theta = std::atof(argv[2]);
    c.print = true;
    if (argc > 3) c.tEnd = std::atof(argv[3]);
    c.startTheta = argc > 4 ? std::atof(argv[4]) : c.theta;
    if (argc > 5) c.r0PerD = std::atof(argv[5]);
    if (argc > 6) c.viscosity = std::atof(argv[6]);
    if (argc > 7) c.depthPerD = std::atof(argv[7]);
    const testing::RidgeResult r = testing::runRidge(c);
    std::printf(
        "ridge: requested %.1f deg, start %.1f deg, R0 = %.0f d, depth %.0f d: measured "
        "%.1f deg (mean of the last fifth; %.1f at the end) after %.3f s; %zu particles, "
        "%ld steps, wall %.1f s%s\n",
        c.theta, c.startTheta, c.r0PerD, c.depthPerD, r.angle, r.finalAngle, c.tEnd, r.particles,
        r.steps, r.seconds, r.finite ? "" : " (NOT FINITE)");
    return r.finite ? 0 : 1;
  }
  if (argc >= 3 && std::strcmp(argv[1], "wedge-static") == 0)
    return wedgeStatic(std::atof(argv[2]), argc > 3 ? std::atof(argv[3]) : 0);
  if (argc >= 3 && std::strcmp(argv[1], "ridge-static") == 0) {
    testing::RidgeCase c;
    c.theta = c.startTheta = std::atof(argv[2]);
    if (argc > 3) c.r0PerD = std::atof(argv[3]);
    c.jitter = argc > 4 ? std::atof(argv[4]) : 0;
    const testing::RidgeScene scene = testing::ridgeScene(c);
    const testing::RidgeFit f = testing::fitRidge(*scene.world, scene.oil, scene.depth);
    std::printf(
        "static ridge %.1f deg, R0 = %.0f d, jitter %.2f d: fit %.2f deg (R = %.2f mm, rms "
        "%.3f mm, %zu points), %zu particles\n",
        c.theta, c.r0PerD, c.jitter, f.angle, f.radius * 1e3, f.rms * 1e3, f.points,
        scene.world->particles.size());
    return 0;
  }
  if (argc >= 3 && std::strcmp(argv[1], "cavity") == 0)
    return cavity(std::strcmp(argv[2], "flat") != 0, std::atof(argv[2]),
                  argc > 3 ? std::atof(argv[3]) : 0.1, argc > 4 ? std::atof(argv[4]) : 8,
                  argc > 5 ? std::atof(argv[5]) : 0, argc > 6 ? std::atof(argv[6]) : 700,
                  argc > 7 ? std::atof(argv[7]) : 0.005, argc > 8 ? std::atof(argv[8]) : 0.04,
                  argc > 9 && std::atoi(argv[9]) != 0, argc > 10 ? argv[10] : "wcsph");
  std::fprintf(
      stderr,
      "usage: sim_interface_bench oscillation [R_mm] [d_per_R] [periods] [solver=indsph|wcsph] "
      "[eps=0.05] [start=velocity|displace] [relax=100] [xsph=0] [alpha=0.05] [mu=1e-3] [box=2] "
      "[expansion=1] [tol=1e-4] [miniter=2] [maxiter=100] [warm=0.5] [omega=0.5] [dtmax=S] "
      "[jitter=0] [divergence=1] [excess=E] [relaxfactor=0] [bg=off|PA] "
      "[form=auto|corrected|symmetric] [csv=FILE]\n"
      "       sim_interface_bench oscillation-csv FILE R_eq_mm eps velocity|displace\n"
      "       sim_interface_bench sessile THETA_DEG [t_end_s] [start_cos] [solver] [wall_layers] "
      "[R_per_d] [mu_Pa_s] [jitter_d] [relax_steps] [half_width_per_R] [R0_mm] "
      "[box_height_per_R] [cap|footprint] [tissue=N] [free=N] [E=Pa] [shift=auto|on|off]\n"
      "       sim_interface_bench sessile-static THETA_DEG [R_per_d] [jitter_d] "
      "[half_width_per_R] [layers]\n"
      "       sim_interface_bench meniscus THETA_DEG [t_end_s] [H_per_d] [mu_Pa_s] [jitter_d] "
      "[depth_per_d]\n"
      "       sim_interface_bench ridge THETA_DEG [t_end_s] [start_deg] [R0_per_d] [mu_Pa_s] "
      "[depth_per_d]\n"
      "       sim_interface_bench ridge-static THETA_DEG [R0_per_d] [jitter_d]\n"
      "       sim_interface_bench wedge-static THETA_DEG [jitter_d]\n"
      "       sim_interface_bench cavity THETA_DEG|flat [t_end_s] [Rs_per_d] [tilt_deg] "
      "[oil_density] [mu_Pa_s] [sigma_N_m] [wall_friction] [solver]\n");
  return 2;
}
