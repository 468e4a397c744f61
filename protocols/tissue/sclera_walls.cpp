#include "protocols/tissue/sclera_walls.h"

#include <cmath>

#include "meshing/point_index.h"
#include "protocols/report/report_format.h"
#include "protocols/tissue/shell_gaps.h"
#include "sim/solid/fixed_particles.h"

namespace protocols {

namespace {

// The cavity wall as rebuilt around the sclera: the walls kept (the lens/IOL cap), those over the
// sclera (removed; their places, layers and tags serve the walls behind), and the walls added
// behind the sclera in order: backstop, collar and fan, shell openings, band face, orbit.
struct WallRebuild {
  std::vector<sim::Index> keep;
  std::vector<sim::Vec3> added, addedNormal;
  std::vector<int> addedTag;
  std::vector<sim::Vec3> covered;  // wall points over the sclera (for the rim's layer and tags)
  std::vector<double> coveredLayer;
  std::vector<sim::Vec3> coveredNormal;
  std::vector<int> coveredTag;
  std::vector<sim::Vec3> fat;  // elastic fat particles at rest
  std::size_t backstop = 0, collar = 0, seam = 0, band = 0, orbit = 0;
};

// The retina samples over the sclera follow its nearest particle (brute force: W x N_sclera
// distance checks, ~1e8 at the standard preset, < 1 s).
void followSclera(Scenario& s, const TissueContext& c, const TissueBody& sclera) {
  RetinaSamples& r = s.retinaSamples;
  r.scleraLayer = c.scleraLayer;
  const long n = static_cast<long>(r.restPositions.size());
#pragma omp parallel for schedule(static)
  for (long w = 0; w < n; ++w) {
    const auto k = static_cast<std::size_t>(w);
    if (c.scleraLayer[k] <= 0.0) continue;
    double best = 1e300;
    std::size_t nearest = 0;
    for (std::size_t j = 0; j < sclera.count; ++j) {
      const double dist = (sclera.restPositions[j] - r.restPositions[k]).squaredNorm();
      if (dist < best) best = dist, nearest = j;
    }
    r.followsId[k] = sclera.firstId + static_cast<std::int32_t>(nearest);
  }
}

// The lens/IOL cap keeps its wall; the wall over an anchored sclera moves behind it (backstop),
// kBackstopGapSpacings d beyond the layer's outer surface: within the kernel's support of the
// outer (anchored) layer, outside that of every free particle. Where elastic fat lies behind the
// sclera, it holds the globe: no backstop there.
void splitWalls(const Scenario& s, const TissueContext& c, WallRebuild& wr) {
  const double d = c.d;
  const sim::WallParticles& walls = s.world->walls;
  for (const TissueBody& t : s.tissues)
    if (t.name == "orbital fat" && t.decision.elastic)
      wr.fat.insert(wr.fat.end(), t.restPositions.begin(), t.restPositions.end());
  const meshing::PointIndex fatGrid(wr.fat, 2.0 * d);
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const double layer = c.layerAt(walls.x[w]);  // [m]
    if (layer <= 0.0) {
      wr.keep.push_back(static_cast<sim::Index>(w));
      continue;
    }
    wr.covered.push_back(walls.x[w]);
    wr.coveredLayer.push_back(layer);
    wr.coveredNormal.push_back(walls.normal[w]);
    wr.coveredTag.push_back(walls.tag[w]);
    if (!c.scleraBackstop) continue;
    const sim::Vec3 x = walls.x[w] + (layer + kBackstopGapSpacings * d) * walls.normal[w];
    if (fatGrid.anyWithin(x, 2.0 * d)) continue;
    wr.added.push_back(x);
    wr.addedNormal.push_back(walls.normal[w]);
    wr.addedTag.push_back(walls.tag[w]);
  }
  wr.backstop = wr.added.size();
}

// The limbus: the cap's rim walls (within 1.5 d of a sclera particle) get a collar of wall
// particles along their normal, every d/2 from d/2 out to the backstop's depth, closing the seam
// between the cap and the sclera layer where fluid left the globe (docs/methods/elasticity.md),
// and a fan at that depth over to the nearest sclera column's backstop point. Returns the cap and
// collar walls, which the clamp anchors the sclera against.
std::vector<sim::Vec3> addLimbusCollar(const Scenario& s, const TissueContext& c,
                                       const TissueBody& sclera, WallRebuild& wr) {
  const double d = c.d;
  const sim::WallParticles& walls = s.world->walls;
  const meshing::PointIndex scleraGrid(sclera.restPositions, 1.5 * d);
  const meshing::PointIndex coveredGrid(wr.covered, d);
  std::vector<sim::Vec3> clamp;  // cap and collar walls
  for (const sim::Index w : wr.keep) {
    const sim::Vec3& x = walls.x[w];
    clamp.push_back(x);
    if (!onCapRim(x, scleraGrid, coveredGrid, d)) continue;
    const long k = coveredGrid.nearest(x, 4.0 * d);
    const double layer =
        k >= 0 ? wr.coveredLayer[static_cast<std::size_t>(k)] : kMinTissueLayerSpacings * d;
    const double depth = layer + kBackstopGapSpacings * d;  // [m]
    const auto put = [&](const sim::Vec3& at, const sim::Vec3& normal) {
      wr.added.push_back(at);
      wr.addedNormal.push_back(normal);
      wr.addedTag.push_back(walls.tag[w]);
      clamp.push_back(at);
      ++wr.collar;
    };
    for (double step = 0.5 * d; step <= depth + 1e-6 * d; step += 0.5 * d)
      put(x + step * walls.normal[w], walls.normal[w]);
    // The cap meets the globe at a crease (the lens surface and the sclera's normals differ
    // by tens of degrees), so the collar's end and the backstop's first column diverge: a fan
    // of wall particles at the backstop's depth, spacing <= d/2, closes that wedge.
    if (k < 0) continue;
    const sim::Vec3& xc = wr.covered[static_cast<std::size_t>(k)];
    const sim::Vec3& nc = wr.coveredNormal[static_cast<std::size_t>(k)];
    const double angle = std::acos(std::clamp(walls.normal[w].dot(nc), -1.0, 1.0));  // [rad]
    const int pieces = fanPieces(x + depth * walls.normal[w], xc + depth * nc, angle, depth, d);
    for (int piece = 1; piece < pieces; ++piece) {
      const double f = static_cast<double>(piece) / pieces;
      const sim::Vec3 normal = ((1.0 - f) * walls.normal[w] + f * nc).normalized();
      put((1.0 - f) * x + f * xc + depth * normal, normal);
    }
  }
  return clamp;
}

// Every sclera particle within kLimbusClampSpacings d of a cap or collar wall is anchored.
void clampAtLimbus(Scenario& s, const TissueContext& c, TissueBody& sclera,
                   const std::vector<sim::Vec3>& clamp) {
  const double d = c.d;
  const meshing::PointIndex clampGrid(clamp, kLimbusClampSpacings * d);
  sim::DynamicParticles& particles = s.world->particles;
  for (std::size_t k = 0; k < sclera.count; ++k) {
    const std::size_t i = static_cast<std::size_t>(sclera.firstId) + k;  // not yet re-sorted
    if (sim::isFixed(particles, i) ||
        !clampGrid.anyWithin(sclera.restPositions[k], kLimbusClampSpacings * d))
      continue;
    sim::setFixed(particles, i);
    ++sclera.anchored;
    ++sclera.limbusClamped;
  }
}

// The backstop, collar and fan are samples moved off the cavity wall; where they spread (the
// backstop's samples drift apart by (R + depth) / R outward, the fans are lines from single
// rim particles) openings up to 0.9 d wide were left, fluid left the globe through one at
// the anterior-inferior limbus (docs/methods/elasticity.md "The limbus band, watertight").
void closeShell(const Scenario& s, const TissueContext& c, const TissueBody& sclera,
                WallRebuild& wr) {
  std::vector<sim::Vec3> freeSclera;
  for (std::size_t k = 0; k < sclera.count; ++k)
    if (!sim::isFixed(s.world->particles, static_cast<std::size_t>(sclera.firstId) + k))
      freeSclera.push_back(sclera.restPositions[k]);
  const ShellGapInput in{wr.covered, wr.coveredLayer, wr.coveredTag, freeSclera, wr.fat, c.d};
  wr.seam = fillShellGaps(s.cavity, in, wr.added, wr.addedNormal, wr.addedTag);
  const std::vector<char> interior = clampBandInterior(sclera, s.world->particles, freeSclera, c.d);
  wr.band = wallClampBand(s.cavity, in, sclera.restPositions, interior, wr.added, wr.addedNormal,
                          wr.addedTag);
}

// The bony orbit around the fat: lattice points (spacing d/2) at [kOrbitGapSpacings,
// kOrbitGapSpacings + 1) d from the nearest fat particle and at least 2 d from every sclera
// particle (no wall inside a tissue particle's support), normals pointing away from the fat.
void addBonyOrbit(const TissueContext& c, const TissueBody& sclera, WallRebuild& wr) {
  const double d = c.d;
  Eigen::AlignedBox3d box;
  for (const sim::Vec3& f : wr.fat) box.extend(f);
  const double reach = (kOrbitGapSpacings + 1.0) * d;  // [m]
  const double h = 0.5 * d;
  const meshing::PointIndex scleraGrid(sclera.restPositions, 2.0 * d);
  const meshing::PointIndex fatReach(wr.fat, reach);
  const meshing::PointIndex coveredGrid(wr.covered, 4.0 * d);
  const sim::Vec3 lo = box.min() - sim::Vec3::Constant(reach),
                  hi = box.max() + sim::Vec3::Constant(reach);
  for (double x = lo.x(); x <= hi.x(); x += h)
    for (double y = lo.y(); y <= hi.y(); y += h)
      for (double z = lo.z(); z <= hi.z(); z += h) {
        const sim::Vec3 q(x, y, z);
        const long f = fatReach.nearest(q, reach);
        if (f < 0) continue;
        const sim::Vec3 away = q - wr.fat[static_cast<std::size_t>(f)];
        if (away.norm() < kOrbitGapSpacings * d || scleraGrid.anyWithin(q, 2.0 * d)) continue;
        long k = -1;
        for (double around = 4.0 * d; k < 0 && around < 64.0 * d; around *= 2.0)
          k = coveredGrid.nearest(q, around);
        wr.added.push_back(q);
        wr.addedNormal.push_back(away.normalized());
        wr.addedTag.push_back(k >= 0 ? wr.coveredTag[static_cast<std::size_t>(k)] : 0);
        ++wr.orbit;
      }
}

void addWallNotes(Scenario& s, const TissueBody& sclera, const WallRebuild& wr) {
  if (wr.backstop > 0)
    s.notes.push_back("sclera held at its outer surface: a rigid backstop wall " +
                      formatNumber(kBackstopGapSpacings, 2) +
                      " particle spacing behind it where no orbital fat is, so no empty gap "
                      "lies behind the globe (docs/methods/elasticity.md)");
  if (wr.band > 0)
    s.notes.push_back(
        "the limbus clamp band's face walled: " + std::to_string(wr.band) +
        " wall particles at half the spacing within " + formatNumber(kBandFaceSpacings, 2) +
        " spacings of the cavity keep the fluid out of the band (docs/methods/elasticity.md)");
  if (wr.seam > 0)
    s.notes.push_back("the wall shell behind the sclera closed: " + std::to_string(wr.seam) +
                      " wall particles where the backstop's, collar's and fan's samples left "
                      "openings wider than the cavity wall's");
  if (wr.collar > 0)
    s.notes.push_back("sclera clamped at the limbus (the rigid lens/IOL cap): " +
                      std::to_string(sclera.limbusClamped) + " sclera particles within " +
                      formatNumber(kLimbusClampSpacings, 2) +
                      " spacings of the cap or its collar (" + std::to_string(wr.collar) +
                      " wall particles) anchored");
  if (wr.orbit > 0)
    s.notes.push_back(
        "the bony orbit: " + std::to_string(wr.orbit) + " rigid wall particles " +
        formatNumber(kOrbitGapSpacings, 2) + "-" + formatNumber(kOrbitGapSpacings + 1.0, 2) +
        " spacings around the orbital fat, so the tissue assembly is enclosed by walls");
}

}  // namespace

void replaceWallsOverSclera(Scenario& s, TissueContext& c) {
  TissueBody& sclera = s.tissues[*c.scleraIndex];
  followSclera(s, c, sclera);
  WallRebuild wr;
  splitWalls(s, c, wr);
  if (c.scleraBackstop) {
    clampAtLimbus(s, c, sclera, addLimbusCollar(s, c, sclera, wr));
    closeShell(s, c, sclera, wr);
    if (!wr.fat.empty()) addBonyOrbit(c, sclera, wr);
  }
  sim::WallParticles& walls = s.world->walls;
  walls.fields.select(wr.keep);
  for (std::size_t b = 0; b < wr.added.size(); ++b)
    walls.add(wr.added[b], wr.addedNormal[b], wr.addedTag[b]);
  addWallNotes(s, sclera, wr);
}

}  // namespace protocols
