#include "meshing/sample_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "meshing/mesh_error.h"
#include "meshing/point_index.h"
#include "meshing/random_stream.h"

namespace meshing {
namespace {

struct Faces {
  std::vector<double> area;
  std::vector<Vec3> normal;
  double total = 0;
};

struct Candidates {
  std::vector<Vec3> point;
  std::vector<double> area;          // equal share of its face's area
  std::vector<std::uint64_t> order;  // random key of the dart-throwing order
  std::vector<int> face;
};

Faces measureFaces(const TriangleMesh& mesh) {
  const size_t nf = mesh.faces.size();
  Faces faces;
  faces.area.resize(nf);
  faces.normal.resize(nf);
  for (size_t f = 0; f < nf; ++f) {
    const Triangle& t = mesh.faces[f];
    const Vec3& a = mesh.vertices[static_cast<size_t>(t[0])];
    const Vec3 n = (mesh.vertices[static_cast<size_t>(t[1])] - a)
                       .cross(mesh.vertices[static_cast<size_t>(t[2])] - a);
    faces.area[f] = 0.5 * n.norm();
    faces.normal[f] = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    faces.total += faces.area[f];
  }
  return faces;
}

// Phase 1: candidates per face, count proportional to area (at least one, so no face's area is
// lost), each carrying an equal share of its face's area.
Candidates drawCandidates(const TriangleMesh& mesh, const std::vector<double>& faceArea,
                          double perArea, std::uint64_t seed) {
  const size_t nf = mesh.faces.size();
  std::vector<size_t> first(nf + 1, 0);
  for (size_t f = 0; f < nf; ++f) {
    detail::RandomStream rng(seed, f);
    const double expected = faceArea[f] * perArea;
    first[f + 1] =
        first[f] + std::max<size_t>(1, static_cast<size_t>(std::floor(expected + rng.uniform())));
  }
  const size_t nc = first[nf];
  Candidates c;
  c.point.resize(nc);
  c.area.resize(nc);
  c.order.resize(nc);
  c.face.resize(nc);
#pragma omp parallel for schedule(static)
  for (long long fl = 0; fl < static_cast<long long>(nf); ++fl) {
    const size_t f = static_cast<size_t>(fl);
    detail::RandomStream rng(seed, f);
    rng.uniform();  // the draw used for the count above
    const Triangle& t = mesh.faces[f];
    const Vec3& a = mesh.vertices[static_cast<size_t>(t[0])];
    const Vec3 ab = mesh.vertices[static_cast<size_t>(t[1])] - a;
    const Vec3 ac = mesh.vertices[static_cast<size_t>(t[2])] - a;
    const double share = faceArea[f] / static_cast<double>(first[f + 1] - first[f]);
    for (size_t k = first[f]; k < first[f + 1]; ++k) {
      double u = rng.uniform(), v = rng.uniform();
      if (u + v > 1) {  // reflect into the triangle: uniform over its area
        u = 1 - u;
        v = 1 - v;
      }
      c.point[k] = a + u * ab + v * ac;
      c.area[k] = share;
      c.face[k] = static_cast<int>(f);
      c.order[k] = rng.next();
    }
  }
  return c;
}

// Phase 2: dart throwing in a seeded random order (sequential: each decision depends on all
// earlier ones). Fills the points and faces of `out`; the index holds the same points.
void throwDarts(const Candidates& c, double radius, SurfaceSamples& out, PointIndex& index) {
  const size_t nc = c.point.size();
  std::vector<size_t> sequence(nc);
  std::iota(sequence.begin(), sequence.end(), size_t{0});
  std::sort(sequence.begin(), sequence.end(), [&](size_t i, size_t j) {
    return c.order[i] != c.order[j] ? c.order[i] < c.order[j] : i < j;
  });
  const double r2 = radius * radius;
  for (size_t k : sequence) {
    bool free = true;
    index.forEachNear(c.point[k], radius, [&](size_t s) {
      if (free && (out.points[s] - c.point[k]).squaredNorm() < r2) free = false;
    });
    if (!free) continue;
    index.insert(c.point[k]);
    out.points.push_back(c.point[k]);
    out.faceIndex.push_back(c.face[k]);
  }
}

// Phase 3: each candidate's area goes to its nearest sample (every rejected candidate has one
// within r, so the search around it always finds it; ties go to the lower sample index).
std::vector<double> sampleAreas(const Candidates& c, double radius, const SurfaceSamples& out,
                                const PointIndex& index) {
  const size_t nc = c.point.size();
  std::vector<int> owner(nc, -1);
#pragma omp parallel for schedule(static)
  for (long long cl = 0; cl < static_cast<long long>(nc); ++cl) {
    const size_t k = static_cast<size_t>(cl);
    double best = std::numeric_limits<double>::infinity();
    index.forEachNear(c.point[k], radius, [&](size_t sample) {
      const int s = static_cast<int>(sample);
      const double q = (out.points[sample] - c.point[k]).squaredNorm();
      if (q < best || (q == best && s < owner[k])) {
        best = q;
        owner[k] = s;
      }
    });
  }
  std::vector<double> areas(out.points.size(), 0.0);
  for (size_t k = 0; k < nc; ++k) areas[static_cast<size_t>(owner[k])] += c.area[k];
  return areas;
}

}  // namespace

SurfaceSamples sampleSurface(const TriangleMesh& mesh, const SurfaceSamplingOptions& options) {
  const double d = options.spacing;  // [unit]
  if (!(d > 0) || !std::isfinite(d))
    throw MeshError("surface sampling", "spacing must be positive and finite", "give e.g. 0.4 mm");
  if (!(options.exclusion > 0 && options.exclusion <= 1.5) || !(options.candidatesPerArea >= 4))
    throw MeshError("surface sampling", "exclusion must lie in (0, 1.5] and candidatesPerArea >= 4",
                    "use the defaults 0.9 and 24");
  const double radius = options.exclusion * d;  // [unit]
  const Faces faces = measureFaces(mesh);
  const double perArea = options.candidatesPerArea / (d * d);  // [1/unit^2]
  if (faces.total * perArea > 5e7)
    throw MeshError("surface sampling",
                    "spacing too small for this surface (" +
                        std::to_string(static_cast<long long>(faces.total / (d * d))) + " samples)",
                    "increase the spacing or check the units");
  const Candidates candidates = drawCandidates(mesh, faces.area, perArea, options.seed);
  SurfaceSamples out;
  PointIndex index(radius);
  throwDarts(candidates, radius, out, index);
  out.areas = sampleAreas(candidates, radius, out, index);
  out.normals.reserve(out.points.size());
  for (int f : out.faceIndex) out.normals.push_back(faces.normal[static_cast<size_t>(f)]);
  return out;
}

}  // namespace meshing
