// Nearest-neighbour spacing statistics of a point set (reports, and the spacing tests).
#pragma once

#include <vector>

#include "meshing/triangle_mesh.h"

namespace meshing {

struct SpacingStatistics {
  double minimum = 0;   // [unit] smallest nearest-neighbour distance
  double mean = 0;      // [unit] mean nearest-neighbour distance over points that have one
  double maximum = 0;   // [unit] largest nearest-neighbour distance found within the search radius
  size_t isolated = 0;  // points with no neighbour within the search radius
};

// Nearest neighbours within `searchRadius` (grid of that cell size; brute force would be O(N^2)).
SpacingStatistics measureSpacing(const std::vector<Vec3>& points, double searchRadius);

}  // namespace meshing
