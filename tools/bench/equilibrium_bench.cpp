// What the static equilibrium's accuracy costs in time: a 12 mm sphere at Bond 1.2 (silicone oil
// 970 in aqueous 1004 kg/m^3, 40 mN/m, 1 g), each voxel spacing against the axisymmetric
// Young-Laplace equilibrium, with iterations and wall time. Writes a markdown table to stdout and
// equilibrium_bench.csv to --out. The last column, the aqueous above the centre, is the film
// along the wall when the oil is light and fills more than about 0.6. A benchmark, not a test: only
// its command line is checked in the suite (check_equilibrium_bench_cli.sh).
//
//   sim_equilibrium_bench [--voxels 0.5,0.4,0.3] [--angles 18,40,90,140] [--fills 0.8,0.9]
//                         [--smoothing 1.5] [--wall-ratio R] [--gravity 9.81] [--tension 0.04]
//                         [--threshold auto|whole|fractional] [--stop DU] [--out DIR]
//
// --wall-ratio: the wall kernel's width over the interface kernel's (default: the calibrated
// ratio per angle, wallKernelRatio; 1: one kernel for both). --gravity 0: the reference is the
// zero-gravity lens. --threshold: the final stage's, to whole voxels or to fractions of a voxel
// (default auto: fractions from a wetting angle of 40 deg; ThresholdDynamicsOptions::
// finalThreshold); the ratio follows it unless --wall-ratio is given. --stop: the fractional
// stage's end, the largest change of a voxel's oil share in an iteration (fractionalTolerance).
// --tension [N/m]: the oil-aqueous tension of the solver and the reference alike (what an effective
// tension below the true one would move the coverage by, e.g. 0.032 for 0.8 sigma:
// docs/validation.md, "Weight against tension").
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "sim/equilibrium/threshold_dynamics_xu2017.h"
#include "sim/equilibrium/wall_oil.h"
#include "tests/sim/young_laplace_sphere.h"

using namespace sim;
using namespace sim::equilibrium;

namespace {

std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || !(v > 0)) {
      std::fprintf(stderr, "sim_equilibrium_bench: '%s' is not a positive number\n", item.c_str());
      std::exit(2);
    }
    out.push_back(v);
  }
  return out;
}

double nonNegative(const char* text) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(v >= 0)) {
    std::fprintf(stderr, "sim_equilibrium_bench: '%s' is not a number >= 0\n", text);
    std::exit(2);
  }
  return v;
}

std::optional<FinalThreshold> thresholdNamed(const std::string& name) {
  if (name == "auto") return FinalThreshold::kByAngle;
  if (name == "whole") return FinalThreshold::kWholeVoxels;
  if (name == "fractional") return FinalThreshold::kFractional;
  return std::nullopt;
}

