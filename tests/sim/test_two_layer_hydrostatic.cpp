// Two-layer hydrostatics (test 1): a light fluid over a heavy one at rest in a tank.
//
// Closed form (layered hydrostatics): with the free surface at H and the interface at y_I,
//   p(y) = rho_l g (H - y)                          for y > y_I,
//   p(y) = rho_l g (H - y_I) + rho_h g (y_I - y)    for y < y_I,
// continuous at y_I. Pairs: silicone oil over aqueous (970 : 1000) and a 1:10 pair. As in the
// single-phase tank (test_hydrostatic.cpp) pressures and positions are averaged over 0.4 s after
// 0.6 s of settling; the acoustic/sloshing modes make any single snapshot deviate by several %.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>

#include "scene_fixtures.h"
#include "sim/measure/interface_gap.h"

using namespace sim;

namespace {

constexpr Real kD = 0.005, kWidth = 0.04, kLayer = 0.03;  // [m] each layer 3 cm deep
constexpr Real kSettle = 0.6, kWindow = 0.4, kG = 9.81;   // [s], [s], [m/s^2]

Material fluid(const char* name, Real rho) {
  Material m;
  m.name = name;
  m.restDensity = rho;        // [kg/m^3]
  m.dynamicViscosity = 1e-3;  // [Pa s]
  return m;
}

struct TwoLayerResult {
  int layers = 0;
  Real meanError = 0, maxError = 0;  // [1] layer |p - p_closed_form| / p_bottom
  Real interfaceTilt = 0;            // [m] largest difference of the interface height between
                                     //     the four quarters of the tank
  Real gapRatio = 0;                 // [1] number density at the interface / in the bulk (0 if
                                     //     the phases are apart over a whole quarter)
  Real separation = 0;               // [m] lowest light minus highest heavy interior particle
  bool finite = true, contained = true;
};

// Number density sum_j W(x_i - x_j) of particle i over all fluid particles [1/m^3].
Real numberDensity(const std::vector<Vec3>& x, std::size_t i, const Kernel& kernel) {
  Real delta = 0;
  for (const Vec3& xj : x) delta += kernel.W(x[i] - xj);
  return delta;
}

TwoLayerResult runTwoLayer(const char* solver, Real heavy, Real light) {
  const Real gap = (testing::kWallGap - 0.5) * kD;
  TankSpec spec;
  spec.innerMax = Vec3(kWidth + 2 * gap, 3 * kLayer, kWidth + 2 * gap);
  WorldParameters params;
  params.particleSpacing = kD;
  params.domain = tankDomain(spec, kD);
  World w(params);
  w.materials.add(fluid("heavy", heavy));
  w.materials.add(fluid("light", light));
  addTankWalls(w, spec, kD);
  addFluidBlock(w, Vec3::Constant(gap), Vec3(gap + kWidth, gap + kLayer, gap + kWidth), kD, 0);
  addFluidBlock(w, Vec3(gap, gap + kLayer, gap), Vec3(gap + kWidth, gap + 2 * kLayer, gap + kWidth),
                kD, 1);
  w.initialize();
  PipelineOptions options;
  options.solver = solver;
  options.wcsph.speedOfSound = 10 * std::sqrt(2 * kG * 2 * kLayer);  // explicit solvers: 10x v_max
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  while (w.time < kSettle) pipeline.step(w);

  const Index n = static_cast<Index>(w.particles.size());
  std::vector<Real> pressureTime(n, 0.0);
  std::vector<Vec3> positionTime(n, Vec3::Zero());
  std::vector<int> material(n);
  Real elapsed = 0;
  while (w.time < kSettle + kWindow) {
    const Real dt = pipeline.step(w);
    const auto& pressure = w.particles.fields.get<Real>("pressure");
    for (Index i = 0; i < n; ++i) {
      pressureTime[w.particles.id[i]] += dt * pressure[i];
      positionTime[w.particles.id[i]] += dt * w.particles.x[i];
      material[w.particles.id[i]] = w.particles.material[i];
    }
    elapsed += dt;
  }
  TwoLayerResult r;
  r.finite = allFinite(w);
  for (const Vec3& x : w.particles.x)
    r.contained = r.contained && (x.array() >= spec.innerMin.array()).all() &&
                  (x.array() <= spec.innerMax.array()).all();
  std::vector<Vec3> x(n);
  for (Index id = 0; id < n; ++id) x[id] = positionTime[id] / elapsed;
  const Real h = w.supportRadius();

  // Free surface half a spacing above the top layer: the mean height of the highest (W/d)^2
  // particles, one lattice layer's worth. For a flat top layer that is its top particle; the top
  // particle alone would let a few particles resting on the surface move the reference by most of
  // a spacing (VSLSPH: 4 particles 0.7 d above the layer read 45 Pa, 7 % of p_bottom), while their
  // weight is 4/64 of a layer, which the mean counts as such.
  std::vector<Real> heights(n);
  for (Index i = 0; i < n; ++i) heights[i] = x[i].y();
  const auto perLayer = static_cast<std::ptrdiff_t>(std::lround((kWidth / kD) * (kWidth / kD)));
  std::partial_sort(heights.begin(), heights.begin() + perLayer, heights.end(), std::greater<>());
  Real top = 0;
  for (std::ptrdiff_t k = 0; k < perLayer; ++k) top += heights[static_cast<std::size_t>(k)];
  top /= static_cast<Real>(perLayer);
  const Real H = top + 0.5 * kD;
  // Interface half-way between the mean heights of the interface particles of each phase (those
  // with the other phase within 1.5 d).
  // Interface particles: those with a particle of the other phase within 1.5 d. Their mean height
  // is the interface height, overall and per quarter of the tank (x, z halves).
  std::vector<bool> atInterface(n, false);
  Real sumY = 0;
  int countY = 0;
  std::array<Real, 4> quarterY{};
  std::array<int, 4> quarterCount{};
  const Vec3 hi = spec.innerMax;
  const Vec3 centre = 0.5 * (spec.innerMin + spec.innerMax);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j)
      if (material[i] != material[j] && (x[i] - x[j]).norm() < 1.5 * kD) {
        atInterface[i] = true;
        sumY += x[i].y();
        ++countY;
        const int q = (x[i].x() > centre.x() ? 1 : 0) + (x[i].z() > centre.z() ? 2 : 0);
        quarterY[q] += x[i].y();
        ++quarterCount[q];
        break;
      }
  // Vertical distance between the two phases: lowest light minus highest heavy particle, among
  // interior particles (a lattice interface without gap reads one spacing d).
  Real lowestLight = H, highestHeavy = 0;
  for (Index i = 0; i < n; ++i) {
    if (x[i].x() < h || x[i].z() < h || hi.x() - x[i].x() < h || hi.z() - x[i].z() < h) continue;
    if (material[i] == 1) lowestLight = std::min(lowestLight, x[i].y());
    if (material[i] == 0) highestHeavy = std::max(highestHeavy, x[i].y());
  }
  r.separation = lowestLight - highestHeavy;
  // The phases do not touch anywhere, or not over a whole quarter of the tank: a gap wider than
  // half a spacing there, which no tilt or density ratio of the touching part should hide.
  const auto apart = static_cast<int>(std::count(quarterCount.begin(), quarterCount.end(), 0));
  if (apart > 0) {
    std::printf("%s two-layer %g over %g: phases apart over %d of 4 quarters, by %.2f d\n", solver,
                light, heavy, apart, r.separation / kD);
    r.gapRatio = 0;
    return r;
  }
  const Real yI = sumY / countY;
  Real lowest = yI, highest = yI;
  for (int q = 0; q < 4; ++q) {
    lowest = std::min(lowest, quarterY[q] / quarterCount[q]);
    highest = std::max(highest, quarterY[q] / quarterCount[q]);
  }
  r.interfaceTilt = highest - lowest;
  auto closedForm = [&](Real y) {
    return y > yI ? light * kG * (H - y) : light * kG * (H - yI) + heavy * kG * (yI - y);
  };
  const Real pBottom = closedForm(0.0);

