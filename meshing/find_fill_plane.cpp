#include "meshing/find_fill_plane.h"

#include <array>
#include <cmath>
#include <limits>

#include "meshing/mesh_error.h"
#include "meshing/mesh_measures.h"

namespace meshing {

double clippedVolume(const TriangleMesh& mesh, const Vec3& u, double c) {
  const Vec3 o = c * u;  // a point on the plane (u is a unit vector)
  // Sequential on purpose: a parallel floating-point reduction would make the bisection depend on
  // the thread count (docs/developer-guide.md principle 7), and one pass over 20 000 faces takes
  // ~0.1 ms.
  double volume = 0;  // [unit^3]
  for (long long fl = 0; fl < static_cast<long long>(mesh.faces.size()); ++fl) {
    const Triangle& t = mesh.faces[static_cast<size_t>(fl)];
    std::array<Vec3, 3> p;
    std::array<double, 3> s;  // signed height above the plane
    int above = 0;
    for (int k = 0; k < 3; ++k) {
      p[static_cast<size_t>(k)] = mesh.vertices[static_cast<size_t>(t[static_cast<size_t>(k)])] - o;
      s[static_cast<size_t>(k)] = u.dot(p[static_cast<size_t>(k)]);
      above += s[static_cast<size_t>(k)] >= 0;
    }
    if (above == 0) continue;
    if (above == 3) {
      volume += p[0].dot(p[1].cross(p[2])) / 6.0;
      continue;
    }
    // Sutherland-Hodgman against one plane: at most 4 vertices, fanned from the first.
    std::array<Vec3, 4> poly;
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      const size_t a = static_cast<size_t>(k), b = static_cast<size_t>((k + 1) % 3);
      if (s[a] >= 0) poly[static_cast<size_t>(n++)] = p[a];
      if ((s[a] >= 0) != (s[b] >= 0)) {
        const double w = s[a] / (s[a] - s[b]);
        poly[static_cast<size_t>(n++)] = p[a] + w * (p[b] - p[a]);
      }
    }
    for (int k = 1; k + 1 < n; ++k)
      volume +=
          poly[0].dot(poly[static_cast<size_t>(k)].cross(poly[static_cast<size_t>(k + 1)])) / 6.0;
  }
  return volume;
}

FillPlane findFillPlane(const TriangleMesh& mesh, double fraction, const Vec3& direction) {
  if (!(fraction >= 0 && fraction <= 1))
    throw MeshError("fill level",
                    "fill fraction " + std::to_string(fraction) + " is outside [0, 1]",
                    "give the fraction of the cavity volume, e.g. 0.8 for 80 %");
  if (!(direction.norm() > 0) || !direction.allFinite())
    throw MeshError("fill level", "fill direction is zero or not finite",
                    "give the direction the filled phase rises toward, e.g. minus gravity");
  FillPlane plane;
  plane.direction = direction.normalized();
  const Vec3& u = plane.direction;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3& v : mesh.vertices) {
    lo = std::min(lo, u.dot(v));
    hi = std::max(hi, u.dot(v));
  }
  const double total = measureMesh(mesh).signedVolume;  // [unit^3]
  if (!(total > 0))
    throw MeshError("fill level", "the mesh encloses no positive volume",
                    "use the mesh repaired by checkMesh() (closed, outward)");
  const double target = fraction * total;
  const double tolerance = 1e-12 * std::max(hi - lo, 1e-300);
  // Bisection: V(lo) = total, V(hi) = 0, V decreasing.
  for (int iteration = 0; iteration < 200 && hi - lo > tolerance; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (clippedVolume(mesh, u, mid) > target ? lo : hi) = mid;
  }
  plane.offset = 0.5 * (lo + hi);
  plane.volumeAbove = clippedVolume(mesh, u, plane.offset);
  plane.volumeBelow = clippedVolume(mesh, -u, -plane.offset);
  return plane;
}

PhaseSamples sampleFillPhases(const TriangleMesh& mesh, const FillPlane& plane,
                              const VolumeSamplingOptions& options) {
  const MeshQuery query(mesh);
  PhaseSamples out;
  VolumeSamplingOptions side = options;
  side.keep = [&](const Vec3& p) { return plane.isAbove(p) && (!options.keep || options.keep(p)); };
  out.above = sampleVolume(mesh, query, side);
  side.keep = [&](const Vec3& p) {
    return !plane.isAbove(p) && (!options.keep || options.keep(p));
  };
  out.below = sampleVolume(mesh, query, side);
  return out;
}

}  // namespace meshing
