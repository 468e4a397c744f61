// Internal to meshing/: the CGAL parts of checkMesh(), behind plain types so that only
// cgal_checks.cpp pays CGAL's compile cost (STACK.md section 4). Not for use outside meshing/.
#pragma once

#include <utility>
#include <vector>

#include "meshing/triangle_mesh.h"

namespace meshing::detail {

// Indices of faces whose three corners are exactly collinear (exact predicate, EPICK) or that
// repeat a vertex.
std::vector<int> findDegenerateFaces(const TriangleMesh& mesh);

// Removes degenerate faces of a closed manifold mesh by edge collapses and flips
// (PMP::remove_degenerate_faces), keeping the mesh closed. `faceOrigin[f]` (input face of each
// face) is carried along; faces CGAL creates get -1. Returns false if some could not be removed.
bool removeDegenerateFaces(TriangleMesh& mesh, std::vector<int>& faceOrigin);

// Pairs of faces that intersect other than along a shared edge or vertex, at most maxPairs.
std::vector<std::pair<int, int>> findSelfIntersections(const TriangleMesh& mesh, size_t maxPairs);

}  // namespace meshing::detail