  // Layers of one spacing, interior particles only (more than h from walls and the free
  // surface), compared with the closed form evaluated at each particle's mean height.
  std::map<int, std::pair<Real, int>> layers;  // sum of (p - closed form), count
  for (Index i = 0; i < n; ++i) {
    const Vec3& xi = x[i];
    if (H - xi.y() < h || xi.y() < h || xi.x() < h || xi.z() < h || hi.x() - xi.x() < h ||
        hi.z() - xi.z() < h)
      continue;
    auto& [sum, count] = layers[static_cast<int>(xi.y() / kD)];
    sum += pressureTime[i] / elapsed - closedForm(xi.y());
    ++count;
  }
  Real sum = 0;
  for (const auto& [k, layer] : layers) {
    if (layer.second < 4) continue;
    const Real error = std::abs(layer.first / layer.second) / pBottom;
    sum += error;
    r.maxError = std::max(r.maxError, error);
    ++r.layers;
  }
  r.meanError = r.layers > 0 ? sum / r.layers : 1.0;
  // Gap: number density of the (time-averaged) packing at the interface against the bulk, both
  // away from walls and the free surface. A gap is a layer of missing particles, so it lowers
  // the number density of the particles next to it.
  Real interfaceDelta = 0, bulkDelta = 0;
  int interfaceCount = 0, bulkCount = 0;
  for (Index i = 0; i < n; ++i) {
    const Vec3& xi = x[i];
    if (H - xi.y() < h || xi.y() < h || xi.x() < h || xi.z() < h || hi.x() - xi.x() < h ||
        hi.z() - xi.z() < h)
      continue;
    const Real delta = numberDensity(x, i, w.kernel);
    if (atInterface[i]) {
      interfaceDelta += delta;
      ++interfaceCount;
    } else {
      bulkDelta += delta;
      ++bulkCount;
    }
  }
  REQUIRE(interfaceCount > 0);
  REQUIRE(bulkCount > 0);
  r.gapRatio = (interfaceDelta / interfaceCount) / (bulkDelta / bulkCount);
  std::printf(
      "%s two-layer %g over %g: %d layers, mean error %.4f, max %.4f (of p_bottom %.0f Pa); "
      "interface at %.4f m, tilt %.2f d, separation %.2f d; interface/bulk number density %.4f\n",
      solver, light, heavy, r.layers, r.meanError, r.maxError, pBottom, yI, r.interfaceTilt / kD,
      r.separation / kD, r.gapRatio);
  return r;
}

