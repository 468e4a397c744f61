// The CGAL translation unit of checkMesh() (one of the two CGAL TUs of meshing/; the other is
// mesh_query.cpp). Everything crosses the boundary as TriangleMesh + index vectors.
#include "meshing/cgal_checks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Surface_mesh.h>

#include <iterator>

namespace meshing::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using FaceIndex = SurfaceMesh::Face_index;
namespace PMP = CGAL::Polygon_mesh_processing;

// Builds a Surface_mesh whose face k is input face k (add_face appends in order). Faces that
// Surface_mesh refuses (non-manifold) get no index; checkMesh() has excluded those already.
SurfaceMesh toSurfaceMesh(const TriangleMesh& mesh, std::vector<FaceIndex>* faceHandles = nullptr) {
  SurfaceMesh sm;
  sm.reserve(static_cast<SurfaceMesh::size_type>(mesh.vertices.size()),
             static_cast<SurfaceMesh::size_type>(3 * mesh.faces.size() / 2),
             static_cast<SurfaceMesh::size_type>(mesh.faces.size()));
  std::vector<SurfaceMesh::Vertex_index> v;
  v.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) v.push_back(sm.add_vertex(Point(p.x(), p.y(), p.z())));
  if (faceHandles) faceHandles->assign(mesh.faces.size(), SurfaceMesh::null_face());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Triangle& t = mesh.faces[f];
    const FaceIndex h = sm.add_face(v[static_cast<size_t>(t[0])], v[static_cast<size_t>(t[1])],
                                    v[static_cast<size_t>(t[2])]);
    if (faceHandles) (*faceHandles)[f] = h;
  }
  return sm;
}

}  // namespace

std::vector<int> findDegenerateFaces(const TriangleMesh& mesh) {
  std::vector<int> out;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Triangle& t = mesh.faces[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      out.push_back(static_cast<int>(f));
      continue;
    }
    const Vec3& a = mesh.vertices[static_cast<size_t>(t[0])];
    const Vec3& b = mesh.vertices[static_cast<size_t>(t[1])];
    const Vec3& c = mesh.vertices[static_cast<size_t>(t[2])];
    if (CGAL::collinear(Point(a.x(), a.y(), a.z()), Point(b.x(), b.y(), b.z()),
                        Point(c.x(), c.y(), c.z())))
      out.push_back(static_cast<int>(f));
  }
  return out;
}

bool removeDegenerateFaces(TriangleMesh& mesh, std::vector<int>& faceOrigin) {
  std::vector<FaceIndex> handles;
  SurfaceMesh sm = toSurfaceMesh(mesh, &handles);
  auto [origin, created] = sm.add_property_map<FaceIndex, int>("f:origin", -1);
  (void)created;
  for (size_t f = 0; f < handles.size(); ++f)
    if (handles[f] != SurfaceMesh::null_face()) origin[handles[f]] = faceOrigin[f];
  const bool ok = PMP::remove_degenerate_faces(sm);
  sm.collect_garbage();
  // Back to the plain mesh; vertex indices are dense after collect_garbage().
  mesh.vertices.clear();
  mesh.faces.clear();
  faceOrigin.clear();
  for (auto vi : sm.vertices()) {
    const Point& p = sm.point(vi);
    mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (FaceIndex f : sm.faces()) {
    Triangle t{};
    int k = 0;
    for (auto vi : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (k < 3) t[static_cast<size_t>(k)] = static_cast<int>(vi.idx());
      ++k;
    }
    if (k != 3) return false;
    mesh.faces.push_back(t);
    faceOrigin.push_back(origin[f]);
  }
  return ok;
}

std::vector<std::pair<int, int>> findSelfIntersections(const TriangleMesh& mesh, size_t maxPairs) {
  const SurfaceMesh sm = toSurfaceMesh(mesh);
  std::vector<std::pair<FaceIndex, FaceIndex>> pairs;
  PMP::self_intersections(sm, std::back_inserter(pairs));
  std::vector<std::pair<int, int>> out;
  for (const auto& [f, g] : pairs) {
    if (out.size() >= maxPairs) break;
    out.emplace_back(static_cast<int>(f.idx()), static_cast<int>(g.idx()));
  }
  return out;
}

}  // namespace meshing::detail
