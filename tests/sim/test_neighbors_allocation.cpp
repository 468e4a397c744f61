// The neighbour search allocates nothing once warmed up (brief: no allocation in the time-step
// loop): its per-thread buffers and lists only grow, with headroom, so positions that move a
// little from step to step reuse them. A separate executable, because counting allocations
// replaces the global operator new for the whole program.
#include <catch2/catch.hpp>

#include <random>

#include "allocation_counter.h"
#include "sim/neighbors/neighbor_search.h"

using namespace sim;

TEST_CASE("neighbour search allocates nothing after warm-up", "[unit][neighbors]") {
  const Box domain(Vec3::Zero(), Vec3(0.2, 0.1, 0.1));
  const Real d = 0.004;  // [m] lattice spacing, support radius 2 d as in the engine
  std::vector<Vec3> fluid, wall;
  for (int a = 1; a < 24; ++a)
    for (int b = 1; b < 24; ++b)
      for (int c = 1; c < 20; ++c) fluid.push_back(Vec3(a * d, b * d, c * d));
  for (int a = 0; a < 50; ++a)
    for (int c = 0; c < 25; ++c) wall.push_back(Vec3(a * d, 0.5 * d, c * d));
  const Kernel kernel(KernelKind::kCubicSpline, 2 * d);
  NeighborSearch search(domain, 2 * d);
  search.setStatic(wall);
  std::vector<Index> order;
  std::mt19937 rng(7);
  // Jitter of 2 % of d per "step".
  std::uniform_real_distribution<Real> jitter(-0.02 * d, 0.02 * d);
  // Warm-up, as the first steps of a run: the perfect lattice, then its first move, in which
  // the pairs at exactly 2 d (excluded: the test is r < h) come within range and the lists
  // grow by ~5 % at once. After that the pair count drifts slowly, inside the buffers' headroom.
  search.update(fluid, kernel);
  for (auto& x : fluid) x += Vec3(jitter(rng), jitter(rng), jitter(rng));
  search.update(fluid, kernel);
  search.zOrder(fluid, order);
  const std::size_t pairsBefore = search.dynamicDynamic().totalPairs();
  counting = true;
  for (int step = 0; step < 5; ++step) {
    for (auto& x : fluid) x += Vec3(jitter(rng), jitter(rng), jitter(rng));
    search.update(fluid, kernel);
    search.zOrder(fluid, order);
  }
  counting = false;
  INFO("pairs before " << pairsBefore << ", after " << search.dynamicDynamic().totalPairs());
  CHECK(search.dynamicDynamic().totalPairs() > 0);
  CHECK(search.dynamicDynamicGradients().size() == search.dynamicDynamic().totalPairs());
  CHECK(allocations.load() == 0);
}

TEST_CASE("variable-support neighbour search allocates nothing after warm-up",
          "[unit][neighbors]") {
  const Box domain(Vec3::Zero(), Vec3(0.2, 0.1, 0.1));
  const Real d = 0.004, h = 2 * d;  // [m]
  std::vector<Vec3> fluid;
  for (int a = 1; a < 24; ++a)
    for (int b = 1; b < 24; ++b)
      for (int c = 1; c < 20; ++c) fluid.push_back(Vec3(a * d, b * d, c * d));
  std::vector<Real> support(fluid.size());
  for (std::size_t i = 0; i < fluid.size(); ++i) support[i] = h * (1.0 + 0.25 * (i % 5) / 4.0);
  const Kernel kernel(KernelKind::kCubicSpline, h);
  NeighborSearch search(domain, h, 1.25 * h);
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> jitter(-0.02 * d, 0.02 * d);
  search.update(fluid, kernel, &support);
  for (auto& x : fluid) x += Vec3(jitter(rng), jitter(rng), jitter(rng));
  search.update(fluid, kernel, &support);
  counting = true;
  for (int step = 0; step < 5; ++step) {
    for (auto& x : fluid) x += Vec3(jitter(rng), jitter(rng), jitter(rng));
    search.update(fluid, kernel, &support);
  }
  counting = false;
  CHECK(search.dynamicDynamic().totalPairs() > 0);
  CHECK(allocations.load() == 0);
}
