// Floating elastic block (docs/methods/elasticity.md validation 3; Wang et al. 2023 Figure 8 claims
// an elastic body of half the fluid's density floats exactly half submerged with INDSPH). Prints
// one markdown line: the submerged fraction measured as the validation defines it — water level far
// from the block (mean of the column tops + d/2, columns at least 3 d from the block) against the
// block's bottom and top (mean of its lowest and highest particle layer -/+ d/2) — averaged over
// the second half of the run. A benchmark, not a test: the 1 s runs take minutes at d = 5 mm
// (docs/methods/elasticity.md).
//
// It also prints (stderr) two other water levels (the far-field particle count x d, and where the
// far-field hydrostatic pressure line reaches p = 0) and the pressure under the block against its
// weight per area (docs/methods/elasticity.md, "Buoyancy"; the count level assumes the layered
// floor at y = 0); with BUOYANCY_TRACE set, also the trace and the far-field layer profile at the
// end. Walls: "layered" (default; sim/boundary/wall_layers.h, 3 layers of static particles whose
// pressure INDSPH solves for, eq. 21; the fluid lattice starts at the wall faces) or "akinci" (one
// surface layer, fluid kWallGap d away: the first numbers of docs/methods/elasticity.md
// "Buoyancy").
//
//   solid_buoyancy_bench <specific gravity> [solver = indsph] [seconds = 1] [block layers = 6]
//                        [tank width [d] = 20] [walls = layered]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tests/sim/floating_block.h"

using namespace sim;

namespace {

struct Waterline {
  Real surface = 0;  // [m] far-field water level
  Real bottom = 0;   // [m] block bottom face
  Real top = 0;      // [m] block top face
};

Waterline measure(const World& world, int block, const Vec3& centre, Real halfWidth, Real d) {
  const auto& p = world.particles;
  Real minY = 1e30, maxY = -1e30;
  std::map<std::pair<int, int>, Real> columnTop;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.x[i];
    if (p.material[i] == block) {
      minY = std::min(minY, x.y());
      maxY = std::max(maxY, x.y());
      continue;
    }
    if (std::max(std::abs(x.x() - centre.x()), std::abs(x.z() - centre.z())) < halfWidth + 3 * d)
      continue;
    const auto key = std::make_pair(static_cast<int>(std::floor(x.x() / d)),
                                    static_cast<int>(std::floor(x.z() / d)));
    const auto it = columnTop.find(key);
    if (it == columnTop.end())
      columnTop[key] = x.y();
    else
      it->second = std::max(it->second, x.y());
  }
  Real bottom = 0, top = 0;
  int nBottom = 0, nTop = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.material[i] != block) continue;
    if (p.x[i].y() < minY + 0.5 * d) bottom += p.x[i].y(), ++nBottom;
    if (p.x[i].y() > maxY - 0.5 * d) top += p.x[i].y(), ++nTop;
  }
  Real surface = 0;
  for (const auto& [key, y] : columnTop) surface += y;
  return {surface / columnTop.size() + 0.5 * d, bottom / nBottom - 0.5 * d, top / nTop + 0.5 * d};
}

// Where the pressure field puts the water level, and what the water under the block pushes with.
struct Probe {
  Real volumeLevel = 0;    // [m] far-field particle count x d^3 / column area (floor at y = 0)
  Real pressureLevel = 0;  // [m] far field: where the least-squares line p(y) reaches p = 0
  Real pressureSlope = 0;  // [1] that line's slope / (-rho g)
  Real underPressure = 0;  // [Pa] mean pressure of the water layer under the block's bottom face
  Real underDepth = 0;     // [m] (far-field particle level) - (mean height of that layer)
};

