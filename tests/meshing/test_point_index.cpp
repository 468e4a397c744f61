// PointIndex against brute force on random points: nearest, any, within and the cells around a
// position, for queries inside and outside the points' bounding box and for empty sets.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "meshing/point_index.h"

using namespace meshing;

namespace {

std::vector<Vec3> randomPoints(std::size_t n, double half, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-half, half);
  std::vector<Vec3> points(n);
  for (Vec3& p : points) p = Vec3(u(rng), u(rng), u(rng));
  return points;
}

std::vector<std::size_t> bruteWithin(const std::vector<Vec3>& points, const Vec3& x, double r) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < points.size(); ++k)
    if ((points[k] - x).squaredNorm() <= r * r) out.push_back(k);
  return out;
}

}  // namespace

TEST_CASE("point index: nearest, any, within and near agree with brute force", "[unit][index]") {
  std::mt19937_64 rng(7);
  // Points in [-1, 1]^3, queries in [-2, 2]^3 (half of them outside the points' box); radii
  // below, at and above the cell (the last one reaches 3 cells each way).
  const std::vector<Vec3> points = randomPoints(2000, 1.0, rng);
  const std::vector<Vec3> queries = randomPoints(500, 2.0, rng);
  const double cell = 0.25;
  const PointIndex index(points, cell);
  REQUIRE(index.size() == points.size());
  for (const double r : {0.1, 0.25, 0.6}) {
    for (const Vec3& x : queries) {
      const std::vector<std::size_t> brute = bruteWithin(points, x, r);
      std::vector<std::size_t> found = index.within(x, r);
      // within() lists the near points in visiting order: the order forEachNear visits them.
      std::vector<std::size_t> visited, visitedWithin;
      index.forEachNear(x, r, [&](std::size_t k) {
        visited.push_back(k);
        if ((points[k] - x).squaredNorm() <= r * r) visitedWithin.push_back(k);
      });
      CHECK(found == visitedWithin);
      std::sort(found.begin(), found.end());
      CHECK(found == brute);
      std::sort(visited.begin(), visited.end());
      CHECK(std::adjacent_find(visited.begin(), visited.end()) == visited.end());  // each once
      CHECK(std::includes(visited.begin(), visited.end(), brute.begin(), brute.end()));
      CHECK(index.anyWithin(x, r) == !brute.empty());
      const long nearest = index.nearest(x, r);
      if (brute.empty()) {
        CHECK(nearest == -1);
      } else {
        REQUIRE(nearest >= 0);
        double best = r * r;
        for (const std::size_t k : brute) best = std::min(best, (points[k] - x).squaredNorm());
        CHECK((points[static_cast<std::size_t>(nearest)] - x).squaredNorm() == best);
      }
    }
  }
}

TEST_CASE("point index: inserting one by one equals building at once", "[unit][index]") {
  std::mt19937_64 rng(11);
  const std::vector<Vec3> points = randomPoints(500, 1.0, rng);
  const PointIndex built(points, 0.3);
  PointIndex inserted(0.3);
  for (std::size_t k = 0; k < points.size(); ++k) CHECK(inserted.insert(points[k]) == k);
  for (const Vec3& x : randomPoints(100, 1.5, rng)) {
    CHECK(inserted.within(x, 0.3) == built.within(x, 0.3));
    CHECK(inserted.nearest(x, 0.3) == built.nearest(x, 0.3));
  }
}

TEST_CASE("point index: visiting order and ties", "[unit][index]") {
  // Cells x outermost, then y, then z; insertion order inside a cell.
  const PointIndex index({Vec3(1.5, 0.5, 0.5), Vec3(0.5, 0.5, 1.5), Vec3(0.5, 1.5, 0.5),
                          Vec3(0.5, 0.5, 1.6), Vec3(-0.5, 1.5, 0.5)},
                         1.0);
  std::vector<std::size_t> order;
  index.forEachNear(Vec3(0.5, 0.5, 0.5), 1.0, [&](std::size_t k) { order.push_back(k); });
  CHECK(order == std::vector<std::size_t>{4, 1, 3, 2, 0});
  // Two points equally near: the one visited last wins.
  const PointIndex tie({Vec3(0.5, 0.5, 0.25), Vec3(0.5, 0.5, 0.75)}, 1.0);
  CHECK(tie.nearest(Vec3(0.5, 0.5, 0.5), 0.5) == 1);
  // A point exactly at the radius counts (dyadic values: exact distances).
  CHECK(tie.nearest(Vec3(0.5, 0.5, 1.0), 0.25) == 1);
  CHECK(tie.nearest(Vec3(0.5, 0.5, 1.0), 0.125) == -1);
}

TEST_CASE("point index: empty sets find nothing", "[unit][index]") {
  const PointIndex empty(std::vector<Vec3>{}, 0.5);
  const PointIndex unfilled(0.5);  // the constructor insert() fills
  for (const PointIndex* index : {&empty, &unfilled}) {
    CHECK(index->size() == 0);
    CHECK(index->nearest(Vec3::Zero(), 10.0) == -1);
    CHECK_FALSE(index->anyWithin(Vec3(3, -2, 1), 10.0));
    CHECK(index->within(Vec3::Zero(), 10.0).empty());
    int visits = 0;
    index->forEachNear(Vec3::Zero(), 1.0, [&](std::size_t) { ++visits; });
    CHECK(visits == 0);
  }
}
