#include "meshing/sample_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "meshing/mesh_error.h"
#include "meshing/point_index.h"
#include "meshing/random_stream.h"

namespace meshing {

SurfaceSamples sampleSurface(const TriangleMesh& mesh, const SurfaceSamplingOptions& options) {
  const double d = options.spacing;  // [unit]
  if (!(d > 0) || !std::isfinite(d))
    throw MeshError("surface sampling", "spacing must be positive and finite", "give e.g. 0.4 mm");
  if (!(options.exclusion > 0 && options.exclusion <= 1.5) || !(options.candidatesPerArea >= 4))
    throw MeshError("surface sampling", "exclusion must lie in (0, 1.5] and candidatesPerArea >= 4",
                    "use the defaults 0.9 and 24");
  const double radius = options.exclusion * d;  // [unit]
  const size_t nf = mesh.faces.size();

  // Phase 1: candidates per face, count proportional to area (at least one, so no face's area is
  // lost), each carrying an equal share of its face's area.
  std::vector<double> faceArea(nf);
  std::vector<Vec3> faceNormal(nf);
  double total = 0;
  for (size_t f = 0; f < nf; ++f) {
    const Triangle& t = mesh.faces[f];
    const Vec3& a = mesh.vertices[static_cast<size_t>(t[0])];
    const Vec3 n = (mesh.vertices[static_cast<size_t>(t[1])] - a)
                       .cross(mesh.vertices[static_cast<size_t>(t[2])] - a);
    faceArea[f] = 0.5 * n.norm();
    faceNormal[f] = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    total += faceArea[f];
  }
  const double perArea = options.candidatesPerArea / (d * d);  // [1/unit^2]
  if (total * perArea > 5e7)
    throw MeshError("surface sampling",
                    "spacing too small for this surface (" +
                        std::to_string(static_cast<long long>(total / (d * d))) + " samples)",
                    "increase the spacing or check the units");
  std::vector<size_t> first(nf + 1, 0);
  for (size_t f = 0; f < nf; ++f) {
    detail::RandomStream rng(options.seed, f);
    const double expected = faceArea[f] * perArea;
    first[f + 1] =
        first[f] + std::max<size_t>(1, static_cast<size_t>(std::floor(expected + rng.uniform())));
  }
  const size_t nc = first[nf];
  std::vector<Vec3> candidate(nc);
  std::vector<double> candidateArea(nc);
  std::vector<std::uint64_t> order(nc);
  std::vector<int> candidateFace(nc);
#pragma omp parallel for schedule(static)
  for (long long fl = 0; fl < static_cast<long long>(nf); ++fl) {
    const size_t f = static_cast<size_t>(fl);
    detail::RandomStream rng(options.seed, f);
    rng.uniform();  // the draw used for the count above
    const Triangle& t = mesh.faces[f];
    const Vec3& a = mesh.vertices[static_cast<size_t>(t[0])];
    const Vec3 ab = mesh.vertices[static_cast<size_t>(t[1])] - a;
    const Vec3 ac = mesh.vertices[static_cast<size_t>(t[2])] - a;
    const double share = faceArea[f] / static_cast<double>(first[f + 1] - first[f]);
    for (size_t c = first[f]; c < first[f + 1]; ++c) {
      double u = rng.uniform(), v = rng.uniform();
      if (u + v > 1) {  // reflect into the triangle: uniform over its area
        u = 1 - u;
        v = 1 - v;
      }
      candidate[c] = a + u * ab + v * ac;
      candidateArea[c] = share;
      candidateFace[c] = static_cast<int>(f);
      order[c] = rng.next();
    }
  }

  // Phase 2: dart throwing in a seeded random order (sequential: each decision depends on all
  // earlier ones).
  std::vector<size_t> sequence(nc);
  std::iota(sequence.begin(), sequence.end(), size_t{0});
  std::sort(sequence.begin(), sequence.end(),
            [&](size_t i, size_t j) { return order[i] != order[j] ? order[i] < order[j] : i < j; });
  SurfaceSamples out;
  PointIndex grid(radius);
  const double r2 = radius * radius;
  for (size_t c : sequence) {
    bool free = true;
    grid.forEachNear(candidate[c], radius, [&](size_t s) {
      if (free && (out.points[s] - candidate[c]).squaredNorm() < r2) free = false;
    });
    if (!free) continue;
    grid.insert(candidate[c]);
    out.points.push_back(candidate[c]);
    out.faceIndex.push_back(candidateFace[c]);
  }

  // Phase 3: each candidate's area goes to its nearest sample (every rejected candidate has one
  // within r, so the search around it always finds it; ties go to the lower sample index).
  std::vector<int> owner(nc, -1);
#pragma omp parallel for schedule(static)
  for (long long cl = 0; cl < static_cast<long long>(nc); ++cl) {
    const size_t c = static_cast<size_t>(cl);
    double best = std::numeric_limits<double>::infinity();
    grid.forEachNear(candidate[c], radius, [&](size_t sample) {
      const int s = static_cast<int>(sample);
      const double q = (out.points[sample] - candidate[c]).squaredNorm();
      if (q < best || (q == best && s < owner[c])) {
        best = q;
        owner[c] = s;
      }
    });
  }
  out.areas.assign(out.points.size(), 0.0);
  for (size_t c = 0; c < nc; ++c) out.areas[static_cast<size_t>(owner[c])] += candidateArea[c];
  out.normals.reserve(out.points.size());
  for (int f : out.faceIndex) out.normals.push_back(faceNormal[static_cast<size_t>(f)]);
  return out;
}

}  // namespace meshing
