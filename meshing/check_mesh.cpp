#include "meshing/check_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include "meshing/cgal_checks.h"
#include "meshing/import_mesh.h"
#include "meshing/mesh_error.h"

namespace meshing {
namespace {

constexpr size_t kMaxListed = 6;  // face indices listed per problem before "..."

std::string point(const Vec3& p) {
  // Round-off noise such as -4.9e-17 next to 9.5 reads as 0.
  const double scale = p.cwiseAbs().maxCoeff();
  const auto clean = [&](double c) { return std::abs(c) < 1e-12 * scale ? 0.0 : c; };
  std::ostringstream s;
  s.precision(5);
  s << '(' << clean(p.x()) << ", " << clean(p.y()) << ", " << clean(p.z()) << ')';
  return s.str();
}

// Input face indices, each once, in order of first appearance; -1 (a face added by a hole
// repair) reads "new".
std::string faceList(const std::vector<int>& faces) {
  std::vector<int> unique;
  for (int f : faces)
    if (std::find(unique.begin(), unique.end(), f) == unique.end()) unique.push_back(f);
  std::ostringstream s;
  for (size_t k = 0; k < unique.size() && k < kMaxListed; ++k) {
    s << (k ? ", " : "");
    if (unique[k] < 0)
      s << "new";
    else
      s << unique[k];
  }
  if (unique.size() > kMaxListed) s << ", ... (" << unique.size() << " in all)";
  return s.str();
}

std::string faceName(int f) {
  return f < 0 ? std::string("a hole-filling face") : "face " + std::to_string(f);
}

Vec3 centroid(const TriangleMesh& m, size_t f) {
  const Triangle& t = m.faces[f];
  return (m.vertices[static_cast<size_t>(t[0])] + m.vertices[static_cast<size_t>(t[1])] +
          m.vertices[static_cast<size_t>(t[2])]) /
         3.0;
}

double faceArea(const TriangleMesh& m, size_t f) {
  const Triangle& t = m.faces[f];
  const Vec3& a = m.vertices[static_cast<size_t>(t[0])];
  return 0.5 * (m.vertices[static_cast<size_t>(t[1])] - a)
                   .cross(m.vertices[static_cast<size_t>(t[2])] - a)
                   .norm();
}

using EdgeKey = std::pair<int, int>;  // (smaller, larger) vertex index
EdgeKey edgeKey(int a, int b) { return a < b ? EdgeKey{a, b} : EdgeKey{b, a}; }

struct EdgeUse {
  int face;
  int from;  // the face traverses the edge from -> to
};

// Undirected edge -> the faces using it (in face order).
std::map<EdgeKey, std::vector<EdgeUse>> edgeUses(const TriangleMesh& m) {
  std::map<EdgeKey, std::vector<EdgeUse>> uses;
  for (size_t f = 0; f < m.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.faces[f][static_cast<size_t>(k)],
                b = m.faces[f][static_cast<size_t>((k + 1) % 3)];
      uses[edgeKey(a, b)].push_back({static_cast<int>(f), a});
    }
  return uses;
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[static_cast<size_t>(x)] != x)
      x = parent[static_cast<size_t>(x)] =
          parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
    return x;
  }
  void unite(int a, int b) { parent[static_cast<size_t>(find(a))] = find(b); }
};

void keepFaces(TriangleMesh& m, std::vector<int>& origin, const std::vector<char>& keep) {
  size_t w = 0;
  for (size_t f = 0; f < m.faces.size(); ++f)
    if (keep[f]) {
      m.faces[w] = m.faces[f];
      origin[w++] = origin[f];
    }
  m.faces.resize(w);
  origin.resize(w);
}

// Phase: drop faces that repeat a vertex and exact duplicate faces (same vertex set).
void dropTrivialFaces(TriangleMesh& m, std::vector<int>& origin, MeshReport& report) {
  std::vector<char> keep(m.faces.size(), 1);
  std::vector<int> repeated, duplicate;
  std::map<std::array<int, 3>, int> seen;
  for (size_t f = 0; f < m.faces.size(); ++f) {
    Triangle t = m.faces[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      keep[f] = 0;
      repeated.push_back(origin[f]);
      continue;
    }
    std::sort(t.begin(), t.end());
    if (!seen.emplace(t, static_cast<int>(f)).second) {
      keep[f] = 0;
      duplicate.push_back(origin[f]);
    }
  }
  if (!repeated.empty())
    report.repairs.push_back("removed " + std::to_string(repeated.size()) +
                             " degenerate faces that repeat a vertex (faces " + faceList(repeated) +
                             ")");
  if (!duplicate.empty())
    report.repairs.push_back("removed " + std::to_string(duplicate.size()) +
                             " duplicate faces (faces " + faceList(duplicate) + ")");
  keepFaces(m, origin, keep);
}

