// Convolution of a voxel field with the heat kernel G_t(x) = (4 pi t)^(-3/2) exp(-|x|^2 / 4t),
// separably, one axis at a time, with zero outside the grid. The threshold-dynamics energy of
// threshold_dynamics_xu2017.h is written with it. Weights are exp(-(m h)^2 / 4t) normalised to sum
// 1 on each axis and cut at 4 standard deviations (sqrt(2t)); their sum error is below 1e-7.
#pragma once

#include <vector>

#include "sim/equilibrium/voxel_grid.h"

namespace sim::equilibrium {

class GaussianBlur {
 public:
  // `t` [m^2]: the heat kernel's time (its standard deviation per axis is sqrt(2 t)).
  GaussianBlur(const VoxelGrid& grid, double t);

  // out = G_t * in. `out` and `in` are distinct, grid-sized; no allocation after the first call.
  void apply(const std::vector<double>& in, std::vector<double>& out);

  double time() const { return t_; }  // [m^2]
  // [1/m] The factor that turns int chi G*(1 - chi) dV into the area of chi's boundary: sqrt(pi /
  // t) for the continuous kernel (Miranda et al. 2007), here 1 / (h sum_m m w_m) of the sampled
  // weights, exact for a plane between two voxel layers. They differ by 8 % at sqrt(2 t) = 1.06 h,
  // the solver's final kernel: the continuous value would weaken the tension by as much.
  double areaFactor() const { return areaFactor_; }

 private:
  void pass(const std::vector<double>& in, std::vector<double>& out, int axis) const;

  VoxelGrid grid_;
  double t_ = 0.0;
  double areaFactor_ = 0.0;      // [1/m]
  std::vector<double> weights_;  // taps 0..radius (symmetric)
  std::vector<double> scratch_;
};

}  // namespace sim::equilibrium
