#include "protocols/tissue/shell_gaps.h"

#include <algorithm>
#include <cmath>

#include "meshing/mesh_query.h"
#include "sim/solid/elasticity_peer2018.h"
#include "sim/solid/fixed_particles.h"

namespace protocols {

namespace {

// [1] fillShellGaps adds a lattice point when no shell wall lies within this many spacings.
// Measured on the paper eye (d = 1.2 mm, widest opening by enclosure.h): 0.5 left 0.61 d (734
// walls), 0.4 leaves 0.58 d (1861), 0.3 also 0.58 d (3424): the rest is the backstop's own
// spacing. The rigid cavity wall's widest is 0.50 d.
constexpr double kShellFillSpacings = 0.4;

}  // namespace

// The lens/IOL cap's rim, where the collar starts: a cap wall particle within 1.5 d of a sclera
// particle, or within kCapRimSpacings d of a wall sample over the sclera (the cap's edge on the
// cavity surface). The first alone followed the sclera lattice's staircase and left stretches of
// the rim 1.7 d long without a collar (a hole 2.5 d wide at the anterior-inferior limbus).
bool onCapRim(const sim::Vec3& x, const meshing::PointIndex& scleraGrid,
              const meshing::PointIndex& coveredGrid, double d) {
  return scleraGrid.anyWithin(x, 1.5 * d) || coveredGrid.anyWithin(x, kCapRimSpacings * d);
}

// Wall particles in the fan from the collar's end to the backstop point: at most d/2 apart along
// the arc (angle x depth) and along the chord between the ends (the collar's foot and the
// backstop's sample are up to 4 d apart on the surface, which the arc alone did not count).
int fanPieces(const sim::Vec3& collarEnd, const sim::Vec3& backstopPoint, double angle,
              double depth, double d) {
  const double length = std::max(angle * depth, (backstopPoint - collarEnd).norm());  // [m]
  return static_cast<int>(std::ceil(length / (0.5 * d)));
}

// Fills the openings of the wall shell behind the sclera (backstop, collar, fan in `added`): the
// shell is the surface at depth t_layer + kBackstopGapSpacings d from the cavity wall, over the
// sclera and over the cap within 4 d of it (there the offset of the cap/sclera crease, the wedge
// the fan approximates). Points of a d/2 lattice within d/4 of that surface get a wall particle
// when no wall of the shell lies within kShellFillSpacings d of them; like the backstop, none
// within 2 d of a free sclera or a fat particle (the fat holds the globe there, the orbit encloses
// it). Normals point away from the cavity. Returns how many it added.
std::size_t fillShellGaps(const meshing::TriangleMesh& cavityMesh, const ShellGapInput& in,
                          std::vector<sim::Vec3>& added, std::vector<sim::Vec3>& addedNormal,
                          std::vector<int>& addedTag) {
  const double d = in.d, h = 0.5 * d;
  const meshing::MeshQuery cavity(cavityMesh);
  const meshing::PointIndex coveredGrid(in.covered, 4.0 * d);
  const meshing::PointIndex shellGrid(added, d);
  const meshing::PointIndex freeGrid(in.freeSclera, 2.0 * d);
  const meshing::PointIndex fatGrid(in.fat, 2.0 * d);
  double deepest = 0.0;  // [m]
  Eigen::AlignedBox3d box;
  for (std::size_t k = 0; k < in.covered.size(); ++k) {
    box.extend(in.covered[k]);
    deepest = std::max(deepest, in.coveredLayer[k]);
  }
  const double reach = deepest + (kBackstopGapSpacings + 1.0) * d;  // [m]
  const sim::Vec3 lo = box.min() - sim::Vec3::Constant(reach),
                  hi = box.max() + sim::Vec3::Constant(reach);
  std::vector<sim::Vec3> points, normals;
  std::vector<int> tags;
  for (double x = lo.x(); x <= hi.x(); x += h)
    for (double y = lo.y(); y <= hi.y(); y += h)
      for (double z = lo.z(); z <= hi.z(); z += h) {
        const sim::Vec3 q(x, y, z);
        // Cheap rejections first: far from the sclera, or a shell wall already close.
        if (!coveredGrid.anyWithin(q, reach) || shellGrid.anyWithin(q, kShellFillSpacings * d))
          continue;
        const sim::Vec3 foot = cavity.closestPoint(q);
        const long c = coveredGrid.nearest(foot, 4.0 * d);
        if (c < 0) continue;
        const double depth =
            in.coveredLayer[static_cast<std::size_t>(c)] + kBackstopGapSpacings * d;  // [m]
        const double r = (q - foot).norm();
        if (std::abs(r - depth) > 0.25 * d || cavity.isInside(q)) continue;
        if (freeGrid.anyWithin(q, 2.0 * d) || fatGrid.anyWithin(q, 2.0 * d)) continue;
        points.push_back(q);
        normals.push_back((q - foot) / r);
        tags.push_back(in.coveredTag[static_cast<std::size_t>(c)]);
      }
  added.insert(added.end(), points.begin(), points.end());
  addedNormal.insert(addedNormal.end(), normals.begin(), normals.end());
  addedTag.insert(addedTag.end(), tags.begin(), tags.end());
  return points.size();
}

// The limbus clamp band's interior (docs/methods/elasticity.md "The limbus band, watertight"):
// anchored sclera particles farther than the elastic stage's reference support (2.5 d) from every
// free one. They never move and enter no free particle's elastic stencil, so they act on the scene
// only as a wall does, but on the lattice at d, whose openings let fluid in (10 kPa, 0.6 s: 10
// fluid particles in the band, 0.5-1.3 d from its anchored particles, none within 1.5 d of a free
// one). `freeSclera`: the rest positions of the sclera's free (not anchored) particles.
std::vector<char> clampBandInterior(const TissueBody& sclera,
                                    const sim::DynamicParticles& particles,
                                    const std::vector<sim::Vec3>& freeSclera, double d) {
  const double support = sim::ElasticityParameters{}.supportRadiusFactor * d;  // [m]
  const meshing::PointIndex freeGrid(freeSclera, support);
  std::vector<char> interior(sclera.count, 0);
  for (std::size_t k = 0; k < sclera.count; ++k)
    interior[k] = sim::isFixed(particles, static_cast<std::size_t>(sclera.firstId) + k) &&
                  !freeGrid.anyWithin(sclera.restPositions[k], support);
  return interior;
}

// kBandFaceSpacings (shell_gaps.h) walls the band near the cavity surface only: its face, where
// fluid enters (the sclera's innermost lattice layer lies d/2 to 1.37 d deep). Walling its whole
// interior (1948 walls instead of 328 at d = 1.2 mm) kept the fluid out of the band too but the
// 10 kPa run gave way at the posterior sclera/fat interface at 0.4 s (docs/methods/elasticity.md).

// Walls the band's face like the cavity wall: wall particles on a d/2 lattice at the points
// within kBandFaceSpacings d of the cavity surface (outside it) whose nearest sclera particle
// (within d) is a band particle. The anchored particles stay (the walls lie among them); the
// walls keep 2 d (the kernel's support) from every free sclera particle and from every other
// anchored one that has a free particle within 2 d: INDSPH gives an anchored particle its own
// stiffness, so a wall inside its support raises its number density and it pushes its free
// neighbours (measured on the 2 MPa sclera test, 10 ms: 0.43 mm without this second rule, bound
// 4 um). Normals point away from the cavity. Returns how many it added.
std::size_t wallClampBand(const meshing::TriangleMesh& cavityMesh, const ShellGapInput& in,
                          const std::vector<sim::Vec3>& scleraRest,
                          const std::vector<char>& interior, std::vector<sim::Vec3>& added,
                          std::vector<sim::Vec3>& addedNormal, std::vector<int>& addedTag) {
  const double d = in.d, h = 0.5 * d;
  Eigen::AlignedBox3d box;
  for (std::size_t k = 0; k < scleraRest.size(); ++k)
    if (interior[k]) box.extend(scleraRest[k]);
  if (box.isEmpty()) return 0;
  const meshing::MeshQuery cavity(cavityMesh);
  const meshing::PointIndex scleraGrid(scleraRest, d);
  const meshing::PointIndex freeGrid(in.freeSclera, 2.0 * d);
  const meshing::PointIndex coveredGrid(in.covered, 4.0 * d);
  std::vector<sim::Vec3> touching;  // kept sclera particles with a free one within 2 d
  for (std::size_t k = 0; k < scleraRest.size(); ++k)
    if (!interior[k] && freeGrid.anyWithin(scleraRest[k], 2.0 * d))
      touching.push_back(scleraRest[k]);
  const meshing::PointIndex touchingGrid(touching, 2.0 * d);
  const sim::Vec3 lo = box.min() - sim::Vec3::Constant(d), hi = box.max() + sim::Vec3::Constant(d);
  std::size_t count = 0;
  for (double x = lo.x(); x <= hi.x(); x += h)
    for (double y = lo.y(); y <= hi.y(); y += h)
      for (double z = lo.z(); z <= hi.z(); z += h) {
        const sim::Vec3 q(x, y, z);
        const long k = scleraGrid.nearest(q, d);
        if (k < 0 || !interior[static_cast<std::size_t>(k)] || freeGrid.anyWithin(q, 2.0 * d) ||
            cavity.isInside(q))
          continue;
        if (touchingGrid.anyWithin(q, 2.0 * d)) continue;
        const sim::Vec3 foot = cavity.closestPoint(q);
        if ((q - foot).norm() > kBandFaceSpacings * d) continue;
        const sim::Vec3 out =
            (q - foot).norm() > 0.0 ? sim::Vec3((q - foot).normalized()) : sim::Vec3::UnitZ();
        const long c = coveredGrid.nearest(foot, 4.0 * d);
        added.push_back(q);
        addedNormal.push_back(out);
        addedTag.push_back(c >= 0 ? in.coveredTag[static_cast<std::size_t>(c)] : 0);
        ++count;
      }
  return count;
}

}  // namespace protocols
