// The threshold step of threshold dynamics at fixed volume: given psi per fluid voxel (the
// linearised energy per unit of oil there), give the oil the voxels where psi is lowest until
// sum u f reaches the target. Used by threshold_dynamics_xu2017.cpp; docs/methods/equilibrium.md.
#pragma once

#include <cstddef>
#include <vector>

namespace sim::equilibrium {

// Whole voxels: u = 1 on the voxels of smallest psi, 0 elsewhere. The voxels whose psi lies
// within `tie` of the last one taken share what is left of the volume alike (a linear program
// with equal costs has every split as a minimum; the even one is the limit of vanishing tension,
// where a whole layer of voxels ties). Deterministic; O(n).
void selectLowest(const std::vector<double>& psi, const std::vector<std::size_t>& fluid,
                  const std::vector<double>& f, double target, double tie, std::vector<double>& u);

// Fractional voxels: u = clamp(1/2 + (lambda - psi) / width, 0, 1) with lambda such that
// sum u f = target. Across a planar interface psi changes by `width` per voxel when width is
// the interface's psi gradient times the spacing, so u is then the voxel's share on the oil side
// of the plane (a volume-of-fluid fraction) and the interface moves by fractions of a voxel
// instead of sticking to whole ones (Ruuth 1998, J. Comput. Phys. 144:603, on pinning in
// threshold dynamics). `lambda` is the level to start from (the previous call's, or NaN) and is
// updated; a safeguarded Newton iteration on the piecewise-linear volume finds it in a few passes.
void selectFractional(const std::vector<double>& psi, const std::vector<std::size_t>& fluid,
                      const std::vector<double>& f, double target, double width, double& lambda,
                      std::vector<double>& u);

}  // namespace sim::equilibrium
