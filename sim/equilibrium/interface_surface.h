// The equilibrium interface as a triangle surface (surface nets: one vertex per dual cell that
// the oil share u crosses 1/2 in, at the mean of its edge crossings; two triangles per crossed
// voxel-to-voxel edge). Only cells whose eight voxels all hold fluid are meshed, so the surface
// stops about a voxel short of the wall. For ParaView (a PLY or STL written by the caller).
#pragma once

#include <array>
#include <vector>

#include "sim/equilibrium/threshold_dynamics_xu2017.h"

namespace sim::equilibrium {

struct InterfaceSurface {
  std::vector<Vec3> vertices;                 // [m]
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from the oil
};

InterfaceSurface interfaceSurface(const EquilibriumSolution& solution);

}  // namespace sim::equilibrium