// [1] The share of the aqueous volume above the sphere's centre (z > 0, against gravity). A light
// oil at fills from 0.6 up leaves no aqueous there except a film along the wall, which the
// discrete energy makes nearly free at small angles (docs/methods/equilibrium.md).
double aqueousAboveCentre(const EquilibriumSolution& s) {
  double above = 0.0, all = 0.0;
  for (std::size_t v = 0; v < s.oil.size(); ++v) {
    const double aqueous = (1.0 - s.oil[v]) * s.fluidFraction[v];
    all += aqueous;
    if (s.grid.centre(v).z() > 0.0) above += aqueous;
  }
  return all > 0.0 ? above / all : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> voxels{0.5, 0.4, 0.3}, angles{18, 40, 90, 140}, fills{0.8, 0.9};
  double smoothing = ThresholdDynamicsOptions{}.finalSmoothing;   // [voxels] final sqrt(t) / h
  double wallRatio = ThresholdDynamicsOptions{}.wallKernelRatio;  // 0: calibrated per angle
  FinalThreshold threshold = ThresholdDynamicsOptions{}.finalThreshold;
  double stop = ThresholdDynamicsOptions{}.fractionalTolerance;
  double g = 9.81;      // [m/s^2]
  double sigma = 0.04;  // [N/m]
  std::filesystem::path out = ".";
  // Each option and what its value sets; the same list names the options that need a value.
  const std::vector<std::pair<std::string, std::function<bool(const char*)>>> setters{
      {"--voxels", [&](const char* v) { return voxels = numbers(v), true; }},
      {"--angles", [&](const char* v) { return angles = numbers(v), true; }},
      {"--fills", [&](const char* v) { return fills = numbers(v), true; }},
      {"--smoothing", [&](const char* v) { return smoothing = numbers(v).at(0), true; }},
      {"--wall-ratio", [&](const char* v) { return wallRatio = numbers(v).at(0), true; }},
      {"--threshold",
       [&](const char* v) {
         const std::optional<FinalThreshold> named = thresholdNamed(v);
         if (named)
           threshold = *named;
         else
           std::fprintf(
               stderr, "sim_equilibrium_bench: --threshold %s: use auto, whole or fractional\n", v);
         return named.has_value();
       }},
      {"--stop", [&](const char* v) { return stop = nonNegative(v), true; }},
      {"--gravity", [&](const char* v) { return g = nonNegative(v), true; }},
      {"--tension", [&](const char* v) { return sigma = numbers(v).at(0), true; }},
      {"--out", [&](const char* v) { return out = v, true; }}};
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const auto option =
        std::find_if(setters.begin(), setters.end(), [&](const auto& o) { return o.first == a; });
    if (option != setters.end() && k + 1 < argc) {
      if (!option->second(argv[++k])) return 2;
      continue;
    }
    if (a != "--help")
      std::fprintf(stderr, "sim_equilibrium_bench: %s '%s'\n",
                   option != setters.end() ? "needs a value:" : "unknown option", a.c_str());
    std::fprintf(a == "--help" ? stdout : stderr,
                 "usage: sim_equilibrium_bench [--voxels MM,...] [--angles DEG,...] "
                 "[--fills F,...] [--smoothing VOXELS] [--wall-ratio R] [--gravity G] "
                 "[--tension N/M] [--threshold auto|whole|fractional] [--stop DU] [--out DIR]\n");
    return a == "--help" ? 0 : 2;
  }
  // The solver's own range (a contact line and an interface must exist), checked before any solve.
  for (const double theta : angles)
    if (!(theta < 180)) {
      std::fprintf(stderr, "sim_equilibrium_bench: --angles: %g is not an angle in (0, 180) deg\n",
                   theta);
      return 2;
    }
  for (const double fill : fills)
    if (!(fill < 1)) {
      std::fprintf(stderr, "sim_equilibrium_bench: --fills: %g is not a fill in (0, 1)\n", fill);
      return 2;
    }
  constexpr double R = 12e-3, oil = 970, aqueous = 1004;
  // Without gravity the reference is the shooting at a vanishing capillary constant, which meets
  // the spherical cap's closed form within 0.05 points (tests/sim/test_equilibrium.cpp).
  const double c = std::max((aqueous - oil) * g / sigma, 1e-6 / (R * R));
  std::error_code error;
  std::filesystem::create_directories(out, error);
  std::ofstream csv(out / "equilibrium_bench.csv");
  if (error || !csv) {
    std::fprintf(stderr,
                 "sim_equilibrium_bench: cannot write to '%s' (%s); give a writable folder with "
                 "--out\n",
                 out.string().c_str(), error ? error.message().c_str() : "cannot open the table");
    return 1;
  }
  csv << "voxel_mm,theta_deg,fill,coverage,young_laplace,error_points,iterations,seconds,"
         "aqueous_above_centre\n";
  std::printf(
      "| voxel | theta (aqueous) | fill | coverage | Young-Laplace | error | iterations "
      "| time | aqueous above centre |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const double voxel : voxels)
    for (const double theta : angles)
      for (const double fill : fills) {
        const double rad = theta * std::numbers::pi / 180;
        // NaN where no axisymmetric meniscus holds the volume: the solver still runs, and the
        // error reads nan.
        double reference = std::numeric_limits<double>::quiet_NaN();
        try {
          reference = testref::youngLaplaceSphere(R, c, rad, 1 - fill).upperWetFraction;
        } catch (const std::exception&) {
        }
        const auto start = std::chrono::steady_clock::now();
        EquilibriumProblem p;
        p.grid = gridAround(Vec3::Constant(-R), Vec3::Constant(R), voxel * 1e-3, 2);
        p.fluidFraction =
            fluidFractionsFromDistance(p.grid, [&](const Vec3& x) { return x.norm() - R; });
        p.oilDensity = oil;
        p.aqueousDensity = aqueous;
        p.tension = sigma;
        p.contactAngle = rad;
        p.gravity = Vec3(0, 0, -g);
        p.oilFraction = fill;
        p.wallArea = 4 * std::numbers::pi * R * R;
        ThresholdDynamicsOptions options;
        options.finalSmoothing = smoothing;
        options.wallKernelRatio = wallRatio;
        options.finalThreshold = threshold;
        options.fractionalTolerance = stop;
        const EquilibriumSolution s = solveEquilibrium(p, options);
        const WallOilReader reader(s, rad);
        const int samples = 20000;
        int covered = 0;
        for (int i = 0; i < samples; ++i) {
          const double z = 1.0 - (2.0 * i + 1.0) / samples, r = std::sqrt(1.0 - z * z);
          const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
          const Vec3 n(r * std::cos(phi), r * std::sin(phi), z);
          covered += reader.oilCovered(R * n, n) ? 1 : 0;
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double coverage = static_cast<double>(covered) / samples;
        const double film = aqueousAboveCentre(s);
        std::printf("| %.2f mm | %.0f | %.2f | %.4f | %.4f | %+.2f | %d | %.2f s | %.3f |\n", voxel,
                    theta, fill, coverage, reference, 100 * (coverage - reference), s.iterations,
                    seconds, film);
        std::fflush(stdout);
        csv << voxel << ',' << theta << ',' << fill << ',' << coverage << ',' << reference << ','
            << 100 * (coverage - reference) << ',' << s.iterations << ',' << seconds << ',' << film
            << '\n';
      }
  return 0;
}
