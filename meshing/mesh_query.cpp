// The second CGAL translation unit of meshing/ (the first is cgal_checks.cpp).
#include "meshing/mesh_query.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "meshing/mesh_error.h"

namespace meshing {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
using Inside = CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>;
}  // namespace

struct MeshQuery::Impl {
  SurfaceMesh mesh;
  std::unique_ptr<Tree> tree;
  std::unique_ptr<Inside> inside;
};

MeshQuery::MeshQuery(const TriangleMesh& input) : impl_(std::make_unique<Impl>()) {
  SurfaceMesh& sm = impl_->mesh;
  std::vector<SurfaceMesh::Vertex_index> v;
  v.reserve(input.vertices.size());
  for (const Vec3& p : input.vertices) v.push_back(sm.add_vertex(Point(p.x(), p.y(), p.z())));
  for (size_t f = 0; f < input.faces.size(); ++f) {
    const Triangle& t = input.faces[f];
    if (sm.add_face(v[static_cast<size_t>(t[0])], v[static_cast<size_t>(t[1])],
                    v[static_cast<size_t>(t[2])]) == SurfaceMesh::null_face())
      throw MeshError("mesh", "face " + std::to_string(f) + " makes the surface non-manifold",
                      "run checkMesh() first and use its repaired mesh");
  }
  if (!CGAL::is_closed(sm))
    throw MeshError("mesh", "inside/outside queries need a closed surface",
                    "run checkMesh() first and use its repaired mesh");
  impl_->tree = std::make_unique<Tree>(faces(sm).first, faces(sm).second, sm);
  // Build both lazy structures now: later queries from OpenMP threads then only read them.
  impl_->tree->accelerate_distance_queries();
  impl_->tree->build();
  impl_->inside = std::make_unique<Inside>(*impl_->tree);
}

MeshQuery::~MeshQuery() = default;
MeshQuery::MeshQuery(MeshQuery&&) noexcept = default;
MeshQuery& MeshQuery::operator=(MeshQuery&&) noexcept = default;

bool MeshQuery::isInside(const Vec3& p) const {
  return (*impl_->inside)(Point(p.x(), p.y(), p.z())) != CGAL::ON_UNBOUNDED_SIDE;
}

double MeshQuery::squaredDistance(const Vec3& p) const {
  return CGAL::to_double(impl_->tree->squared_distance(Point(p.x(), p.y(), p.z())));
}

bool MeshQuery::isWithin(const Vec3& p, double distance) const {
  // Sphere_3 queries on the AABB tree test the solid ball (squared distance <= r^2).
  return impl_->tree->do_intersect(
      Kernel::Sphere_3(Point(p.x(), p.y(), p.z()), distance * distance));
}

Vec3 MeshQuery::closestPoint(const Vec3& p, int* face) const {
  const auto [q, primitive] = impl_->tree->closest_point_and_primitive(Point(p.x(), p.y(), p.z()));
  if (face) *face = static_cast<int>(primitive.idx());
  return Vec3(q.x(), q.y(), q.z());
}

bool MeshQuery::lineCrossings(const Vec3& p, int axis, std::vector<double>& crossings) const {
  crossings.clear();
  Kernel::Vector_3 direction(axis == 0, axis == 1, axis == 2);
  const Kernel::Line_3 line(Point(p.x(), p.y(), p.z()), direction);
  using Hit = Tree::Intersection_and_primitive_id<Kernel::Line_3>::Type;
  std::vector<Hit> hits;
  impl_->tree->all_intersections(line, std::back_inserter(hits));
  for (const Hit& hit : hits) {
    const Point* q = boost::get<Point>(&hit.first);
    if (q == nullptr) return false;  // the line lies in a face: a segment
    crossings.push_back(CGAL::to_double((*q)[axis]));
  }
  std::sort(crossings.begin(), crossings.end());
  if (crossings.size() % 2 != 0) return false;
  // Equal crossings: the line passes through an edge or vertex shared by several faces.
  for (size_t k = 1; k < crossings.size(); ++k)
    if (crossings[k] - crossings[k - 1] <= 1e-12 * (std::abs(crossings[k]) + 1e-300)) return false;
  return true;
}

}  // namespace meshing
