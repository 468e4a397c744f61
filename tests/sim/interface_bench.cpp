// Longer interface validations (issue 6) that are too costly for CI, run by hand:
//   sim_interface_bench oscillation [R_mm] [d_per_R] [periods]  l = 2 oscillation vs Lamb
//   sim_interface_bench sessile THETA_DEG [t_end_s] [start_cos] [solver] [wall_layers] [R_per_d]
//                               [mu_Pa_s] [jitter_d] [relax_steps] [half_width_per_R]
//                                                      sessile droplet contact angle
//   sim_interface_bench cavity THETA_DEG|flat [t_end_s] [Rs_per_d] [tilt_deg] [oil_density]
//                              [mu_Pa_s] [sigma_N_m] [wall_friction 0|1] [solver]
//                                      equilibrium tamponade shape in a spherical cavity
// Results and wall times go to stdout; docs/interface.md records the measured numbers.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include <Eigen/Dense>
#include <numbers>
#include <vector>

#include "interface_fixtures.h"
#include "interface_sessile.h"
#include "sim/measure/droplet_pressure_jump.h"
#include "sim/measure/sessile_contact_angle.h"
#include "sim/measure/wall_nearest_material.h"

using namespace sim;

namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Shape moment of the oil: Q = <y^2> - (<x^2> + <z^2>) / 2 about its centre [m^2]; it follows
// the P2 amplitude of the droplet's shape.
Real shapeMoment(const World& w, int oil) {
  const Vec3 c = centreOfMaterial(w, oil);
  Real q = 0;
  int n = 0;
  for (Index i = 0; i < w.particles.size(); ++i)
    if (w.particles.material[i] == oil) {
      const Vec3 r = w.particles.x[i] - c;
      q += r.y() * r.y() - 0.5 * (r.x() * r.x() + r.z() * r.z());
      ++n;
    }
  return q / n;
}