Probe probe(const World& world, int block, const Vec3& centre, Real halfWidth, Real d,
            Real bottomFace, Real level) {
  const auto& p = world.particles;
  const auto& pressure = p.fields.get<Real>("pressure");
  Probe r;
  std::map<std::pair<int, int>, int> columnCount;
  Real sy = 0, sp = 0, syy = 0, syp = 0, under = 0, underY = 0;
  int n = 0, nUnder = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.material[i] == block) continue;
    const Vec3& x = p.x[i];
    const Real off = std::max(std::abs(x.x() - centre.x()), std::abs(x.z() - centre.z()));
    if (off < halfWidth - d && x.y() < bottomFace && x.y() > bottomFace - d) {
      under += pressure[i], underY += x.y(), ++nUnder;  // inner footprint, first layer under
    }
    if (off < halfWidth + 3 * d) continue;
    ++columnCount[std::make_pair(static_cast<int>(std::floor(x.x() / d)),
                                 static_cast<int>(std::floor(x.z() / d)))];
    // Fit over the interior only: 1.5 d off the floor, 2.5 d under the surface (the free-surface
    // layers have a number-density deficit, the floor layer sees the walls).
    if (x.y() > 1.5 * d && x.y() < level - 2.5 * d) {
      sy += x.y(), sp += pressure[i], syy += x.y() * x.y(), syp += x.y() * pressure[i], ++n;
    }
  }
  int total = 0;
  for (const auto& [key, c] : columnCount) total += c;
  r.volumeLevel = d * total / columnCount.size();
  const Real slope = (n * syp - sy * sp) / (n * syy - sy * sy);
  const Real intercept = (sp - slope * sy) / n;
  r.pressureLevel = -intercept / slope;
  r.pressureSlope = -slope / (1000 * 9.81);
  r.underPressure = nUnder ? under / nUnder : 0;
  r.underDepth = nUnder ? level - underY / nUnder : 0;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: %s <specific gravity> [solver] [seconds] [block layers] [tank width] "
                 "[layered|akinci]\n",
                 argv[0]);
    return 2;
  }
  const Real gravityRatio = std::atof(argv[1]);  // [1] block density / water density
  const std::string solver = argc > 2 ? argv[2] : "indsph";
  const Real duration = argc > 3 ? std::atof(argv[3]) : 1.0;  // [s]
  const int layers = argc > 4 ? std::atoi(argv[4]) : 6;
  const int width = argc > 5 ? std::atoi(argv[5]) : 20;  // [d]
  const bool layered = argc > 6 ? std::string(argv[6]) != "akinci" : true;
  const Real d = 0.005;                  // [m]
  const int depth = 10, blockWidth = 8;  // [d]
  testing::FloatingBlockSpec spec;
  spec.d = d;
  spec.specificGravity = gravityRatio;
  spec.tankWidth = width, spec.waterDepth = depth;
  spec.blockWidth = blockWidth, spec.blockLayers = layers;
  spec.layeredWalls = layered;
  spec.solver = solver;
  testing::FloatingBlock scene = testing::floatingBlock(spec);
  World& world = *scene.world;
  Pipeline& pipeline = *scene.pipeline;
  const int block = scene.block;
  const Real height = layers * d;  // [m]
  const Vec3 centre = scene.footprintCentre;
  Real sum = 0, sum2 = 0;
  int samples = 0;
  Probe probes;  // sums over the averaging window
  Real levelSum = 0, bottomSum = 0, topSum = 0;
  Waterline last;
  for (Real t = 0.01; t <= duration + 1e-9; t += 0.01) {
    while (world.time < t) pipeline.step(world);
    last = measure(world, block, centre, 0.5 * blockWidth * d, d);
    const Real fraction = (last.surface - last.bottom) / (last.top - last.bottom);
    if (world.time > duration / 2) {
      sum += fraction, sum2 += fraction * fraction, ++samples;
      const Probe q =
          probe(world, block, centre, 0.5 * blockWidth * d, d, last.bottom, last.surface);
      probes.volumeLevel += q.volumeLevel, probes.pressureLevel += q.pressureLevel;
      probes.pressureSlope += q.pressureSlope, probes.underPressure += q.underPressure;
      probes.underDepth += q.underDepth;
      levelSum += last.surface, bottomSum += last.bottom, topSum += last.top;
    }
    if (std::getenv("BUOYANCY_TRACE"))
      std::fprintf(stderr, "t %.2f level %.3f bottom %.3f top %.3f [d] fraction %.3f\n", world.time,
                   last.surface / d, last.bottom / d, last.top / d, fraction);
  }
  const Real mean = sum / samples;
  std::printf("| %.2f | %s | %s | %d | %d | %.3f | %.3f | %.2f | %.2g |\n", gravityRatio,
              solver.c_str(), layered ? "layered" : "akinci", width, layers, mean,
              std::sqrt(std::max(0.0, sum2 / samples - mean * mean)),
              (mean - gravityRatio) * layers, kineticEnergy(world));
  // Diagnostics (stderr): all in d from the tank floor, averaged over the window. The draft the
  // block's weight needs is s.g. x H; the bottom-face pressure it needs is s.g. rho g H.
  const Real k = 1.0 / samples;
  std::fprintf(stderr,
               "# level: particles %.3f d, volume %.3f d, pressure %.3f d (slope %.3f); block "
               "bottom %.3f top %.3f d; water under the block: p %.1f Pa at depth %.3f d (rho g "
               "depth %.1f Pa); weight / area %.1f Pa\n",
               levelSum * k / d, probes.volumeLevel * k / d, probes.pressureLevel * k / d,
               probes.pressureSlope * k, bottomSum * k / d, topSum * k / d,
               probes.underPressure * k, probes.underDepth * k / d,
               1000 * 9.81 * probes.underDepth * k, gravityRatio * 1000 * 9.81 * height);
  // Layer profile of the far-field columns at the end (stderr): mean height of the k-th particle
  // from the floor, in d (a lattice at rest: k + 1/2), and its mean pressure.
  if (std::getenv("BUOYANCY_TRACE")) {
    std::map<std::pair<int, int>, std::vector<std::pair<Real, Real>>> columns;
    const auto& p = world.particles;
    const auto& pressure = p.fields.get<Real>("pressure");
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3& x = p.x[i];
      if (p.material[i] == block ||
          std::max(std::abs(x.x() - centre.x()), std::abs(x.z() - centre.z())) <
              0.5 * blockWidth * d + 3 * d)
        continue;
      columns[{static_cast<int>(std::floor(x.x() / d)), static_cast<int>(std::floor(x.z() / d))}]
          .push_back({x.y(), pressure[i]});
    }
    std::vector<Real> y(40, 0.0), pk(40, 0.0);
    std::vector<int> n(40, 0);
    for (auto& [key, c] : columns) {
      std::sort(c.begin(), c.end());
      for (std::size_t r = 0; r < c.size() && r < 40; ++r)
        y[r] += c[r].first, pk[r] += c[r].second, ++n[r];
    }
    for (int r = 0; r < 40 && n[r]; ++r)
      std::fprintf(stderr, "# layer %d: y %.3f d, p %.1f Pa, columns %d\n", r, y[r] / n[r] / d,
                   pk[r] / n[r], n[r]);
  }
  return 0;
}