// Phase: every edge in at most two faces, every vertex with one fan of faces around it.
bool checkManifold(const TriangleMesh& m, const std::vector<int>& origin,
                   const std::map<EdgeKey, std::vector<EdgeUse>>& uses, MeshReport& report) {
  for (const auto& [edge, list] : uses) {
    if (list.size() <= 2) continue;
    std::vector<int> faces;
    for (const EdgeUse& u : list) faces.push_back(origin[static_cast<size_t>(u.face)]);
    const Vec3 mid = 0.5 * (m.vertices[static_cast<size_t>(edge.first)] +
                            m.vertices[static_cast<size_t>(edge.second)]);
    report.refusals.push_back("non-manifold edge shared by " + std::to_string(list.size()) +
                              " faces (faces " + faceList(faces) + ") at " + point(mid) +
                              "; separate the touching surfaces in the modelling tool");
    return false;
  }
  // Fans: union faces around each vertex that share an edge through that vertex.
  std::vector<std::vector<int>> facesOfVertex(m.vertices.size());
  for (size_t f = 0; f < m.faces.size(); ++f)
    for (int v : m.faces[f]) facesOfVertex[static_cast<size_t>(v)].push_back(static_cast<int>(f));
  for (size_t v = 0; v < m.vertices.size(); ++v) {
    const auto& around = facesOfVertex[v];
    if (around.size() < 2) continue;
    std::unordered_map<int, int> local;
    for (size_t k = 0; k < around.size(); ++k) local[around[k]] = static_cast<int>(k);
    UnionFind fans(around.size());
    for (size_t k = 0; k < around.size(); ++k)
      for (int w : m.faces[static_cast<size_t>(around[k])]) {
        if (w == static_cast<int>(v)) continue;
        for (const EdgeUse& u : uses.at(edgeKey(static_cast<int>(v), w)))
          fans.unite(static_cast<int>(k), local.at(u.face));
      }
    int roots = 0;
    for (size_t k = 0; k < around.size(); ++k)
      roots += fans.find(static_cast<int>(k)) == static_cast<int>(k);
    if (roots > 1) {
      std::vector<int> faces;
      for (int f : around) faces.push_back(origin[static_cast<size_t>(f)]);
      report.refusals.push_back("non-manifold vertex " + point(m.vertices[v]) + " where " +
                                std::to_string(roots) + " separate fans of faces touch (faces " +
                                faceList(faces) + "); separate the surfaces in the modelling tool");
      return false;
    }
  }
  return true;
}

// Phase: connected components by shared edges; keep the largest by area.
void selectComponent(TriangleMesh& m, std::vector<int>& origin,
                     const std::map<EdgeKey, std::vector<EdgeUse>>& uses,
                     const MeshCheckOptions& options, MeshReport& report) {
  UnionFind cc(m.faces.size());
  for (const auto& [edge, list] : uses)
    for (size_t k = 1; k < list.size(); ++k) cc.unite(list[0].face, list[k].face);
  std::map<int, double> areaOf;
  std::map<int, int> facesOf;
  for (size_t f = 0; f < m.faces.size(); ++f) {
    const int r = cc.find(static_cast<int>(f));
    areaOf[r] += faceArea(m, f);
    ++facesOf[r];
  }
  if (areaOf.size() <= 1) return;
  const int largest =
      std::max_element(areaOf.begin(), areaOf.end(), [](const auto& a, const auto& b) {
        return a.second < b.second;
      })->first;
  // Debris next to the cavity (a speck, a loose lens surface) is removed; two components of
  // similar size (a tie, or two shells such as two overlapping spheres) leave no way to tell
  // which one is the cavity.
  constexpr double kSimilarArea = 0.5;  // [1] second-largest over largest at which we refuse
  double secondArea = 0.0;              // [m^2 or file units^2]
  for (const auto& [root, area] : areaOf)
    if (root != largest) secondArea = std::max(secondArea, area);
  const bool ambiguous = secondArea >= kSimilarArea * areaOf[largest];
  std::ostringstream others;
  int listed = 0;
  for (const auto& [root, area] : areaOf) {
    if (root == largest || listed >= 3) continue;
    others << (listed++ ? "; " : "") << facesOf[root] << " faces near "
           << point(centroid(m, static_cast<size_t>(root))) << " starting at face "
           << origin[static_cast<size_t>(root)];
  }
  const std::string what = std::to_string(areaOf.size()) + " connected components";
  if (!options.keepLargestComponent) {
    report.refusals.push_back("the mesh has " + what + " (other than the largest: " + others.str() +
                              "); export only the cavity surface or allow keeping the largest");
    return;
  }
  if (ambiguous) {
    report.refusals.push_back(
        "the mesh has " + what + " of similar size (the second has " +
        std::to_string(static_cast<int>(std::lround(100 * secondArea / areaOf[largest]))) +
        " % of the largest one's area: " + others.str() +
        "), so which one is the cavity is unclear; export only the cavity surface");
    return;
  }
  std::vector<char> keep(m.faces.size());
  for (size_t f = 0; f < m.faces.size(); ++f) keep[f] = cc.find(static_cast<int>(f)) == largest;
  report.repairs.push_back("kept the largest of " + what + " (" + std::to_string(facesOf[largest]) +
                           " faces) and removed the others (" + others.str() + ")");
  keepFaces(m, origin, keep);
}

