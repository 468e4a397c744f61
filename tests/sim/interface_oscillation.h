// The l = 2 oscillation of an oil droplet in aqueous (validation 2), shared by the
// `[oscillation]` test and `sim_interface_bench oscillation`: scene, relaxed start, linear-mode
// velocity kick, the shape signal Q(t), and the two period estimates (zero crossings, damped-cosine
// fit), with Lamb's closed forms to compare against.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "interface_fixtures.h"
#include "sim/measure/interface_gap.h"

namespace sim::testing {

// Lamb (1932, Hydrodynamics, section 275): a drop of density rhoI in a liquid of density rhoO,
//   omega_l^2 = l (l+1) (l-1) (l+2) sigma / (R^3 ((l+1) rhoI + l rhoO));
// with rhoO = 0 it is Rayleigh's l (l-1) (l+2) sigma / (rhoI R^3).
inline Real lambOmega(int l, Real sigma, Real radius, Real rhoI, Real rhoO) {
  const Real n = l * (l + 1.0) * (l - 1.0) * (l + 2.0);
  return std::sqrt(n * sigma / (radius * radius * radius * ((l + 1) * rhoI + l * rhoO)));
}

// Amplitude decay rate [1/s] of the irrotational mode (dissipation method, Lamb 1932 section 355,
// extended to both phases): the viscous dissipation of the potential flows phi_i ~ r^l P_l inside
// and phi_o ~ r^-(l+1) P_l outside, over twice the mode's energy,
//   beta = (2l+1) ((l-1)(l+1) mu_i + l (l+2) mu_o) / (R^2 ((l+1) rho_i + l rho_o)),
// which is Lamb's (l-1)(2l+1) nu / R^2 (5 nu / R^2 for l = 2) for a drop in vacuum. Between two
// liquids the potential flows slip past each other at the interface; the real no-slip interface
// carries an oscillating shear layer of thickness sqrt(2 nu / omega) whose dissipation adds
// (Miller & Scriven 1968, J. Fluid Mech. 32) -- see interfaceLayerDamping.
inline Real irrotationalDamping(int l, Real radius, Real rhoI, Real rhoO, Real muI, Real muO) {
  return (2 * l + 1) * ((l - 1.0) * (l + 1.0) * muI + l * (l + 2.0) * muO) /
         (radius * radius * ((l + 1) * rhoI + l * rhoO));
}

// Estimate [1/s] of the interface shear layer's share, for two liquids of equal mu rho (each side
// then takes half the potential flows' tangential velocity jump, whose amplitude is (2l+1)/(l+1)
// times the inner tangential velocity): time-averaged Stokes-layer dissipation
// (1/2) U^2 sqrt(mu rho omega / 2) per side and area, over twice the mode's energy:
//   beta_layer = (2l+1)^2 sqrt(mu rho omega / 2) / (4 R ((l+1) rho_i + l rho_o)).
// It exceeds the irrotational part by ~ R / layer thickness, i.e. it dominates at low viscosity.
inline Real interfaceLayerDamping(int l, Real radius, Real rhoI, Real rhoO, Real mu, Real rho,
                                  Real omega) {
  return (2 * l + 1) * (2 * l + 1) * std::sqrt(mu * rho * omega / 2) /
         (4 * radius * ((l + 1) * rhoI + l * rhoO));
}

struct OscillationSpec {
  Real radius = 0.003;        // [m] R
  Real perR = 6;              // [1] R / d
  Real halfWidthPerR = 2;     // [1] box half-width / R
  Real sigma = 0.04;          // [N/m]
  Real mu = 1e-3;             // [Pa s] both phases (physical, water-like)
  Real amplitude = 0.05;      // [1] eps: peak P2 amplitude of r = R (1 + eps P2(cos theta))
  bool velocityStart = true;  // kick the relaxed sphere with the linear mode's velocity field;
                              // false: displace the lattice sphere (the old start)
  int relaxSteps = 100;       // velocity-reset steps before the kick (0 = lattice start)
  // [1] velocities are multiplied by this after each relaxation step: 0 resets them (gradient
  // descent), a value near 1 lets the fast acoustic mode equilibrate while damping it; they are
  // reset at the end either way
  Real relaxVelocityFactor = 0;
  std::string solver = "indsph";
  Real velocitySmoothing = 0;  // [1] XSPH (incompressible solvers; 0 = only physical viscosity)
  Real artificialViscosity = 0.05;  // [1] WCSPH alpha
  Real periods = 2;                 // simulated time in Lamb periods (after the relaxation)
  bool bulkExpansion = true;        // INDSPH: IndsphParameters::correctBulkExpansion (closed box)
  IndsphParameters indsph;          // INDSPH solve (tolerance, iterations, warm start)
  Real maxTimeStep = 0;             // [s] cap on the step (0: the pipeline's limits only)
  Real backgroundPressure = -1;     // [Pa] PipelineOptions::backgroundPressure (< 0 automatic)
  SurfaceStressForm surfaceStress = SurfaceStressForm::kAuto;  // PipelineOptions::surfaceStress
  Real massExcess = -1;  // [1] DropletSpec::massExcess; < 0: 0.05 for WCSPH, 0 otherwise
  Real jitter = 0;       // [1] lattice positions moved by up to +-jitter d per axis before
                         // the relaxation (fixed seed): a disordered start
};

struct OscillationRun {
  std::vector<Real> t, q;  // [s], [m^2] time since the kick and the shape moment Q
  Real radius = 0;         // [m] equivalent radius of the oil lattice
  Real omega = 0;          // [1/s] Lamb's omega_2 for that radius
  Real q0 = 0;             // [m^2] (3/5) eps R^2: the linear mode's Q amplitude (eps >= 1e-3)
  std::size_t particles = 0;
  long steps = 0;  // after the relaxation
  long relaxSteps = 0;
  Real meanIterations = 0;  // pressure-solve iterations per step (after the relaxation)
  Real wallSeconds = 0;
};

// Shape moment of the oil: Q = <y^2> - (<x^2> + <z^2>) / 2 about its centre [m^2]. For
// r = R (1 + eps P2(cos theta)) it is (3/5) eps R^2 to first order: it follows the P2 amplitude.
inline Real shapeMoment(const World& w, int oil) {
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

// Linear l = 2 mode about a sphere of radius R at the origin (Lamb section 275): inside
// phi = A r^2 P2 = A (y^2 - (x^2 + z^2)/2), outside phi = C r^-3 P2 with the same radial velocity
// at R (C = -2 A R^5 / 3). A = eps omega / 2 makes the surface r = R (1 + eps sin(omega t) P2).
inline Vec3 p2ModeVelocity(const Vec3& x, Real radius, Real a, bool inside) {
  if (inside) return a * Vec3(-x.x(), 2 * x.y(), -x.z());
  const Real r2 = x.squaredNorm(), r = std::sqrt(r2);
  const Real c = -2 * a * std::pow(radius, 5) / 3;
  const Real g = x.y() * x.y() - 0.5 * (x.x() * x.x() + x.z() * x.z());
  return c * (Vec3(-x.x(), 2 * x.y(), -x.z()) / std::pow(r, 5) - 5 * g / std::pow(r, 7) * x);
}

inline OscillationRun runOscillation(const OscillationSpec& o, bool verbose = false) {
  DropletSpec s;
  s.radius = o.radius;
  s.spacing = o.radius / o.perR;
  s.halfWidth = o.halfWidthPerR * o.radius;
  s.sigma = o.sigma;
  s.oilViscosity = s.aqueousViscosity = o.mu;
  // WCSPH needs the compressed background (no Tait clamp at p = 0, see DropletSpec); INDSPH holds
  // the rest number density 1/V0, so the lattice must start at it.
  s.massExcess = o.massExcess >= 0 ? o.massExcess : (o.solver == "wcsph" ? 0.05 : 0.0);
  s.p2Amplitude = o.velocityStart ? 0.0 : o.amplitude;
  s.maxTimeStep = o.maxTimeStep;
  auto scene = dropletScene(s);
  World& w = *scene.world;
  if (o.jitter > 0) {
    // std::mt19937's sequence is fixed by the standard (its distributions' are not).
    std::mt19937 random(7);
    const auto u = [&] {
      return o.jitter * s.spacing * (2.0 * static_cast<Real>(random()) / 4294967295.0 - 1.0);
    };
    for (Vec3& x : w.particles.x) x += Vec3(u(), u(), u());
  }
  OscillationRun out;
  out.radius = scene.radius;
  out.omega = lambOmega(2, o.sigma, scene.radius, 970, 1000);
  out.q0 = 0.6 * std::max(o.amplitude, Real(1e-3)) * scene.radius * scene.radius;
  out.particles = w.particles.size();
  PipelineOptions options;
  options.solver = o.solver;
  options.velocitySmoothing = o.velocitySmoothing;
  options.indsph = o.indsph;
  options.indsph.correctBulkExpansion = o.bulkExpansion;
  options.wcsph.speedOfSound = 12 * std::sqrt(2 * o.sigma / scene.radius / 1000);
  options.wcsph.artificialViscosity = o.artificialViscosity;
  options.backgroundPressure = o.backgroundPressure;
  options.surfaceStress = o.surfaceStress;
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  const auto t0 = std::chrono::steady_clock::now();
  // Diagnostics of the verbose runs: the fastest particle and the droplet's pressure jump [Pa].
  const auto maxSpeed = [&] {
    Real vmax = 0;
    for (const Vec3& v : w.particles.v) vmax = std::max(vmax, v.norm());
    return vmax;
  };
  const auto pressureJump = [&] {
    const Real h = w.supportRadius();
    return measureDropletPressureJump(
               w, w.particles.fields.get<Real>("pressure"),
               {centreOfMaterial(w, scene.oil), scene.radius, h, scene.oil, scene.radius + 2 * h})
        .jump;
  };
  // Relaxed start: the lattice sphere is not the droplet's rest state (the diffuse interface
  // and the lattice's staircase rearrange under the tension); steps with the velocities reset
  // after each let it settle without storing the rearrangement as motion.
  for (int k = 0; k < o.relaxSteps; ++k) {
    pipeline.step(w);
    if (verbose && (k + 1) % 20 == 0) {
      std::printf(
          "  relaxation step %d: max speed before the reset %.2e m/s, Q %+.3e m^2, "
          "pressure jump %.2f Pa (2 sigma / R = %.2f Pa), interface number density %.3f, "
          "nearest other phase %.2f d\n",
          k + 1, maxSpeed(), shapeMoment(w, scene.oil), pressureJump(), 2 * o.sigma / scene.radius,
          interfaceGap(w, scene.oil, scene.aqueous).numberDensityRatio,
          interfaceGap(w, scene.oil, scene.aqueous).meanNearestDistance);
    }
    for (Vec3& v : w.particles.v) v *= o.relaxVelocityFactor;
  }
  if (o.relaxSteps > 0)
    for (Vec3& v : w.particles.v) v.setZero();
  out.relaxSteps = w.stepCount;
  if (o.velocityStart) {
    const Vec3 c = centreOfMaterial(w, scene.oil);
    const Real a = 0.5 * o.amplitude * out.omega;
    for (Index i = 0; i < w.particles.size(); ++i)
      w.particles.v[i] = p2ModeVelocity(w.particles.x[i] - c, scene.radius, a,
                                        w.particles.material[i] == scene.oil);
  }
  const Real tStart = w.time, period = 2 * std::numbers::pi / out.omega;
  out.t.push_back(0);
  out.q.push_back(shapeMoment(w, scene.oil));
  while (w.time - tStart < o.periods * period) {
    pipeline.step(w);
    out.t.push_back(w.time - tStart);
    out.meanIterations += pipeline.solver().stats().densityIterations;
    out.q.push_back(shapeMoment(w, scene.oil));
    if (verbose && out.t.size() % 20 == 0) {
      std::printf(
          "  t = %.4f s  Q = %+.3e m^2 (%+.3f of (3/5) eps R^2)  dt %.2e s  max speed %.3f "
          "m/s  jump %.3f of 2 sigma/R  wall %.0f s\n",
          out.t.back(), out.q.back(), out.q.back() / out.q0, w.lastTimeStep, maxSpeed(),
          pressureJump() * scene.radius / (2 * o.sigma),
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      std::fflush(stdout);
    }
  }
  out.steps = w.stepCount - out.relaxSteps;
  out.meanIterations /= static_cast<Real>(std::max(out.steps, 1L));
  out.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

// Times [s] where Q minus its mean changes sign (linear interpolation), counted only up to
// `tEnd` (where the oscillation has decayed into the particle noise, sign changes of the noise
// are not half-periods). A crossing counts only after the signal has stayed on one side for
// minGap samples.
inline std::vector<Real> zeroCrossings(const std::vector<Real>& t, const std::vector<Real>& q,
                                       Real mean, Real tEnd, std::size_t minGap = 5) {
  std::vector<Real> out;
  std::size_t last = 0;
  for (std::size_t k = 1; k < q.size() && t[k] <= tEnd; ++k) {
    const Real a = q[k - 1] - mean, b = q[k] - mean;
    if (a * b < 0 && (out.empty() || k - last >= minGap)) {
      out.push_back(t[k - 1] + (t[k] - t[k - 1]) * a / (a - b));
      last = k;
    }
  }
  return out;
}

// Period [s] from the zero crossings: twice the mean spacing of consecutive crossings (0 if
// fewer than two).
inline Real crossingPeriod(const std::vector<Real>& crossings) {
  if (crossings.size() < 2) return 0;
  return 2 * (crossings.back() - crossings.front()) / static_cast<Real>(crossings.size() - 1);
}

struct DampedCosineFit {
  Real omega = 0;      // [1/s]
  Real damping = 0;    // [1/s] amplitude decay rate
  Real mean = 0;       // [m^2]
  Real drift = 0;      // [m^2/s]
  Real amplitude = 0;  // [m^2] at t = 0
  Real rms = 0;        // [m^2] residual
};

// Least-squares fit Q(t) = a + b t + exp(-g t) (c cos(w t) + e sin(w t)): linear in (a, b, c, e),
// (w, g) by a grid search refined three times around the best point. The drift b (withDrift)
// absorbs the mean-shape relaxation of an unrelaxed lattice start; after a relaxed start the mean
// is the sphere's and b only trades off against the damped cosine over one or two periods, so it
// is left out (b = 0).
inline DampedCosineFit fitDampedCosine(const std::vector<Real>& t, const std::vector<Real>& q,
                                       Real omegaGuess, bool withDrift = true) {
  const auto solve = [&](Real wTry, Real gTry, Eigen::Vector4d& c) {
    Eigen::Matrix4d ata = Eigen::Matrix4d::Zero();
    Eigen::Vector4d atb = Eigen::Vector4d::Zero();
    for (std::size_t k = 0; k < q.size(); ++k) {
      const Real e = std::exp(-gTry * t[k]);
      const Eigen::Vector4d row(1, withDrift ? t[k] : 0.0, e * std::cos(wTry * t[k]),
                                e * std::sin(wTry * t[k]));
      ata += row * row.transpose();
      atb += row * q[k];
    }
    if (!withDrift) ata(1, 1) = 1;  // the drift column is zero: keep the system regular (c[1] = 0)
    c = ata.ldlt().solve(atb);
    Real residual = 0;
    for (std::size_t k = 0; k < q.size(); ++k) {
      const Real e = std::exp(-gTry * t[k]);
      const Real model =
          c[0] + c[1] * t[k] + e * (c[2] * std::cos(wTry * t[k]) + c[3] * std::sin(wTry * t[k]));
      residual += (q[k] - model) * (q[k] - model);
    }
    return residual;
  };
  Real wLo = 0.3 * omegaGuess, wHi = 1.7 * omegaGuess, gLo = 0, gHi = 0.5 * omegaGuess;
  DampedCosineFit best;
  Real bestResidual = std::numeric_limits<Real>::infinity();
  Eigen::Vector4d bestC = Eigen::Vector4d::Zero();
  for (int pass = 0; pass < 4; ++pass) {
    const int n = 40;
    for (int iw = 0; iw <= n; ++iw)
      for (int ig = 0; ig <= n; ++ig) {
        const Real wTry = wLo + (wHi - wLo) * iw / n, gTry = gLo + (gHi - gLo) * ig / n;
        Eigen::Vector4d c;
        const Real r = solve(wTry, gTry, c);
        if (r < bestResidual) {
          bestResidual = r;
          best.omega = wTry;
          best.damping = gTry;
          bestC = c;
        }
      }
    const Real dw = 2 * (wHi - wLo) / n, dg = 2 * (gHi - gLo) / n;
    wLo = best.omega - dw;
    wHi = best.omega + dw;
    gLo = std::max(Real(0), best.damping - dg);
    gHi = best.damping + dg;
  }
  best.mean = bestC[0];
  best.drift = bestC[1];
  best.amplitude = std::hypot(bestC[2], bestC[3]);
  best.rms = std::sqrt(bestResidual / static_cast<Real>(q.size()));
  return best;
}

// Both period estimates of one record. After a velocity kick the reference of the crossings is
// Q of the relaxed sphere, q[0] (0 up to round-off: the centred droplet in the cubic box has the
// box's symmetry), and the fit has no drift; after a displacement start the reference is the
// record's mean and the fit has the drift term. Crossings count while the fitted envelope is above
// a tenth of its start: later sign changes are the particle noise's. The kick is itself a crossing.
struct OscillationAnalysis {
  DampedCosineFit fit;
  std::vector<Real> crossings;  // [s]
  Real fittedPeriod = 0;        // [s]
  Real crossingPeriod = 0;      // [s] 0 with fewer than two crossings
};
inline OscillationAnalysis analyseOscillation(const std::vector<Real>& t,
                                              const std::vector<Real>& q, Real omega,
                                              bool velocityStart) {
  OscillationAnalysis a;
  a.fit = fitDampedCosine(t, q, omega, !velocityStart);
  Real mean = q.front();
  if (!velocityStart) {
    mean = 0;
    for (const Real v : q) mean += v;
    mean /= static_cast<Real>(q.size());
  }
  const Real tEnd = a.fit.damping > 0 ? std::log(10.0) / a.fit.damping : t.back();
  a.crossings = zeroCrossings(t, q, mean, tEnd);
  if (velocityStart) a.crossings.insert(a.crossings.begin(), t.front());
  a.fittedPeriod = 2 * std::numbers::pi / a.fit.omega;
  a.crossingPeriod = crossingPeriod(a.crossings);
  return a;
}

}  // namespace sim::testing
