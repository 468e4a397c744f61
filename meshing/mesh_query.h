// Inside/outside and distance queries against a closed triangle mesh (CGAL AABB tree and
// Side_of_triangle_mesh behind a PIMPL, so no CGAL type leaks into users' translation units).
// Build once, query many times; the queries are const and safe from several OpenMP threads.
#pragma once

#include <memory>
#include <vector>

#include "meshing/triangle_mesh.h"

namespace meshing {

class MeshQuery {
 public:
  // `mesh` must be closed and outward oriented (checkMesh() output); it is copied.
  explicit MeshQuery(const TriangleMesh& mesh);
  ~MeshQuery();
  MeshQuery(MeshQuery&&) noexcept;
  MeshQuery& operator=(MeshQuery&&) noexcept;

  // true for points strictly inside or on the surface.
  bool isInside(const Vec3& p) const;
  double squaredDistance(const Vec3& p) const;  // [unit^2] to the nearest surface point
  // true if some surface point lies within `distance` of p. Much cheaper than squaredDistance()
  // deep inside a round cavity, where every face is nearly equidistant and the tree cannot prune.
  bool isWithin(const Vec3& p, double distance) const;
  // Nearest surface point and the index of the face it lies on.
  Vec3 closestPoint(const Vec3& p, int* face = nullptr) const;
  // Coordinates along `axis` (0 x, 1 y, 2 z) where the axis-parallel line through p crosses the
  // surface, sorted. Returns false when the line grazes an edge, a vertex or a face (duplicate or
  // segment intersections, odd count): the parity of the crossings is then unreliable and the
  // caller must fall back to isInside() per point.
  bool lineCrossings(const Vec3& p, int axis, std::vector<double>& crossings) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace meshing