// Phase: make every shared edge traversed in opposite directions by its two faces (breadth-first
// from face 0; the global sign is fixed later by the volume). Refuses non-orientable surfaces.
bool orientConsistently(TriangleMesh& m, const std::vector<int>& origin,
                        const std::map<EdgeKey, std::vector<EdgeUse>>& uses, MeshReport& report) {
  const size_t n = m.faces.size();
  std::vector<std::vector<std::pair<int, int>>> neighbours(n);  // (face, same direction?)
  for (const auto& [edge, list] : uses)
    if (list.size() == 2) {
      const int same = list[0].from == list[1].from;
      neighbours[static_cast<size_t>(list[0].face)].push_back({list[1].face, same});
      neighbours[static_cast<size_t>(list[1].face)].push_back({list[0].face, same});
    }
  std::vector<int> flip(n, -1);
  std::vector<int> queue{0};
  flip[0] = 0;
  for (size_t q = 0; q < queue.size(); ++q) {
    const int f = queue[q];
    for (const auto& [g, same] : neighbours[static_cast<size_t>(f)]) {
      const int want = flip[static_cast<size_t>(f)] ^ same;
      if (flip[static_cast<size_t>(g)] < 0) {
        flip[static_cast<size_t>(g)] = want;
        queue.push_back(g);
      } else if (flip[static_cast<size_t>(g)] != want) {
        report.refusals.push_back("non-orientable surface (like a Moebius strip) around face " +
                                  std::to_string(origin[static_cast<size_t>(g)]) + " at " +
                                  point(centroid(m, static_cast<size_t>(g))) +
                                  "; rebuild the surface");
        return false;
      }
    }
  }
  size_t flipped = static_cast<size_t>(std::count(flip.begin(), flip.end(), 1));
  const bool invertAll = 2 * flipped > n;  // flip the minority; the outward sign comes later
  std::vector<int> changed;
  for (size_t f = 0; f < n; ++f)
    if ((flip[f] == 1) != invertAll) {
      std::swap(m.faces[f][1], m.faces[f][2]);
      changed.push_back(origin[f]);
    }
  if (!changed.empty())
    report.repairs.push_back("re-oriented " + std::to_string(changed.size()) +
                             " faces to match their neighbours (faces " + faceList(changed) + ")");
  return true;
}

