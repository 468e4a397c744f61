// The fraction of each voxel of a box grid that lies inside a closed mesh: what the static
// equilibrium solver (sim/equilibrium/) takes as its cavity. Inside tests run one axis-parallel
// line per voxel row (MeshQuery::lineCrossings); only voxels whose 27-neighbourhood straddles the
// surface ask for their distance to it, and get clamp(1/2 - s/h, 0, 1) for the signed distance s
// (negative inside), the exact fraction for a wall parallel to a voxel face.
#pragma once

#include <vector>

#include "meshing/mesh_query.h"

namespace meshing {

struct VoxelBox {
  Vec3 origin = Vec3::Zero();  // corner of voxel (0, 0, 0); voxels x fastest
  double spacing = 0.0;        // edge h
  int nx = 0, ny = 0, nz = 0;
};

std::vector<double> voxelInsideFractions(const MeshQuery& query, const VoxelBox& box);

}  // namespace meshing
