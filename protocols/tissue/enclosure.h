// Is the fluid walled in? A geometric check on an assembled scene (no stepping): a path from the
// fluid to the edge of a box that keeps at least `clearance` from every obstacle point (wall
// particles, anchored tissue particles). Used by the tissue tests (fluid that leaves the
// globe through holes in the walls behind the sclera, docs/methods/elasticity.md "The limbus band,
// watertight") and for finding such a hole.
//
// Criterion: grid points of spacing `cell` inside `box`, a point open when no obstacle lies
// closer than `clearance`; a path is a chain of open points that are neighbours along an axis,
// from a start's point to a point on the box's faces. With clearance d/2 a wall sampled at d/2
// has no open point in it (in its plane no point is farther than 0.35 d from a wall particle on
// a square d/2 lattice), one sampled at d has (0.71 d), which is the wall that leaked in
// protocols/assembly/README.md. The grid resolves clearances to about cell / 2.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "sim/core/types.h"

namespace protocols {

struct EscapePath {
  std::vector<sim::Vec3> points;  // [m] from a start to the box's face; empty: walled in
  bool escapes() const { return !points.empty(); }
};

// Breadth-first over the grid from the starts' points (starts in blocked points are skipped), so
// the path is a shortest one in grid steps.
EscapePath findEscapePath(const std::vector<sim::Vec3>& obstacles,
                          const std::vector<sim::Vec3>& starts, const Eigen::AlignedBox3d& box,
                          double clearance, double cell);

}  // namespace protocols
