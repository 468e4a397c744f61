#include "protocols/scenario/tissue_layer_volumes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace protocols {

double kernelHalfSpaceFraction(const sim::Kernel& kernel, double z) {
  const double h = kernel.supportRadius();  // [m]
  if (z >= h) return 0.0;
  if (z <= -h) return 1.0;
  if (z < 0.0) return 1.0 - kernelHalfSpaceFraction(kernel, -z);
  // Over the plane at distance s the kernel integrates to 2 pi int_s^h W(r) r dr (radial
  // coordinates in the plane: rho^2 = r^2 - s^2, rho d rho = r dr); then integrate s from z to h.
  // Midpoint rule, 400 x 400 points: the cubic spline's pieces are smooth, error < 1e-5.
  constexpr int kSteps = 400;
  const double ds = (h - z) / kSteps;
  double total = 0.0;
  for (int a = 0; a < kSteps; ++a) {
    const double s = z + (a + 0.5) * ds;
    const double dr = (h - s) / kSteps;
    double plane = 0.0;
    for (int b = 0; b < kSteps; ++b) {
      const double r = s + (b + 0.5) * dr;
      plane += kernel.W(r) * r * dr;
    }
    total += 2.0 * std::numbers::pi * plane * ds;
  }
  return total;
}

std::vector<double> calibratedLayerVolumes(const sim::Kernel& kernel, const std::vector<sim::Vec3>& points,
                                           const std::vector<double>& depths,
                                           const std::vector<sim::Vec3>& others,
                                           const std::vector<sim::Vec3>& walls, double d) {
  const double h2 = kernel.supportRadius() * kernel.supportRadius();  // [m^2]
  // Akinci volumes of the walls within reach of a tissue particle.
  std::vector<char> near(walls.size(), 0);
  for (std::size_t b = 0; b < walls.size(); ++b)
    for (const sim::Vec3& x : points)
      if ((x - walls[b]).squaredNorm() < h2) {
        near[b] = 1;
        break;
      }
  std::vector<double> wallVolume(walls.size(), 0.0);  // [m^3]
  for (std::size_t b = 0; b < walls.size(); ++b) {
    if (!near[b]) continue;
    double sum = 0.0;
    for (const sim::Vec3& y : walls) {
      const double r2 = (y - walls[b]).squaredNorm();
      if (r2 < h2) sum += kernel.W(std::sqrt(r2));
    }
    wallVolume[b] = 1.0 / sum;
  }
  // Phi(z) on the distinct depths (layers share theirs): a small table, exact per layer.
  std::vector<double> phi(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto same = std::find(depths.begin(), depths.begin() + static_cast<std::ptrdiff_t>(i), depths[i]);
    const auto k = static_cast<std::size_t>(same - depths.begin());
    phi[i] = k < i ? phi[k] : kernelHalfSpaceFraction(kernel, depths[i]);
  }
  std::vector<double> volume(points.size());
  const long n = static_cast<long>(points.size());
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const auto i = static_cast<std::size_t>(a);
    double sum = phi[i] / (d * d * d);  // [1/m^3]
    for (const auto* set : {&points, &others})
      for (const sim::Vec3& x : *set) {
        const double r2 = (x - points[i]).squaredNorm();
        if (r2 < h2) sum += kernel.W(std::sqrt(r2));
      }
    double wall = 0.0;  // [1] sum_b V_b W_ib
    for (std::size_t b = 0; b < walls.size(); ++b) {
      if (!near[b]) continue;
      const double r2 = (walls[b] - points[i]).squaredNorm();
      if (r2 < h2) wall += wallVolume[b] * kernel.W(std::sqrt(r2));
    }
    volume[i] = std::max(1.0 - wall, 0.25) / sum;
  }
  return volume;
}

}  // namespace protocols
