#include "sim/equilibrium/interface_surface.h"

#include <unordered_map>

namespace sim::equilibrium {

namespace {

// One vertex per dual cell the interface u = 1/2 crosses (all eight voxels fluid), at the mean of
// the crossings on its edges; returns the vertex index of each such cell.
std::unordered_map<std::size_t, int> placeVertices(const EquilibriumSolution& s,
                                                   InterfaceSurface& out) {
  const VoxelGrid& g = s.grid;
  const std::vector<double>& u = s.oil;
  const std::vector<double>& f = s.fluidFraction;
  auto fluid = [&](int i, int j, int k) { return f[g.index(i, j, k)] > 0.0; };
  auto value = [&](int i, int j, int k) { return u[g.index(i, j, k)] - 0.5; };
  // Dual cell (i, j, k) spans voxel centres i..i+1, j..j+1, k..k+1.
  std::unordered_map<std::size_t, int> vertexOf;
  for (int k = 0; k + 1 < g.nz; ++k)
    for (int j = 0; j + 1 < g.ny; ++j)
      for (int i = 0; i + 1 < g.nx; ++i) {
        bool allFluid = true, below = false, above = false;
        for (int c = 0; c < 8; ++c) {
          const int a = i + (c & 1), b = j + ((c >> 1) & 1), e = k + ((c >> 2) & 1);
          allFluid = allFluid && fluid(a, b, e);
          (value(a, b, e) < 0.0 ? below : above) = true;
        }
        if (!allFluid || !below || !above) continue;
        Vec3 sum = Vec3::Zero();
        int count = 0;
        for (int c = 0; c < 8; ++c)
          for (int axis = 0; axis < 3; ++axis) {
            if (c & (1 << axis)) continue;  // each of the 12 edges once, from its lower corner
            const int a = i + (c & 1), b = j + ((c >> 1) & 1), e = k + ((c >> 2) & 1);
            const int a2 = a + (axis == 0), b2 = b + (axis == 1), e2 = e + (axis == 2);
            const double v0 = value(a, b, e), v1 = value(a2, b2, e2);
            if ((v0 < 0.0) == (v1 < 0.0)) continue;
            const double t = v0 / (v0 - v1);
            sum += g.centre(a, b, e) + t * (g.centre(a2, b2, e2) - g.centre(a, b, e));
            ++count;
          }
        vertexOf[g.index(i, j, k)] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(sum / count);
      }
  return vertexOf;
}

// One quad per crossed edge between voxel centres, from the four dual cells around it.
void connectQuads(const EquilibriumSolution& s,
                  const std::unordered_map<std::size_t, int>& vertexOf, InterfaceSurface& out) {
  const VoxelGrid& g = s.grid;
  const std::vector<double>& u = s.oil;
  auto value = [&](int i, int j, int k) { return u[g.index(i, j, k)] - 0.5; };
  for (int k = 1; k + 1 < g.nz; ++k)
    for (int j = 1; j + 1 < g.ny; ++j)
      for (int i = 1; i + 1 < g.nx; ++i)
        for (int axis = 0; axis < 3; ++axis) {
          const int i2 = i + (axis == 0), j2 = j + (axis == 1), k2 = k + (axis == 2);
          if (i2 >= g.nx || j2 >= g.ny || k2 >= g.nz) continue;
          const double v0 = value(i, j, k), v1 = value(i2, j2, k2);
          if ((v0 < 0.0) == (v1 < 0.0)) continue;
          // The dual cells sharing this edge: offsets -1/0 along the two other axes.
          const int p = (axis + 1) % 3, q = (axis + 2) % 3;
          int cell[4];
          bool complete = true;
          for (int c = 0; c < 4; ++c) {
            int idx[3] = {i, j, k};
            idx[p] -= (c == 1 || c == 2) ? 1 : 0;
            idx[q] -= (c >= 2) ? 1 : 0;
            const auto it = vertexOf.find(g.index(idx[0], idx[1], idx[2]));
            complete = complete && it != vertexOf.end();
            cell[c] = complete ? it->second : -1;
          }
          if (!complete) continue;
          // Oil (u > 1/2) on the far side: keep the winding so normals point into the oil.
          if (v1 > v0) {
            out.triangles.push_back({cell[0], cell[1], cell[2]});
            out.triangles.push_back({cell[0], cell[2], cell[3]});
          } else {
            out.triangles.push_back({cell[0], cell[2], cell[1]});
            out.triangles.push_back({cell[0], cell[3], cell[2]});
          }
        }
}

}  // namespace

InterfaceSurface interfaceSurface(const EquilibriumSolution& s) {
  InterfaceSurface out;
  const std::unordered_map<std::size_t, int> vertexOf = placeVertices(s, out);
  connectQuads(s, vertexOf, out);
  return out;
}

}  // namespace sim::equilibrium