// Phase: boundary loops; fill those with at most maxHoleEdges edges by a fan around their
// centroid, refuse the others.
bool closeHoles(TriangleMesh& m, std::vector<int>& origin,
                const std::map<EdgeKey, std::vector<EdgeUse>>& uses,
                const MeshCheckOptions& options, MeshReport& report) {
  std::unordered_map<int, int> next;  // boundary edge a -> b as traversed by its one face
  std::unordered_map<int, int> faceOfEdge;
  for (const auto& [edge, list] : uses)
    if (list.size() == 1) {
      const int from = list[0].from, to = from == edge.first ? edge.second : edge.first;
      next[from] = to;
      faceOfEdge[from] = list[0].face;
    }
  if (next.empty()) return true;
  std::vector<int> starts;
  for (const auto& [a, b] : next) starts.push_back(a);
  std::sort(starts.begin(), starts.end());  // deterministic order of the loops
  std::unordered_map<int, char> done;
  bool ok = true;
  for (int start : starts) {
    if (done[start]) continue;
    std::vector<int> loop;
    std::vector<int> faces;
    for (int v = start; !done[v]; v = next.at(v)) {
      done[v] = 1;
      loop.push_back(v);
      const int face = origin[static_cast<size_t>(faceOfEdge.at(v))];
      if (std::find(faces.begin(), faces.end(), face) == faces.end()) faces.push_back(face);
      if (!next.count(next.at(v))) break;
    }
    Vec3 c = Vec3::Zero();
    for (int v : loop) c += m.vertices[static_cast<size_t>(v)];
    c /= static_cast<double>(loop.size());
    if (static_cast<int>(loop.size()) > options.maxHoleEdges) {
      report.refusals.push_back(
          "open surface: a hole with " + std::to_string(loop.size()) + " boundary edges around " +
          point(c) + " (bordering faces " + faceList(faces) +
          "); close it in the modelling tool (holes up to " + std::to_string(options.maxHoleEdges) +
          " edges are filled automatically)");
      ok = false;
      continue;
    }
    // The boundary edge a -> b belongs to a face traversing it a -> b, so the patch traverses
    // b -> a: triangle (b, a, centre) keeps the orientation consistent.
    const int centre = static_cast<int>(m.vertices.size());
    m.vertices.push_back(c);
    for (size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      m.faces.push_back({b, a, centre});
      origin.push_back(-1);
    }
    report.repairs.push_back("filled a hole of " + std::to_string(loop.size()) + " edges around " +
                             point(c) + " (bordering faces " + faceList(faces) + ")");
  }
  return ok;
}

void dropUnusedVertices(TriangleMesh& m) {
  std::vector<int> remap(m.vertices.size(), -1);
  std::vector<Vec3> kept;
  for (Triangle& t : m.faces)
    for (int& v : t) {
      if (remap[static_cast<size_t>(v)] < 0) {
        remap[static_cast<size_t>(v)] = static_cast<int>(kept.size());
        kept.push_back(m.vertices[static_cast<size_t>(v)]);
      }
      v = remap[static_cast<size_t>(v)];
    }
  m.vertices = std::move(kept);
}

// Throws for a mesh without faces, with a face index out of range or a non-finite vertex.
void requireValidInput(const TriangleMesh& input) {
  if (input.faces.empty())
    throw MeshError("mesh", "has no faces", "give a closed triangle surface");
  for (size_t f = 0; f < input.faces.size(); ++f)
    for (int v : input.faces[f])
      if (v < 0 || static_cast<size_t>(v) >= input.vertices.size())
        throw MeshError("mesh",
                        "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                            " but there are only " + std::to_string(input.vertices.size()),
                        "fix the face indices");
  for (size_t v = 0; v < input.vertices.size(); ++v)
    if (!input.vertices[v].allFinite())
      throw MeshError("mesh", "vertex " + std::to_string(v) + " has a NaN or infinite coordinate",
                      "repair or re-export the mesh");
}

// Removes degenerate (zero-area) faces; false (with a refusal) when that fails.
bool repairDegenerateFaces(TriangleMesh& m, std::vector<int>& origin, MeshReport& report) {
  if (const auto degenerate = detail::findDegenerateFaces(m); !degenerate.empty()) {
    std::vector<int> inputFaces;
    for (int f : degenerate) inputFaces.push_back(origin[static_cast<size_t>(f)]);
    const Vec3 where = centroid(m, static_cast<size_t>(degenerate.front()));
    if (!detail::removeDegenerateFaces(m, origin)) {
      report.refusals.push_back("could not remove " + std::to_string(degenerate.size()) +
                                " degenerate (zero-area) faces (faces " + faceList(inputFaces) +
                                ") near " + point(where) + "; remesh the surface");
      return false;
    }
    report.repairs.push_back("removed " + std::to_string(degenerate.size()) +
                             " degenerate (zero-area) faces by edge collapses (faces " +
                             faceList(inputFaces) + ") near " + point(where));
  }
  return true;
}

