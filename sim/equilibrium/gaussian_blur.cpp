#include "sim/equilibrium/gaussian_blur.h"

#include <algorithm>
#include <cmath>

#include "sim/core/error.h"

namespace sim::equilibrium {

GaussianBlur::GaussianBlur(const VoxelGrid& grid, double t) : grid_(grid), t_(t) {
  require(t > 0.0 && std::isfinite(t), "equilibrium: the heat kernel's time must be > 0");
  const double deviation = std::sqrt(2.0 * t) / grid.spacing;  // [voxels]
  const int radius = std::max(1, static_cast<int>(std::ceil(4.0 * deviation)));
  weights_.resize(static_cast<std::size_t>(radius) + 1);
  double sum = 0.0;
  for (int m = 0; m <= radius; ++m) {
    weights_[m] = std::exp(-0.5 * (m / deviation) * (m / deviation));
    sum += (m == 0 ? 1.0 : 2.0) * weights_[m];
  }
  for (double& w : weights_) w /= sum;
  double firstMoment = 0.0;  // sum over m >= 1 of m w_m: pairs across a plane per unit area / h
  for (int m = 1; m <= radius; ++m) firstMoment += m * weights_[m];
  areaFactor_ = 1.0 / (grid.spacing * firstMoment);
}

// Along x each line is contiguous; along y and z the pass runs over whole x-rows at once, so
// every read is a contiguous, vectorisable row (a strided walk along z touched one cache line per
// value and was several times slower).
void GaussianBlur::pass(const std::vector<double>& in, std::vector<double>& out, int axis) const {
  const int nx = grid_.nx, ny = grid_.ny, nz = grid_.nz;
  const int radius = static_cast<int>(weights_.size()) - 1;
  const double* w = weights_.data();
  if (axis == 0) {
#pragma omp parallel for schedule(static) collapse(2)
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j) {
        const double* row = &in[grid_.index(0, j, k)];
        double* target = &out[grid_.index(0, j, k)];
        for (int i = 0; i < nx; ++i) {
          double s = w[0] * row[i];
          const int left = std::min(radius, i), right = std::min(radius, nx - 1 - i);
          for (int r = 1; r <= left; ++r) s += w[r] * row[i - r];
          for (int r = 1; r <= right; ++r) s += w[r] * row[i + r];
          target[i] = s;
        }
      }
    return;
  }
  const int len = axis == 1 ? ny : nz;
  const std::size_t step = axis == 1 ? static_cast<std::size_t>(nx)
                                     : static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  const int other = axis == 1 ? nz : ny;
#pragma omp parallel for schedule(static) collapse(2)
  for (int q = 0; q < other; ++q)
    for (int m = 0; m < len; ++m) {
      const std::size_t base = axis == 1 ? grid_.index(0, m, q) : grid_.index(0, q, m);
      double* target = &out[base];
      const double* centre = &in[base];
      for (int i = 0; i < nx; ++i) target[i] = w[0] * centre[i];
      for (int r = 1; r <= radius; ++r) {
        if (m - r >= 0) {
          const double* row = centre - r * step;
          for (int i = 0; i < nx; ++i) target[i] += w[r] * row[i];
        }
        if (m + r < len) {
          const double* row = centre + r * step;
          for (int i = 0; i < nx; ++i) target[i] += w[r] * row[i];
        }
      }
    }
}

void GaussianBlur::apply(const std::vector<double>& in, std::vector<double>& out) {
  require(in.size() == grid_.size() && &in != &out, "GaussianBlur: field size or aliasing");
  out.resize(in.size());
  scratch_.resize(in.size());
  pass(in, out, 0);
  pass(out, scratch_, 1);
  pass(scratch_, out, 2);
}

}  // namespace sim::equilibrium