int oscillation(Real radius, Real perR, Real kPeriods) {
  testing::DropletSpec s;
  s.radius = radius;
  s.spacing = radius / perR;
  s.halfWidth = 2 * radius;
  s.sigma = 0.04;
  s.oilViscosity = s.aqueousViscosity = 1e-3;  // water-like: damping 5 nu / R^2 << omega
  s.massExcess = 0.05;
  s.p2Amplitude = 0.15;
  auto scene = testing::dropletScene(s);
  World& w = *scene.world;
  const Real rhoI = 970, rhoO = 1000;
  // Lamb (1932, Hydrodynamics, section 275): a drop of density rhoI in a liquid of density rhoO,
  //   omega_l^2 = l (l+1) (l-1) (l+2) sigma / (R^3 ((l+1) rhoI + l rhoO));
  // with rhoO = 0 it is Rayleigh's l (l-1) (l+2) sigma / (rhoI R^3).
  const Real R = scene.radius;
  const Real omega = std::sqrt(24 * s.sigma / (R * R * R * (3 * rhoI + 2 * rhoO)));
  const Real period = 2 * std::numbers::pi / omega;
  PipelineOptions options;
  options.solver = "wcsph";
  options.wcsph.speedOfSound = 12 * std::sqrt(2 * s.sigma / R / 1000);
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  std::printf("oscillation: R = %.2f mm, d = R/%.0f, %zu particles, sigma %.3f N/m, Lamb period "
              "%.2f ms (Rayleigh in vacuum %.2f ms)\n",
              R * 1e3, perR, w.particles.size(), s.sigma, period * 1e3,
              2 * std::numbers::pi / std::sqrt(8 * s.sigma / (rhoI * R * R * R)) * 1e3);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Real> times, q;
  while (w.time < kPeriods * period) {
    pipeline.step(w);
    times.push_back(w.time);
    q.push_back(shapeMoment(w, scene.oil));
  }
  for (std::size_t k = 0; k < q.size(); k += q.size() / 40)
    std::printf("  t = %.4f s  Q = %+.3e m^2\n", times[k], q[k]);
  // Least-squares fit Q(t) = a + b t + exp(-g t) (c cos(w t) + e sin(w t)) over a grid of (w, g),
  // linear in (a, b, c, e): the drift term absorbs the slow relaxation of the lattice droplet's
  // mean shape, the damping the viscous and artificial dissipation.
  Real bestW = 0, bestG = 0, bestResidual = std::numeric_limits<Real>::infinity();
  for (int iw = 0; iw <= 200; ++iw) {
    const Real wTry = omega * (0.5 + iw / 200.0);
    for (int ig = 0; ig <= 30; ++ig) {
      const Real gTry = ig / 30.0 * 3.0 / period;
      Eigen::Matrix4d ata = Eigen::Matrix4d::Zero();
      Eigen::Vector4d atb = Eigen::Vector4d::Zero();
      for (std::size_t k = 0; k < q.size(); ++k) {
        const Real e = std::exp(-gTry * times[k]);
        const Eigen::Vector4d row(1, times[k] / period, e * std::cos(wTry * times[k]),
                                  e * std::sin(wTry * times[k]));
        ata += row * row.transpose();
        atb += row * q[k];
      }
      const Eigen::Vector4d c = ata.ldlt().solve(atb);
      Real residual = 0;
      for (std::size_t k = 0; k < q.size(); ++k) {
        const Real e = std::exp(-gTry * times[k]);
        const Real model = c[0] + c[1] * times[k] / period +
                           e * (c[2] * std::cos(wTry * times[k]) + c[3] * std::sin(wTry * times[k]));
        residual += (q[k] - model) * (q[k] - model);
      }
      if (residual < bestResidual) {
        bestResidual = residual;
        bestW = wTry;
        bestG = gTry;
      }
    }
  }
  // Extrema of a running mean over +-30 samples: the first period read directly (max to max).
  std::vector<Real> extremaTimes;
  const std::size_t halfWindow = 30;
  std::vector<Real> smooth(q.size(), 0);
  for (std::size_t k = halfWindow; k + halfWindow < q.size(); ++k) {
    for (std::size_t j = k - halfWindow; j <= k + halfWindow; ++j) smooth[k] += q[j];
    smooth[k] /= 2 * halfWindow + 1;
  }
  for (std::size_t k = halfWindow + 1; k + halfWindow + 1 < q.size(); ++k)
    if ((smooth[k] - smooth[k - 1]) * (smooth[k + 1] - smooth[k]) < 0) {
      extremaTimes.push_back(times[k]);
      std::printf("  extremum at t = %.4f s (Q = %+.3e m^2)\n", times[k], smooth[k]);
    }
  const Real measured = 2 * std::numbers::pi / bestW;
  std::printf("fitted period %.2f ms (damping %.1f 1/s), Lamb %.2f ms: %+.1f %%; %ld steps, "
              "wall %.1f s\n",
              measured * 1e3, bestG, period * 1e3, 100 * (measured / period - 1), w.stepCount,
              seconds(t0));
  return 0;
}