// False (with a refusal) when faces cross.
bool refuseSelfIntersections(const TriangleMesh& m, const std::vector<int>& origin,
                             MeshReport& report) {
  if (const auto pairs = detail::findSelfIntersections(m, 64); !pairs.empty()) {
    std::vector<int> faces;
    for (const auto& [f, g] : pairs) {
      faces.push_back(origin[static_cast<size_t>(f)]);
      faces.push_back(origin[static_cast<size_t>(g)]);
    }
    const Vec3 where = 0.5 * (centroid(m, static_cast<size_t>(pairs[0].first)) +
                              centroid(m, static_cast<size_t>(pairs[0].second)));
    report.refusals.push_back(
        "self-intersecting surface: " + std::string(pairs.size() >= 64 ? "at least " : "") +
        std::to_string(pairs.size()) + " pairs of faces cross, e.g. " + faceName(faces[0]) +
        " and " + faceName(faces[1]) + " near " + point(where) + " (faces " + faceList(faces) +
        "); fix the surface in the modelling tool");
    return false;
  }
  return true;
}

// Reverses all faces if the enclosed volume is negative; false (with a refusal) when the surface
// encloses no volume.
bool orientOutward(TriangleMesh& m, MeshMeasures& measures, MeshReport& report) {
  // A closed surface of collapsed (flat or zero-area) faces encloses nothing: a sphere has
  // |V| / A^1.5 = 0.094, so 1e-6 only catches surfaces that are flat to rounding.
  constexpr double kFlatRatio = 1e-6;  // [1]
  if (!(std::abs(measures.signedVolume) > kFlatRatio * std::pow(measures.area, 1.5))) {
    std::ostringstream sizes;
    sizes.precision(3);
    sizes << "area " << measures.area << ", volume " << measures.signedVolume;
    report.refusals.push_back("the surface encloses no volume (" + sizes.str() +
                              ": its faces are flat or collapsed); export the cavity as a closed "
                              "surface around its volume");
    return false;
  }
  if (measures.signedVolume < 0) {
    for (Triangle& t : m.faces) std::swap(t[1], t[2]);
    measures.signedVolume = -measures.signedVolume;
    report.repairs.push_back(
        "reversed all " + std::to_string(m.faces.size()) +
        " faces so that normals point outward (the enclosed volume was negative)");
  }
  return true;
}

}  // namespace

MeshReport checkMesh(const TriangleMesh& input, const MeshCheckOptions& options) {
  MeshReport report;
  report.inputVertices = static_cast<int>(input.vertices.size());
  report.inputFaces = static_cast<int>(input.faces.size());
  requireValidInput(input);
  report.measures = measureMesh(input);

  TriangleMesh m = input;
  std::vector<int> origin(m.faces.size());
  std::iota(origin.begin(), origin.end(), 0);

  // Phase 1: duplicate vertices, repeated-vertex and duplicate faces.
  if (const int joined = joinIdenticalVertices(m); joined > 0) {
    report.repairs.push_back("removed " + std::to_string(joined) +
                             " duplicate (identical coordinates) or unused vertices");
  }
  dropTrivialFaces(m, origin, report);
  if (m.faces.empty()) {
    report.refusals.push_back("no faces left after removing degenerate and duplicate faces");
    return report;
  }

  // Phase 2: manifoldness, components, consistent orientation, holes.
  auto uses = edgeUses(m);
  if (!checkManifold(m, origin, uses, report)) return report;
  selectComponent(m, origin, uses, options, report);
  if (!report.isUsable()) return report;
  uses = edgeUses(m);
  if (!orientConsistently(m, origin, uses, report)) return report;
  uses = edgeUses(m);
  if (!closeHoles(m, origin, uses, options, report)) return report;
  dropUnusedVertices(m);

  // Phase 3 (CGAL): degenerate faces, then self-intersections (degenerate faces would be
  // reported as self-intersecting).
  if (!repairDegenerateFaces(m, origin, report)) return report;
  if (!refuseSelfIntersections(m, origin, report)) return report;

  // Phase 4: outward orientation. Closed, consistent, not self-intersecting: the sign of the
  // enclosed volume says whether the normals point out.
  MeshMeasures measures = measureMesh(m);
  if (!orientOutward(m, measures, report)) return report;
  report.measures = measures;
  report.mesh = std::move(m);
  return report;
}

MeshReport requireUsableMesh(const TriangleMesh& mesh, const std::string& source,
                             const MeshCheckOptions& options) {
  MeshReport report = checkMesh(mesh, options);
  if (!report.isUsable()) {
    std::string what = "mesh refused: ";
    for (size_t k = 0; k < report.refusals.size(); ++k)
      what += (k ? "; " : "") + report.refusals[k];
    throw MeshError(source, what, "");
  }
  return report;
}

}  // namespace meshing