// Tolerances, in units of the bottom pressure, with the reasoning of test_hydrostatic.cpp: the
// free surface is known to ~d/4 (1.7 % of rho g H for one phase over 7.5 cm) and, here, the
// interface height to ~d/4 as well, which moves the lower layer's profile by
// (rho_h - rho_l) g d/4: negligible for 970:1000, 1.4 % for 1:10. Hence a 3 % mean and a 5 %
// single-layer bound, as for one phase.
// Flat interface: the interface heights of the four quarters of the tank agree within half a
// spacing (each quarter's mean comes from ~25 particles spread over +-1.5 d: standard error
// ~0.15 d; a sloshing or tilted interface differs by spacings).
// No gap: the number density next to the interface is within 2 % of the bulk. A gap of width g
// removes the kernel weight of a slab of width g at distance ~d/2 from the interface particles,
// about 0.3 g/d of their number density; 2 % therefore detects a gap of ~0.07 d, while the
// disordered packing's own scatter of the mean is below 0.5 %.
void checkTwoLayer(const TwoLayerResult& r) {
  CHECK(r.finite);
  CHECK(r.contained);
  REQUIRE(r.layers >= 8);
  CHECK(r.meanError < 0.03);
  CHECK(r.maxError < 0.05);
  CHECK(r.interfaceTilt < 0.5 * kD);
  CHECK(r.gapRatio > 0.98);
}

}  // namespace

TEST_CASE("INDSPH: silicone oil over aqueous at rest matches layered hydrostatics, flat, no gap",
          "[validation][solvers][indsph][two-layer]") {
  checkTwoLayer(runTwoLayer("indsph", 1000.0, 970.0));
}

TEST_CASE("INDSPH: a 1:10 pair at rest matches layered hydrostatics, flat, no gap",
          "[validation][solvers][indsph][two-layer]") {
  checkTwoLayer(runTwoLayer("indsph", 1000.0, 100.0));
}

// VSLSPH (Li et al. 2023) in its number-density form (sim/fluid/vslsph_li2023.h): the same closed
// form and bounds. Explicit, so its compressibility rho g H / (rho c^2) = 0.5 % at c = 10 v_max
// adds to the error budget above and stays inside it. Measured: 1.4 % mean, 2.8 % max, tilt
// 0.18 d, interface/bulk number density 0.9996.
TEST_CASE("VSLSPH: silicone oil over aqueous at rest matches layered hydrostatics, flat, no gap",
          "[validation][solvers][vslsph][two-layer]") {
  checkTwoLayer(runTwoLayer("vslsph", 1000.0, 970.0));
}

// The 1:10 pair: the number-density form keeps the light phase from reading as compressed next to
// the heavy one (measured: 0.8 % mean, 2.2 % max, tilt 0.04 d, interface/bulk 1.0000).
TEST_CASE("VSLSPH: a 1:10 pair at rest matches layered hydrostatics, flat, no gap",
          "[validation][solvers][vslsph][two-layer]") {
  checkTwoLayer(runTwoLayer("vslsph", 1000.0, 100.0));
}

// The artefact INDSPH exists to remove (Wang et al. 2023, section 3.3 and Fig. 3): with
// mass-weighted densities a light particle next to heavy ones reads as compressed, and the
// solver pushes the phases apart. On the same scene and checks, DFSPH must show it at 1:10; if it
// did not, the gap check above would not be able to tell INDSPH's benefit from nothing.
TEST_CASE("DFSPH (mass-weighted) opens a gap between a 1:10 pair at rest that INDSPH does not",
          "[validation][solvers][two-layer]") {
  const TwoLayerResult r = runTwoLayer("dfsph", 1000.0, 100.0);
  CHECK(r.finite);
  CHECK(r.gapRatio < 0.98);
}