int sessile(const testing::SessileCase& c) {
  testing::SessileCase run = c;
  run.print = true;
  const testing::SessileResult r = testing::runSessile(run);
  std::printf(
      "sessile: requested %.1f deg, start %.1f deg, %s, %d wall layers, d = R/%.0f: "
      "measured %.1f deg (mean of the last fifth; %.1f at the end) after %.3f s; %zu "
      "particles, %ld steps, wall %.1f s%s\n",
      c.theta, std::acos(-c.startCos) * 180 / std::numbers::pi, c.solver.c_str(), c.wallLayers,
      c.perR, r.angle, r.finalAngle, c.tEnd, r.particles, r.steps, r.seconds,
      r.finite ? "" : " (NOT FINITE)");
  return r.finite ? 0 : 1;
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
  const Real v = 0.3;
  s.oilOffset = s.cavityRadius * (1 - 2 * testing::flatCoverage(v));
  const Real tilt = tiltDeg * std::numbers::pi / 180;
  s.oilAxis = Vec3(std::sin(tilt), std::cos(tilt), 0);
  // tilt < 0: a vertical column of the same volume fraction, 1 - (1 - a^2)^(3/2) = v
  if (tiltDeg < 0) {
    s.oilAxis = Vec3::UnitY();
    s.oilColumnRadius = s.cavityRadius * std::sqrt(1 - std::pow(1 - v, 2.0 / 3.0));
  }
  s.massExcess = 0.02;
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
  std::printf("cavity %s: Rs %.1f mm, d = Rs/%.0f, %zu fluid + %zu wall particles, oil fraction "
              "%.4f, closed-form coverage %.4f (flat start %.4f)\n",
              lens ? "lens" : "flat", s.cavityRadius * 1e3, perR, w.particles.size(),
              w.walls.size(), scene.oilVolumeFraction, expected,
              testing::flatCoverage(scene.oilVolumeFraction));
  const auto t0 = std::chrono::steady_clock::now();
  Real next = 0;
  while (w.time < tEnd) {
    pipeline.step(w);
    if (w.time >= next) {
      const auto m = testing::measureCavity(scene, s.cavityRadius);
      const Vec3 c = centreOfMaterial(w, scene.oil);
      std::printf("  t = %.4f s  coverage %.4f (Shepard %.4f, dry %.4f)  angle %.1f deg  oil centre "
                  "(%.2f %.2f %.2f) mm  wall %.1f s\n",
                  w.time, m.coverage, m.shepardCoverage, m.dry, m.angle, c.x() * 1e3, c.y() * 1e3,
                  c.z() * 1e3, seconds(t0));
      std::fflush(stdout);
      next += tEnd / 20;
    }
  }
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
    std::printf("bulk interface at y = %.3f mm (%d points), fluid centre y = %.3f mm, R_eff = %.3f "
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
      const int k = std::clamp(
          static_cast<int>((w.walls.x[b].y() + s.cavityRadius) / s.spacing), 0, bins - 1);
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
    const int k = std::clamp(
        static_cast<int>((w.particles.x[i].y() + s.cavityRadius) / s.spacing), 0, slabs - 1);
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
  if (argc >= 2 && std::strcmp(argv[1], "oscillation") == 0)
    return oscillation(argc > 2 ? std::atof(argv[2]) * 1e-3 : 0.003, argc > 3 ? std::atof(argv[3]) : 6,
                       argc > 4 ? std::atof(argv[4]) : 2.2);
  if (argc >= 3 && std::strcmp(argv[1], "sessile") == 0) {
    testing::SessileCase c;
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
    return sessile(c);
  }
  if (argc >= 3 && std::strcmp(argv[1], "cavity") == 0)
    return cavity(std::strcmp(argv[2], "flat") != 0, std::atof(argv[2]),
                  argc > 3 ? std::atof(argv[3]) : 0.1, argc > 4 ? std::atof(argv[4]) : 8,
                  argc > 5 ? std::atof(argv[5]) : 0, argc > 6 ? std::atof(argv[6]) : 700,
                  argc > 7 ? std::atof(argv[7]) : 0.005, argc > 8 ? std::atof(argv[8]) : 0.04,
                  argc > 9 && std::atoi(argv[9]) != 0, argc > 10 ? argv[10] : "wcsph");
  std::fprintf(
      stderr,
      "usage: sim_interface_bench oscillation [R_mm] [d_per_R] [periods]\n"
      "       sim_interface_bench sessile THETA_DEG [t_end_s] [start_cos] [solver] [wall_layers] "
      "[R_per_d] [mu_Pa_s] [jitter_d] [relax_steps] [half_width_per_R]\n"
      "       sim_interface_bench cavity THETA_DEG|flat [t_end_s] [Rs_per_d] [tilt_deg] "
      "[oil_density] [mu_Pa_s] [sigma_N_m] [wall_friction] [solver]\n");
  return 2;
}
