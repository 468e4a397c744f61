#include "sim/equilibrium/volume_threshold.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sim::equilibrium {
namespace {

// [lowest, highest] psi over the fluid voxels.
std::pair<double, double> psiRange(const std::vector<double>& psi,
                                   const std::vector<std::size_t>& fluid) {
  double lo = psi[fluid[0]], hi = lo;
  for (std::size_t v : fluid) {
    lo = std::min(lo, psi[v]);
    hi = std::max(hi, psi[v]);
  }
  return {lo, hi};
}

double shareAt(double lambda, double psi, double width) {
  return std::clamp(0.5 + (lambda - psi) / width, 0.0, 1.0);
}

}  // namespace

// O(n): a histogram of psi finds the voxels that straddle the quantile, and only those are
// sorted.
void selectLowest(const std::vector<double>& psi, const std::vector<std::size_t>& fluid,
                  const std::vector<double>& f, double target, double tie, std::vector<double>& u) {
  const auto [lo, hi] = psiRange(psi, fluid);
  constexpr int kBins = 1 << 16;
  const double scale = hi > lo ? (kBins - 1) / (hi - lo) : 0.0;
  auto binOf = [&](std::size_t v) { return static_cast<int>((psi[v] - lo) * scale); };
  std::vector<double> weight(kBins, 0.0);
  for (std::size_t v : fluid) weight[binOf(v)] += f[v];
  int cut = 0;
  double below = 0.0;
  while (cut < kBins - 1 && below + weight[cut] < target) below += weight[cut++];
  std::vector<std::size_t> straddling;
  for (std::size_t v : fluid)
    if (binOf(v) == cut) straddling.push_back(v);
  std::sort(straddling.begin(), straddling.end(), [&](std::size_t a, std::size_t b) {
    return psi[a] < psi[b] || (psi[a] == psi[b] && a < b);
  });
  double cutPsi = straddling.empty() ? hi : psi[straddling.back()];
  for (std::size_t v : straddling) {
    below += f[v];
    if (below >= target) {
      cutPsi = psi[v];
      break;
    }
  }
  double lower = 0.0, tied = 0.0;  // [voxels] below the tie band, in it
  for (std::size_t v : fluid) {
    if (psi[v] < cutPsi - tie)
      lower += f[v];
    else if (psi[v] <= cutPsi + tie)
      tied += f[v];
  }
  const double share = tied > 0.0 ? std::clamp((target - lower) / tied, 0.0, 1.0) : 0.0;
  for (std::size_t v : fluid)
    u[v] = psi[v] < cutPsi - tie ? 1.0 : (psi[v] <= cutPsi + tie ? share : 0.0);
}

void selectFractional(const std::vector<double>& psi, const std::vector<std::size_t>& fluid,
                      const std::vector<double>& f, double target, double width, double& lambda,
                      std::vector<double>& u) {
  // V(lambda) = sum f share is continuous, piecewise linear and non-decreasing: keep a bracket
  // [lo, hi] around the root, take Newton's step on the local slope when it stays inside, and
  // halve the bracket when it does not.
  auto [lo, hi] = psiRange(psi, fluid);
  lo -= width;
  hi += width;
  if (!(lambda > lo && lambda < hi)) lambda = 0.5 * (lo + hi);
  const double tolerance = 1e-12 * target;
  for (int pass = 0; pass < 200; ++pass) {
    double volume = 0.0, slope = 0.0;
    for (std::size_t v : fluid) {
      const double share = shareAt(lambda, psi[v], width);
      volume += f[v] * share;
      if (share > 0.0 && share < 1.0) slope += f[v] / width;  // on the ramp
    }
    if (std::abs(volume - target) <= tolerance) break;
    (volume < target ? lo : hi) = lambda;
    const double bisection = 0.5 * (lo + hi);
    const double newton = slope > 0.0 ? lambda + (target - volume) / slope : bisection;
    lambda = newton > lo && newton < hi ? newton : bisection;
    if (hi - lo <= 1e-15 * (std::abs(lo) + std::abs(hi))) break;
  }
  for (std::size_t v : fluid) u[v] = shareAt(lambda, psi[v], width);
}

}  // namespace sim::equilibrium
