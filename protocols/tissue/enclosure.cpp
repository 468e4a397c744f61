#include "protocols/tissue/enclosure.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>

#include "sim/core/error.h"

namespace protocols {
namespace {

// The grid of the check: point (i, j, k) at box.min() + cell (i, j, k).
class Grid {
 public:
  Grid(const Eigen::AlignedBox3d& box, double cell) : origin_(box.min()), cell_(cell) {
    for (int a = 0; a < 3; ++a)
      n_[a] = static_cast<std::int64_t>(std::floor(box.sizes()[a] / cell)) + 1;
    if (static_cast<double>(n_[0]) * static_cast<double>(n_[1]) * static_cast<double>(n_[2]) > 4e8)
      throw sim::SimError("findEscapePath: more than 4e8 grid points, use a larger cell");
  }
  std::size_t size() const { return static_cast<std::size_t>(n_[0] * n_[1] * n_[2]); }
  std::int64_t count(int axis) const { return n_[axis]; }
  std::size_t index(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return static_cast<std::size_t>((k * n_[1] + j) * n_[0] + i);
  }
  std::array<std::int64_t, 3> cellOf(std::size_t index) const {
    const auto at = static_cast<std::int64_t>(index);
    return {at % n_[0], (at / n_[0]) % n_[1], at / (n_[0] * n_[1])};
  }
  sim::Vec3 point(std::size_t index) const {
    const auto c = cellOf(index);
    return origin_ + cell_ * sim::Vec3(static_cast<double>(c[0]), static_cast<double>(c[1]),
                                       static_cast<double>(c[2]));
  }
  // The grid coordinate of x along an axis, rounded down (not clamped).
  std::int64_t below(const sim::Vec3& x, int axis) const {
    return static_cast<std::int64_t>(std::floor((x[axis] - origin_[axis]) / cell_));
  }
  bool onFace(std::size_t index) const {
    const auto c = cellOf(index);
    for (int a = 0; a < 3; ++a)
      if (c[a] == 0 || c[a] == n_[a] - 1) return true;
    return false;
  }

 private:
  sim::Vec3 origin_;
  double cell_;
  std::array<std::int64_t, 3> n_{};
};

// Grid points closer than `clearance` to an obstacle point.
std::vector<char> blockedPoints(const Grid& grid, const std::vector<sim::Vec3>& obstacles,
                                double clearance) {
  std::vector<char> blocked(grid.size(), 0);
  for (const sim::Vec3& x : obstacles) {
    std::array<std::int64_t, 3> lo{}, hi{};
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::max<std::int64_t>(0, grid.below(x - sim::Vec3::Constant(clearance), a));
      hi[a] = std::min<std::int64_t>(grid.count(a) - 1,
                                     grid.below(x + sim::Vec3::Constant(clearance), a) + 1);
    }
    for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
          const std::size_t at = grid.index(i, j, k);
          if ((grid.point(at) - x).squaredNorm() < clearance * clearance) blocked[at] = 1;
        }
  }
  return blocked;
}

}  // namespace

EscapePath findEscapePath(const std::vector<sim::Vec3>& obstacles,
                          const std::vector<sim::Vec3>& starts, const Eigen::AlignedBox3d& box,
                          double clearance, double cell) {
  const Grid grid(box, cell);
  const std::vector<char> blocked = blockedPoints(grid, obstacles, clearance);
  constexpr std::uint32_t kUnseen = 0xFFFFFFFFu, kStart = 0xFFFFFFFEu;
  if (grid.size() >= kStart)
    throw sim::SimError("findEscapePath: grid too large for its parent links");
  std::vector<std::uint32_t> parent(grid.size(), kUnseen);
  std::deque<std::size_t> queue;
  for (const sim::Vec3& x : starts) {
    if (!box.contains(x)) continue;
    const std::size_t at =
        grid.index(std::clamp<std::int64_t>(grid.below(x, 0), 0, grid.count(0) - 1),
                   std::clamp<std::int64_t>(grid.below(x, 1), 0, grid.count(1) - 1),
                   std::clamp<std::int64_t>(grid.below(x, 2), 0, grid.count(2) - 1));
    if (blocked[at] || parent[at] != kUnseen) continue;
    parent[at] = kStart;
    queue.push_back(at);
  }
  while (!queue.empty()) {
    const std::size_t at = queue.front();
    queue.pop_front();
    if (grid.onFace(at)) {
      EscapePath path;
      for (std::size_t p = at;; p = parent[p]) {
        path.points.push_back(grid.point(p));
        if (parent[p] == kStart) break;
      }
      std::reverse(path.points.begin(), path.points.end());
      return path;
    }
    const auto c = grid.cellOf(at);
    for (int a = 0; a < 3; ++a)
      for (const int step : {-1, 1}) {
        auto next = c;
        next[static_cast<std::size_t>(a)] += step;
        const std::size_t to = grid.index(next[0], next[1], next[2]);  // at is not on a face
        if (blocked[to] || parent[to] != kUnseen) continue;
        parent[to] = static_cast<std::uint32_t>(at);
        queue.push_back(to);
      }
  }
  return {};
}

}  // namespace protocols
