// Elastic tissue in eye scenarios (protocols/tissue/tissue_particles.h): the decision
// in both directions, the elastic sclera/fat replacing the wall they cover, the example protocols
// (validate and plan), a few steps of the paper's experiment with its report, and bad input.
#include <unistd.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "meshing/mesh_query.h"
#include "meshing/point_index.h"
#include "protocols/assembly/assemble_scenario.h"
#include "protocols/assembly/wall_wetting_notes.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/format/protocol_error.h"
#include "protocols/io/frame_reader.h"
#include "protocols/run/rebuild_report.h"
#include "protocols/run/run_scenario.h"
#include "protocols/scenario/scenario.h"
#include "protocols/tissue/enclosure.h"
#include "protocols/tissue/tissue_measures.h"
#include "sim/boundary/wall_layers.h"
#include "sim/boundary/wetted_surface.h"
#include "sim/solid/fixed_particles.h"
#include "sim/world/pipeline.h"
#include "sim/world/stage_registry.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"

namespace fs = std::filesystem;
using namespace protocols;

namespace {

const fs::path kProtocols = fs::path(TAMPONADE_SOURCE_DIR) / "data" / "protocols";
const fs::path kPaper10 = kProtocols / "paper_sclera_10kpa.toml";
const fs::path kPhysiological = kProtocols / "physiological_sclera.toml";

std::size_t countMaterial(const Scenario& s, int material) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < s.world->particles.size(); ++i)
    n += s.world->particles.material[i] == material;
  return n;
}

// The paper protocol's text with one line replaced (for bad-input and decision variants).
std::string paperWith(const std::string& from, const std::string& to) {
  std::string text = tamponade_test::readText(kPaper10);
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  return text;
}

}  // namespace

TEST_CASE("tissue: the physiological sclera is rigid by the rule and changes nothing",
          "[unit][protocol][tissue]") {
  const Protocol p = parseProtocol(kPhysiological.string());
  const Scenario s = assembleScenario(p);
  REQUIRE(s.tissues.size() == 2);
  const TissueBody& sclera = s.tissues[0];
  CHECK_FALSE(sclera.decision.elastic);
  CHECK_FALSE(sclera.decision.forced);
  // The sclera is anchored at its outer surface (the format's default), so the estimate is the
  // layer's compression p t / E at the thinnest anatomical thickness (0.42 mm at the equator,
  // anatomy/sclera_shell.h) and the scene's load; recompute the load independently:
  // rho_max g H + 2 sigma / R with the cavity's largest extent and equivalent-sphere radius.
  Eigen::AlignedBox3d box;
  for (const auto& v : s.cavity.vertices) box.extend(v);
  const double h = (box.max() - box.min()).maxCoeff();
  const double r = std::cbrt(3.0 * s.cavityVolume / (4.0 * std::numbers::pi));
  const double load = s.phases[0].density * 9.81 * h +
                      2.0 * *s.phases[1].interfacialTension / r;  // aqueous is heavier
  CHECK(sclera.loadPressure == Approx(load).epsilon(1e-3));  // g = 9.81 m/s^2 exactly in the format
  CHECK(sclera.estimatedDisplacement ==
        Approx(sclera.loadPressure * 0.42e-3 / 2e6).epsilon(1e-12));  // same formula, round-off
  CHECK(sclera.decision.reason.find("anchored layer compressed") != std::string::npos);
  CHECK(sclera.estimatedDisplacement / s.accuracy.particleSpacing < 0.1);
  // The fat alone would deform (1 kPa), but behind a rigid sclera the rule keeps it rigid.
  const TissueBody& fat = s.tissues[1];
  CHECK_FALSE(fat.decision.elastic);
  CHECK(fat.decision.reason.find("behind a rigid sclera") != std::string::npos);
  // Nothing changes: no tissue particle, the rigid cavity's layered wall (accuracy.wall_model
  // "auto"), the retina samples at rest.
  CHECK(s.world->particles.size() == s.phases[0].count + s.phases[1].count);
  CHECK(s.layeredWalls);
  CHECK(sim::hasLayeredWalls(s.world->walls));
  CHECK_FALSE(s.retinaSamples.moves());
  const std::vector<std::string> lines = tissueReportLines(s, {}, 0.0);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].rfind("tissue rigid (sclera estimate ", 0) == 0);
  CHECK(lines[0].find(" d < 0.1 d; orbital fat estimate ") != std::string::npos);
  CHECK(lines[0].find(" d, behind the rigid sclera)") != std::string::npos);
}

TEST_CASE("tissue: the paper's 10 kPa sclera and 1 kPa fat become anchored elastic particles",
          "[unit][protocol][tissue]") {
  const Protocol p = parseProtocol(kPaper10.string());
  const Scenario s = assembleScenario(p);
  REQUIRE(s.tissues.size() == 2);
  const double d = s.accuracy.particleSpacing;
  for (const TissueBody& t : s.tissues) {
    INFO(t.describe());
    CHECK(t.decision.elastic);
    CHECK(t.count > 100);
    CHECK(t.anchored > 0);
    CHECK(t.anchored < t.count);
    CHECK(countMaterial(s, t.materialIndex) == t.count);
    const sim::Material& m = s.world->materials[t.materialIndex];
    CHECK(m.kind == sim::MaterialKind::kElastic);
    CHECK(m.youngsModulus == t.simulatedModulus);
  }
  // An elastic tissue's outer face carries no fluid pressure: it must feel the full p, so gravity
  // is not taken relative to the aqueous (ScenarioOptions::removeHydrostaticBackground).
  CHECK(s.world->gravityReferenceDensity == 0.0);
  const TissueBody& sclera = s.tissues[0];
  {
    // The report warns when the run's step does not resolve the layer's thickness mode: omega_1 =
    // pi c_p / (2 t_layer), c_p the P-wave speed of the simulated modulus (closed form, here
    // recomputed); the line appears for (omega_1 dt)^2 > 1 and names the factor 1 + (omega_1 dt)^2.
    const double nu = sclera.poissonRatio, E = sclera.simulatedModulus;
    const double cp =
        std::sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / sclera.density);  // [m/s]
    const double omega = std::numbers::pi * cp / (2 * sclera.layerThickness);  // [rad/s]
    CHECK(sclera.thicknessModeFrequency == Approx(omega).epsilon(1e-12));
    TissueMeasures none;
    none.maxDisplacement.assign(s.tissues.size(), 0.0);
    none.regionMeanOutward.assign(kReportedRegions.size(), 0.0);
    const auto mentions = [&](double dt) {
      for (const std::string& line : tissueReportLines(s, none, 0.1, dt))
        if (line.rfind("sclera: its displacement is an upper bound", 0) == 0) return line;
      return std::string();
    };
    CHECK(mentions(0.0).empty());          // unknown step: no claim
    CHECK(mentions(0.5 / omega).empty());  // resolved
    const std::string line = mentions(3.0 / omega);
    CHECK(line.find("up to 10x the physical one") != std::string::npos);
  }
  // 10 kPa held at its outer surface: the rule says rigid (the layer compresses by p t / E ~ 10 um
  // = 0.009 d), so the protocol's mode = "elastic" is a force (the paper's visible deformation
  // needs a sclera the orbit does not hold; unanchored, it falls out of the domain when upright).
  CHECK(sclera.decision.forced);
  CHECK(sclera.decision.reason.find("anchored layer compressed") != std::string::npos);
  // The 0.42-0.94 mm sclera is thinner than 2.5 d at d = 1.2 mm: the layer is thickened and E
  // scaled by t / t_layer (membrane stiffness E t kept), so E_sim t_layer lies between
  // E x 0.42 mm and E x 0.94 mm.
  CHECK(sclera.layerThickness >= kMinTissueLayerSpacings * d - 1e-12);
  CHECK(sclera.simulatedModulus * sclera.layerThickness >= 10e3 * 0.42e-3 - 1e-9);
  CHECK(sclera.simulatedModulus * sclera.layerThickness <= 10e3 * 0.94e-3 + 1e-9);
  // Anchored = the sampled layer's outermost lattice layer: farther out than every free particle's
  // minimum, i.e. no anchored particle lies in the first layer next to the cavity.
  std::size_t fixedCount = 0;
  for (std::size_t i = 0; i < s.world->particles.size(); ++i)
    fixedCount += sim::isFixed(s.world->particles, i);
  CHECK(fixedCount == s.tissues[0].anchored + s.tissues[1].anchored);
  // The walls over the sclera are replaced: at the cavity surface only the lens/IOL cap keeps wall
  // particles (and the limbus clamp band's face, among its anchored particles); the others stand
  // behind the anchored layer as the backstop (kBackstopGapSpacings d
  // beyond it), only where no fat lies behind the sclera, and at least 2 d from every fat
  // particle. The cap's rim gets a collar (walls along the cap's normal out to the backstop's
  // depth, its nearest cavity point on the cap) and the fat an orbit (below). Every retina sample
  // off the cap follows a sclera particle within 2 d of it.
  {
    const meshing::MeshQuery cavity(s.cavity);
    std::vector<sim::Vec3> cap;
    for (const sim::Vec3& x : s.world->walls.x)
      if (cavity.squaredDistance(x) < 0.25 * d * d) cap.push_back(x);
    std::vector<sim::Vec3> anchoredSclera;
    for (std::size_t i = 0; i < s.world->particles.size(); ++i)
      if (s.world->particles.material[i] == sclera.materialIndex &&
          sim::isFixed(s.world->particles, i))
        anchoredSclera.push_back(s.world->particles.x[i]);
    const meshing::PointIndex anchoredGrid(anchoredSclera, d);
    std::size_t behind = 0, collar = 0, band = 0;
    for (const sim::Vec3& x : s.world->walls.x) {
      const double r = std::sqrt(cavity.squaredDistance(x));
      if (r < 0.5 * d) continue;
      const sim::Vec3 q = cavity.closestPoint(x);
      const bool onCap = std::any_of(cap.begin(), cap.end(),
                                     [&](const sim::Vec3& c) { return (c - q).norm() < 0.6 * d; });
      if (onCap) {
        ++collar;  // from the cap's rim out to the backstop's depth: t_layer + kBackstopGapSpacings
                   // d
        CHECK(r < sclera.layerThickness + kBackstopGapSpacings * d + 0.6 * d);
      } else if (r > kMinTissueLayerSpacings * d + 0.5 * d) {
        ++behind;
      } else {
        // Within the layer: only the walls of the limbus clamp band's face, among its anchored
        // particles (within d of one) and none within 2 d of a free one (checked for every wall
        // below; without them fluid entered the band's lattice at d).
        ++band;
        CHECK(anchoredGrid.anyWithin(x, d));
        CHECK(r < 1.5 * d + 1e-9);
      }
      for (std::size_t i = 0; i < s.world->particles.size(); ++i)
        if (s.world->particles.material[i] == s.tissues[1].materialIndex &&
            (s.world->particles.x[i] - x).norm() < 2 * d) {
          FAIL_CHECK("wall within 2 d of a fat particle");
          break;
        }
    }
    CHECK(cap.size() < s.retina.areas.size() / 4);
    CHECK(behind > 0);
    CHECK(collar > 0);
    CHECK(band > 0);
    // Every wall stays in the World's domain (tissueDomainPadding covers the orbit).
    const sim::Box& domain = s.world->parameters().domain;
    for (const sim::Vec3& x : s.world->walls.x) CHECK(domain.contains(x));
  }
  // The limbus clamp: some sclera particles anchored next to the cap, and every sclera particle
  // within the kernel's support (2 d) of any wall particle is anchored, so no wall (cap, collar,
  // backstop, orbit) can push a free sclera particle.
  CHECK(sclera.limbusClamped > 0);
  CHECK(sclera.limbusClamped < sclera.anchored);
  {
    std::size_t freeNearWall = 0;
    for (std::size_t i = 0; i < s.world->particles.size(); ++i) {
      if (s.world->particles.material[i] != sclera.materialIndex ||
          sim::isFixed(s.world->particles, i))
        continue;
      for (const sim::Vec3& w : s.world->walls.x)
        if ((w - s.world->particles.x[i]).norm() < 2.0 * d) {
          ++freeNearWall;
          break;
        }
    }
    CHECK(freeNearWall == 0);
  }
  // The bony orbit behind the fat: every anchored (back-face) fat particle has a wall particle
  // 2-3.2 d from it on its far side (away from the globe's centre), i.e. the fat's back face is
  // covered; a fluid particle that got through the fat would meet a wall, not the domain's end.
  {
    Eigen::AlignedBox3d box;
    for (const auto& v : s.cavity.vertices) box.extend(v);
    const sim::Vec3 centre = box.center();
    std::size_t backFace = 0, covered = 0;
    for (std::size_t i = 0; i < s.world->particles.size(); ++i) {
      if (s.world->particles.material[i] != s.tissues[1].materialIndex ||
          !sim::isFixed(s.world->particles, i))
        continue;
      ++backFace;
      const sim::Vec3 f = s.world->particles.x[i];
      const sim::Vec3 out = (f - centre).normalized();
      covered +=
          std::any_of(s.world->walls.x.begin(), s.world->walls.x.end(), [&](const sim::Vec3& w) {
            const double r = (w - f).norm();
            return r >= 2.0 * d && r < 3.2 * d && (w - f).dot(out) > 0.0;
          });
    }
    CHECK(backFace > 0);
    CHECK(covered == backFace);
  }
  std::size_t following = 0;
  for (std::size_t w = 0; w < s.retina.areas.size(); ++w) {
    const std::int32_t id = s.retinaSamples.followsId[w];
    if (id < 0) continue;
    ++following;
    REQUIRE(id >= sclera.firstId);
    REQUIRE(id < sclera.firstId + static_cast<std::int32_t>(sclera.count));
    CHECK((sclera.restPositions[static_cast<std::size_t>(id - sclera.firstId)] -
           s.retinaSamples.restPositions[w])
              .norm() < 2.0 * d);
  }
  CHECK(following + s.world->walls.size() >= s.retina.areas.size());
  // The frames carry the ids and the displacement map.
  CHECK(std::find(s.outputFields.begin(), s.outputFields.end(), "tissue_displacement") !=
        s.outputFields.end());
  CHECK(std::find(s.outputFields.begin(), s.outputFields.end(), "id") != s.outputFields.end());
  // At rest nothing has moved.
  const TissueMeasures m = measureTissues(s, s.world->particles.x, s.world->particles.id);
  CHECK(m.retinaMaxDisplacement == 0.0);
  CHECK(m.cavityVolumeChange == 0.0);
}

// A leak of fluid out of the globe (docs/methods/elasticity.md "Closing the gaps behind the
// sclera"): an empty gap behind the anchored sclera layer (the backstop 2 d beyond its outer
// surface, the fat from d/2 beyond it) was a free surface inside the pressurised globe: INDSPH
// clamps the pressure at 0 where the number density is deficient (measured at 0.1 s: the anchored
// layer's mean 0.81 of rest, 98 % of it at p = 0, the fluid next to the face ~50 Pa), and the
// pressure solve drove fluid through the layer into the gap. Now every outer-layer (anchored)
// sclera particle has a wall (backstop, collar) or fat particle on its far side (outward from the
// cavity) within the kernel's support up to the lattice's staircase (below), so its number density
// counts what is behind it; the fat continues the sclera's lattice (no fat particle closer than d
// to a sclera particle: no double particles), and no wall particle lies within the kernel's support
// of a free sclera particle (none pushes it). Over an elastic sclera the retina is the sclera's
// fluid-facing layer, not wall particles: that layer carries the wall tags it replaces, so the
// library oil's contact angle acts there too (sim/boundary/wetted_surface.h; the stages'
// equivalence over tissue and over the wall is tests/sim/interface_units.cpp, "Over a wetted tissue
// floor ...").
TEST_CASE("tissue: the retina over the elastic sclera carries the wall's contact angle",
          "[unit][protocol][tissue]") {
  const Protocol p = parseProtocol(kPaper10.string());
  const Scenario s = assembleScenario(p);
  const double d = s.accuracy.particleSpacing;
  const sim::DynamicParticles& particles = s.world->particles;
  const TissueBody& sclera = s.tissues[0];
  REQUIRE(sclera.name == "sclera");
  REQUIRE(s.phases[1].contactAngleThroughAqueous);  // the library oil has one
  std::vector<sim::Vec3> wetted;
  std::size_t wettedOutsideSclera = 0, untaggedAngle = 0;
  std::vector<int> angleTags;
  for (const auto& a : s.world->materials.contactAngles()) angleTags.push_back(a.wallTag);
  for (sim::Index i = 0; i < particles.size(); ++i) {
    const std::int32_t tag = sim::wettedSurfaceTag(particles, i);
    if (tag < 0) continue;
    wetted.push_back(particles.x[i]);
    wettedOutsideSclera += particles.material[i] != sclera.materialIndex;
    untaggedAngle += std::find(angleTags.begin(), angleTags.end(), tag) == angleTags.end();
  }
  INFO(wetted.size() << " wetted sclera particles of " << sclera.count);
  CHECK(wettedOutsideSclera == 0);
  CHECK(untaggedAngle == 0);  // every wetted particle's tag has the oil's angle
  // One layer: each retina sample over the sclera has a wetted particle within the lattice's
  // reach of the surface (the layer is the lattice's points 0.5-1.5 d deep, whose nearest point
  // to a surface point is at most 1.5 d deep and sqrt(3)/2 d aside), and the layer holds about one
  // particle per d^2 of the retina it covers, with the layer's mean depth d above the retina
  // adding 2 d / R ~ 20 % of area (R ~ 11 mm, d = 1.2 mm): measured N d^2 / A = 1.24 (1153
  // particles over 2871 retina samples). 15 %: a second layer tagged would double it, a
  // missing half of the layer halve it.
  const meshing::PointIndex grid(wetted, 2.0 * d);
  const RetinaSamples& r = s.retinaSamples;
  REQUIRE(r.scleraLayer.size() == r.restPositions.size());
  std::size_t covered = 0, bare = 0;
  double coveredArea = 0.0;  // [m^2]
  for (std::size_t w = 0; w < r.restPositions.size(); ++w) {
    if (r.scleraLayer[w] <= 0.0) continue;
    ++covered;
    coveredArea += s.retina.areas[w];
    bare += !grid.anyWithin(r.restPositions[w], std::sqrt(1.5 * 1.5 + 0.75) * d);
  }
  INFO(covered << " retina samples over the sclera, " << bare << " without a wetted particle near; "
               << "N d^2 / A = " << wetted.size() * d * d / coveredArea);
  CHECK(covered > 100);
  CHECK(bare == 0);
  CHECK(wetted.size() * d * d / coveredArea == Approx(1.2).epsilon(0.15));
  // The plan says so (it said "has no wall adhesion" before).
  const std::string expectedNote =
      "the retina over the elastic sclera is the sclera's fluid-facing layer: its " +
      std::to_string(wetted.size()) + " particles";
  CHECK(std::any_of(s.notes.begin(), s.notes.end(),
                    [&](const std::string& note) { return note.rfind(expectedNote, 0) == 0; }));
  for (const std::string& note : s.notes)
    CHECK(note.find("has no wall adhesion") == std::string::npos);
  // The wall-model note names the lattice retina and leaves the single layer to the lens cap.
  CHECK(std::count(s.notes.begin(), s.notes.end(),
                   contactAngleWallModelNote(RetinaWall::kElasticSclera)) == 1);
  CHECK(std::count(s.notes.begin(), s.notes.end(),
                   contactAngleWallModelNote(RetinaWall::kSingleLayer)) == 0);
}

TEST_CASE(
    "tissue: the anchored sclera layer is backed by the wall or the fat within the kernel's "
    "support",
    "[unit][protocol][tissue]") {
  const Protocol p = parseProtocol(kPaper10.string());
  const Scenario s = assembleScenario(p);
  REQUIRE(s.tissues.size() == 2);
  const double d = s.accuracy.particleSpacing;
  const sim::World& world = *s.world;
  const double h = world.kernel.supportRadius();
  REQUIRE(h == Approx(2.0 * d));
  const TissueBody& sclera = s.tissues[0];
  const TissueBody& fat = s.tissues[1];
  const sim::DynamicParticles& particles = world.particles;
  std::vector<sim::Vec3> fatPoints, scleraPoints, freePoints;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.material[i] == fat.materialIndex) fatPoints.push_back(particles.x[i]);
    if (particles.material[i] != sclera.materialIndex) continue;
    scleraPoints.push_back(particles.x[i]);
    if (!sim::isFixed(particles, i)) freePoints.push_back(particles.x[i]);
  }
  const meshing::PointIndex fatGrid(fatPoints, h);
  const meshing::PointIndex wallGrid(world.walls.x, h);
  const meshing::MeshQuery cavity(s.cavity);
  // The outer layer spans depths (t_layer - d, t_layer] and the backstop stands at t_layer + g d
  // (g = kBackstopGapSpacings), so along the normal the wall is g d to (1 + g) d away; sampled at
  // d/2, its nearest particle is at most d/4 further sideways. g = 1 is the largest gap that keeps
  // it within the kernel's support (2 d) of the layer up to that d/4 (g < 1 would bring it within
  // 2 d of free particles at depth t_layer - d).
  static_assert(kBackstopGapSpacings <= 1.0);
  const double farthest = (1.0 + kBackstopGapSpacings + 0.25) * d;  // [m]
  std::size_t outer = 0, unbacked = 0, withinSupport = 0;
  double kernelSum = 0.0;  // [1] sum of delta_i V0_i of the outer layer (tissue + walls), reported
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.material[i] != sclera.materialIndex || !sim::isFixed(particles, i)) continue;
    const sim::Vec3& x = particles.x[i];
    const sim::Vec3 q = cavity.closestPoint(x);
    if ((x - q).norm() <= sclera.layerThickness - d)
      continue;  // inner particles of the limbus clamp
    const sim::Vec3 out = (x - q).normalized();
    ++outer;
    double nearest = 1e300;  // [m] nearest wall or fat particle on the far side
    for (const std::size_t b : wallGrid.within(x, farthest)) {
      if ((world.walls.x[b] - x).dot(out) > 0.0)
        nearest = std::min(nearest, (world.walls.x[b] - x).norm());
      kernelSum += world.walls.volume[b] * world.kernel.W(x - world.walls.x[b]);
    }
    for (const std::size_t f : fatGrid.within(x, farthest)) {
      if ((fatPoints[f] - x).dot(out) > 0.0) nearest = std::min(nearest, (fatPoints[f] - x).norm());
      kernelSum += d * d * d * world.kernel.W(x - fatPoints[f]);
    }
    for (const sim::Vec3& y : scleraPoints)
      if ((y - x).squaredNorm() < h * h) kernelSum += d * d * d * world.kernel.W(x - y);
    withinSupport += nearest < h ? 1 : 0;
    if (nearest >= farthest && unbacked++ < 10)
      UNSCOPED_INFO("unbacked outer sclera particle at " << x.transpose() * 1e3 << " mm");
  }
  REQUIRE(outer > 100);
  INFO(outer << " outer-layer sclera particles, " << withinSupport
             << " with a wall or fat particle behind them within 2 d; kernel sum mean "
             << kernelSum / static_cast<double>(outer));
  CHECK(unbacked == 0);
  const meshing::PointIndex scleraGrid(scleraPoints, d);
  std::size_t tooClose = 0;
  for (const sim::Vec3& f : fatPoints) tooClose += scleraGrid.anyWithin(f, 0.99 * d) ? 1 : 0;
  CHECK(tooClose == 0);
  const meshing::PointIndex freeGrid(freePoints, h);
  std::size_t wallNearFree = 0;
  for (const sim::Vec3& w : world.walls.x) wallNearFree += freeGrid.anyWithin(w, h) ? 1 : 0;
  CHECK(wallNearFree == 0);
}

// The enclosure check itself (protocols/tissue/enclosure.h) on a cube of side 10 d with a
// point at its centre: its faces sampled on a square lattice at d/2 are closed at clearance d/2
// (no point of a face farther than 0.35 d from a sample), at d they are open (0.71 d), and a hole
// of radius d cut into a d/2 face is found, the path passing through it.
TEST_CASE(
    "tissue: the enclosure check finds a hole of radius d and the pores of a d lattice, not a d/2 "
    "wall",
    "[unit][protocol][tissue]") {
  const double d = 1.0e-3, side = 10.0 * d;  // [m]
  const auto cube = [&](double spacing, double holeRadius) {
    std::vector<sim::Vec3> points;
    const sim::Vec3 hole(side, 0.5 * side, 0.5 * side);  // centre of the face x = side
    const int n = static_cast<int>(std::lround(side / spacing));
    for (int a = 0; a < 3; ++a)
      for (const double at : {0.0, side})
        for (int i = 0; i <= n; ++i)
          for (int j = 0; j <= n; ++j) {
            sim::Vec3 x;
            x[a] = at;
            x[(a + 1) % 3] = i * spacing;
            x[(a + 2) % 3] = j * spacing;
            if ((x - hole).norm() >= holeRadius) points.push_back(x);
          }
    return points;
  };
  // The grid is offset from the lattice (a box edge at a non-round place), as it is in a scene.
  const Eigen::AlignedBox3d box(sim::Vec3::Constant(-3.13 * d),
                                sim::Vec3::Constant(side + 3.07 * d));
  const std::vector<sim::Vec3> centre{sim::Vec3::Constant(0.5 * side)};
  CHECK_FALSE(findEscapePath(cube(0.5 * d, 0.0), centre, box, 0.5 * d, 0.25 * d).escapes());
  CHECK(findEscapePath(cube(d, 0.0), centre, box, 0.5 * d, 0.25 * d).escapes());
  const EscapePath throughHole = findEscapePath(cube(0.5 * d, d), centre, box, 0.5 * d, 0.25 * d);
  REQUIRE(throughHole.escapes());
  const auto crossing = std::find_if(throughHole.points.begin(), throughHole.points.end(),
                                     [&](const sim::Vec3& x) { return x.x() >= side; });
  REQUIRE(crossing != throughHole.points.end());
  CHECK((*crossing - sim::Vec3(side, 0.5 * side, 0.5 * side)).norm() < d);
  // A start inside an obstacle's clearance is skipped: nothing to walk from.
  CHECK_FALSE(findEscapePath(cube(d, 0.0), {sim::Vec3::Zero()}, box, 0.5 * d, 0.25 * d).escapes());
}

namespace {

std::vector<sim::Vec3> fluidPositions(const Scenario& s) {
  std::vector<sim::Vec3> fluid;
  const sim::DynamicParticles& particles = s.world->particles;
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (particles.material[i] == s.phases[0].materialIndex ||
        particles.material[i] == s.phases[1].materialIndex)
      fluid.push_back(particles.x[i]);
  return fluid;
}

// [m] the widest opening from the fluid out of the scene's walls: the largest clearance at which
// findEscapePath still escapes, by bisection over [d/4, 2 d] to d/64.
double widestOpening(const Scenario& s, double cell) {
  const double d = s.accuracy.particleSpacing;
  const std::vector<sim::Vec3> fluid = fluidPositions(s);
  double open = 0.25 * d, closed = 2.0 * d;
  REQUIRE(
      findEscapePath(s.world->walls.x, fluid, s.world->parameters().domain, open, cell).escapes());
  REQUIRE_FALSE(findEscapePath(s.world->walls.x, fluid, s.world->parameters().domain, closed, cell)
                    .escapes());
  while (closed - open > d / 64.0) {
    const double mid = 0.5 * (open + closed);
    (findEscapePath(s.world->walls.x, fluid, s.world->parameters().domain, mid, cell).escapes()
         ? open
         : closed) = mid;
  }
  return open;
}

}  // namespace

// The leak's way out (docs/methods/elasticity.md "The limbus band, watertight"): fluid that got
// into the limbus clamp band left the tissue assembly through openings in the walls around it
// (the collar, its fan, the backstop, the orbit) near (2.4, -14, 11.6) mm, the nearest wall
// particle 1.6-2.9 d away, and reached y -19..-21 mm. A geometric check on the assembled scenes
// (protocols/tissue/enclosure.h, no stepping): the widest opening is the largest clearance from
// every wall particle at which a chain of grid points (spacing d/4) leads from a fluid particle to
// the domain's edge. The reference is the rigid cavity wall of the physiological eye (d/2
// samples, the same spacing d): it holds the fluid in every rigid run, and by this measure its
// widest opening is ~0.5 d (a square d/2 lattice: 0.35 d; the Poisson-disk samples leave wider
// holes). The tissue scene's walls (cap, collar, fan, backstop, orbit; the tissues are not
// obstacles, the walls alone must enclose them and whatever passes them) must not open wider than
// that, up to the grid's resolution of a clearance, cell / 2 = d/8. Before the shell was closed
// the paper eye's widest opening was 1.2-1.4 d, at the anterior-inferior limbus.
TEST_CASE("tissue: the walls around the tissues open no wider than the rigid cavity wall",
          "[unit][protocol][tissue]") {
  const Scenario rigid = assembleScenario(parseProtocol(kPhysiological.string()));
  const Scenario paper = assembleScenario(parseProtocol(kPaper10.string()));
  const double d = paper.accuracy.particleSpacing, cell = 0.25 * d;
  REQUIRE(rigid.accuracy.particleSpacing == d);
  REQUIRE(rigid.tissues[0].count == 0);  // rigid by the rule: the cavity wall alone
  const double reference = widestOpening(rigid, cell);
  const std::vector<sim::Vec3> fluid = fluidPositions(paper);
  REQUIRE(fluid.size() == paper.phases[0].count + paper.phases[1].count);
  const sim::World& world = *paper.world;
  const EscapePath path =
      findEscapePath(world.walls.x, fluid, world.parameters().domain, reference + 0.5 * cell, cell);
  INFO("rigid cavity wall's widest opening " << reference / d << " d; the paper eye's walls at "
                                             << (reference + 0.5 * cell) / d
                                             << " d: " << (path.escapes() ? "open" : "closed"));
  if (path.escapes()) {
    // Where it leads (mm, and the nearest wall particle in d): the narrowest point is the hole.
    const meshing::PointIndex wallGrid(world.walls.x, d);
    for (std::size_t k = 0; k < path.points.size();
         k += std::max<std::size_t>(1, path.points.size() / 40)) {
      const long w = wallGrid.nearest(path.points[k], 8.0 * d);
      UNSCOPED_INFO(
          "path " << k << ": " << path.points[k].transpose() * 1e3 << " mm, nearest wall "
                  << (w < 0 ? 8.0
                            : (world.walls.x[static_cast<std::size_t>(w)] - path.points[k]).norm() /
                                  d)
                  << " d");
    }
  }
  CHECK_FALSE(path.escapes());
}

TEST_CASE("tissue: the rule decides in both directions and a protocol can force either",
          "[unit][protocol][tissue]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_tissue_decide");
  const std::filesystem::path& dir = scratch.path();
  // 2 MPa in auto: rigid; forced elastic: elastic, marked forced.
  const std::string stiff = paperWith("youngs_modulus = \"10 kPa\"\nmode = \"elastic\"",
                                      "youngs_modulus = \"2 MPa\"\nmode = \"auto\"");
  Scenario rigid = assembleScenario(parseProtocolText(stiff, dir / "stiff.toml"));
  CHECK_FALSE(rigid.tissues[0].decision.elastic);
  const std::string forced = paperWith("youngs_modulus = \"10 kPa\"", "youngs_modulus = \"2 MPa\"");
  Scenario elastic = assembleScenario(parseProtocolText(forced, dir / "forced.toml"));
  CHECK(elastic.tissues[0].decision.elastic);
  CHECK(elastic.tissues[0].decision.forced);
  CHECK(elastic.tissues[0].describe().find("forced elastic") != std::string::npos);
  // 10 kPa forced rigid: the walls stay, the fat (forced elastic) sits behind a rigid sclera.
  const std::string soft = paperWith("youngs_modulus = \"10 kPa\"\nmode = \"elastic\"",
                                     "youngs_modulus = \"10 kPa\"\nmode = \"rigid\"");
  Scenario soft10 = assembleScenario(parseProtocolText(soft, dir / "soft.toml"));
  CHECK_FALSE(soft10.tissues[0].decision.elastic);
  CHECK_FALSE(soft10.tissues[0].decision.forced);  // anchored: the rule says rigid too
  CHECK(soft10.world->walls.size() == soft10.retina.areas.size());
  // 10 kPa not anchored, auto: a free membrane, p R^2 / (2 E t) ~ 4 mm, elastic by the rule.
  std::string free = paperWith("youngs_modulus = \"10 kPa\"\nmode = \"elastic\"",
                               "youngs_modulus = \"10 kPa\"\nmode = \"auto\"");
  const std::string anchorLine = "\nanchoring = \"outer_surface\"";
  REQUIRE(free.find(anchorLine) != std::string::npos);
  free.replace(free.find(anchorLine), anchorLine.size(), "\nanchoring = \"none\"");
  Scenario membrane = assembleScenario(parseProtocolText(free, dir / "free.toml"));
  CHECK(membrane.tissues[0].decision.elastic);
  CHECK_FALSE(membrane.tissues[0].decision.forced);
  CHECK(membrane.tissues[0].decision.reason.find("free membrane") != std::string::npos);
  // ratio R^2 / (2 t^2) ~ 340 at R ~ 11 mm, t = 0.42 mm
  CHECK(membrane.tissues[0].estimatedDisplacement >
        100.0 * soft10.tissues[0].estimatedDisplacement);
}

TEST_CASE("tissue: the example protocols validate, and plan prints each tissue's choice",
          "[unit][protocol][tissue][cli]") {
  const fs::path work = fs::temp_directory_path();
  for (const char* name : {"paper_sclera_10kpa.toml", "paper_sclera_100kpa.toml",
                           "paper_sclera_500kpa.toml", "physiological_sclera.toml"}) {
    const auto r =
        tamponade_test::runTamponade("validate '" + (kProtocols / name).string() + "'", work);
    INFO(name << "\n" << r.output);
    CHECK(r.exitCode == 0);
  }
  const auto plan = tamponade_test::runTamponade("plan '" + kPhysiological.string() + "'", work);
  INFO(plan.output);
  REQUIRE(plan.exitCode == 0);
  CHECK(plan.output.find("sclera (E 2000 kPa") != std::string::npos);
  CHECK(plan.output.find("rigid, anchored layer compressed, u = p t / E; estimated displacement") !=
        std::string::npos);
  CHECK(plan.output.find("treated as rigid wall") != std::string::npos);
  CHECK(plan.output.find("elastic stage time-step limit") == std::string::npos);
}

namespace {

// A few steps of the paper's 10 kPa protocol, run once and shared by the two test cases below.
struct PaperRun {
  Protocol protocol;
  Scenario scenario;
  RunSummary summary;
  std::string report;
  std::string summaryJson, rebuiltSummaryJson;  // summary.json of the run, and from `report DIR`
  std::vector<std::string> series;              // series names in frames.h5
};

const PaperRun& paperRun() {
  static const PaperRun run = [] {
    PaperRun r;
    // One folder per process: CTest runs the two cases sharing this run as parallel processes.
    const tamponade_test::ScratchDirectory scratch("tamponade_tissue_run");
    const fs::path out = scratch / "out";
    fs::create_directories(out);
    // A few steps: two postures of 12 ms (the protocol's INDSPH takes ~1.7 ms steps at d = 1.2 mm),
    // written as a protocol file so that the run records, and `report DIR` re-reads, the
    // shortened schedule.
    std::string text = tamponade_test::readText(kPaper10);
    for (std::size_t at; (at = text.find("duration = \"0.3 s\"")) != std::string::npos;)
      text.replace(at, 18, "duration = \"0.012 s\"");
    text.replace(text.find("frame_interval = \"0.05 s\""), 25, "frame_interval = \"0.005 s\"");
    const fs::path shortened = scratch / "out.toml";
    std::ofstream(shortened) << text;
    r.protocol = parseProtocol(shortened.string());
    REQUIRE(r.protocol.schedule.postures.size() == 2);
    for (const Posture& posture : r.protocol.schedule.postures)
      REQUIRE(posture.duration.value == Approx(12e-3));
    REQUIRE(r.protocol.outputs.frameInterval.value == Approx(5e-3));
    r.scenario = assembleScenario(r.protocol);
    RunOptions options;
    options.outputFolder = out;
    r.summary = runScenario(r.protocol, r.scenario, options);
    r.report = tamponade_test::readText(out / "report.html");
    r.summaryJson = tamponade_test::readText(out / "summary.json");
    r.series = FrameReader(out / "frames.h5").seriesNames();
    rebuildReport(out);  // recomputes coverage and tissue measures from the frames' ids
    r.rebuiltSummaryJson = tamponade_test::readText(out / "summary.json");
    return r;
  }();
  return run;
}

}  // namespace

TEST_CASE("tissue: a few steps of the paper's 10 kPa experiment stay finite and report the tissue",
          "[stability][protocol][tissue]") {
  const PaperRun& run = paperRun();
  const Scenario& s = run.scenario;
  CHECK(run.summary.steps > 10);
  const sim::DynamicParticles& particles = s.world->particles;
  bool finite = true;
  for (std::size_t i = 0; i < particles.size(); ++i)
    finite = finite && particles.x[i].allFinite() && particles.v[i].allFinite();
  CHECK(finite);
  CHECK(run.report.find("<h2>Tissue</h2>") != std::string::npos);
  CHECK(run.report.find("sclera: elastic, maximum displacement ") != std::string::npos);
  CHECK(run.report.find("orbital fat: elastic, maximum displacement ") != std::string::npos);
  CHECK(run.report.find("retina maximum displacement ") != std::string::npos);
  CHECK(run.report.find("cavity volume change ") != std::string::npos);
  const auto tissue = nlohmann::json::parse(run.summaryJson).at("tissue");
  REQUIRE_FALSE(tissue.empty());
  CHECK(tissue.at(0).get<std::string>().rfind("sclera: elastic", 0) == 0);
  CHECK(std::find(run.series.begin(), run.series.end(), "tissue") != run.series.end());
  // `tamponade report DIR` rebuilds the same coverage and tissue lines from the files.
  CHECK(run.rebuiltSummaryJson == run.summaryJson);
  const TissueMeasures m = measureTissues(s, particles.x, particles.id);
  INFO("after " << run.summary.steps << " steps: sclera " << m.maxDisplacement[0] << " m, fat "
                << m.maxDisplacement[1] << " m, retina " << m.retinaMaxDisplacement
                << " m, volume change " << m.cavityVolumeChange << " m^3 of " << s.cavityVolume);
  // No explosion. The fluid holds less than the cavity at rest density (MassRule::kRelaxedFill:
  // ~0.96 (V - A d/2), then a start-up shifting pass), so only the start's local over-density
  // (the largest kernel-summed volume fraction C_max of a fluid particle at t = 0; fillCompression
  // for the older rules) can push the wall out: a cavity grown by more than (C_max - 1) V would
  // mean the tissue left the fluid behind. And no sclera particle moves farther than its layer is
  // thick (that would have torn the shell).
  const double startExcess = std::max(s.fillCompression, s.startMaxFraction) - 1.0;  // [1]
  CHECK(startExcess > 0.0);
  CHECK(std::abs(m.cavityVolumeChange) < startExcess * s.cavityVolume);
  CHECK(m.maxDisplacement[0] < s.tissues[0].layerThickness);
  // retina samples follow sclera particles (same displacement up to the round-off of x - x0)
  CHECK(m.retinaMaxDisplacement <= m.maxDisplacement[0] * (1.0 + 1e-9));
}

// Anchored particles keep their rest positions: they are Dirichlet rows of the elastic solve, and
// the pipeline's "constrain" step sets them back to v = 0 after the pressure solver (which runs
// after the elastic solve and moved them 0.36 mm in 3 ms before that step existed).
TEST_CASE("tissue: anchored tissue particles stay at rest in a coupled eye scene",
          "[stability][protocol][tissue]") {
  const PaperRun& run = paperRun();
  const Scenario& s = run.scenario;
  const sim::DynamicParticles& particles = s.world->particles;
  double worstFixed = 0.0;  // [m]
  std::size_t anchored = 0;
  for (const TissueBody& t : s.tissues)
    for (std::size_t i = 0; i < particles.size(); ++i)
      if (sim::isFixed(particles, i) && particles.id[i] >= t.firstId &&
          particles.id[i] < t.firstId + static_cast<std::int32_t>(t.count)) {
        ++anchored;
        worstFixed = std::max(
            worstFixed, (particles.x[i] -
                         t.restPositions[static_cast<std::size_t>(particles.id[i] - t.firstId)])
                            .norm());
      }
  CHECK(anchored == s.tissues[0].anchored + s.tissues[1].anchored);
  CHECK(worstFixed < 1e-9);  // [m] round-off of x += dt * 0
}

// The leak counter (TissueMeasures::fluidInTissue / fluidThroughTissue) on constructed cases: the
// assembled paper scene at rest has no fluid outside the cavity; one fluid particle moved into the
// tissue (at a free sclera particle at least 1.5 d deep, i.e. a lattice layer behind the
// innermost) counts as in the tissue, one moved d beyond the sampled layer as through it, and
// one moved into a staircase opening (at the depth of the innermost sclera particle of its column,
// next to it) is not counted: it has not passed a tissue particle. The report then warns.
TEST_CASE(
    "tissue: the leak counter finds fluid in and beyond the sclera layer, not in its face's "
    "openings",
    "[unit][protocol][tissue]") {
  const Scenario s = assembleScenario(parseProtocol(kPaper10.string()));
  const double d = s.accuracy.particleSpacing;
  const TissueBody& sclera = s.tissues[0];
  const sim::DynamicParticles& particles = s.world->particles;
  std::vector<sim::Vec3> x(particles.x.begin(), particles.x.end());
  const std::vector<std::int32_t> ids(particles.id.begin(), particles.id.end());
  const TissueMeasures rest = measureTissues(s, x, ids);
  CHECK(rest.fluidInTissue == 0);
  CHECK(rest.fluidThroughTissue == 0);
  CHECK(rest.deepestFluid == 0.0);  // the fill lies inside the cavity
  const meshing::MeshQuery cavity(s.cavity);
  // Fluid particles to move: the first three of the aqueous.
  std::vector<std::size_t> fluid;
  for (std::size_t i = 0; i < particles.size() && fluid.size() < 3; ++i)
    if (particles.material[i] == s.phases[0].materialIndex) fluid.push_back(i);
  REQUIRE(fluid.size() == 3);
  // A retina sample over the sclera, away from the cap, and the sclera particle it follows (the
  // innermost of its column), whose depth leaves room for a point 1.2 d behind it in the layer.
  const RetinaSamples& r = s.retinaSamples;
  const auto depthOf = [&](const sim::Vec3& p) { return std::sqrt(cavity.squaredDistance(p)); };
  const auto followed = [&](std::size_t k) {
    return sclera.restPositions[static_cast<std::size_t>(r.followsId[k] - sclera.firstId)];
  };
  std::size_t w = 0;
  while (w < r.restPositions.size() && (r.scleraLayer[w] <= 0.0 || r.restPositions[w].z() > 0.0 ||
                                        depthOf(followed(w)) + 1.3 * d > r.scleraLayer[w]))
    ++w;
  REQUIRE(w < r.restPositions.size());
  const sim::Vec3 surface = r.restPositions[w], normal = r.normals[w];
  const sim::Vec3 innermost = followed(w);
  // (1) into an opening of the face: next to the innermost sclera particle, at its depth.
  x[fluid[0]] = innermost + 0.3 * d * normal.unitOrthogonal();
  TissueMeasures m = measureTissues(s, x, ids);
  CHECK(m.fluidInTissue == 0);
  CHECK(m.deepestFluid > 0.0);
  // (2) inside the layer: 1.2 d behind the innermost particle (more than the counter's d), still
  // within the sampled layer.
  x[fluid[1]] = innermost + 1.2 * d * normal;
  REQUIRE(depthOf(x[fluid[1]]) < r.scleraLayer[w]);
  m = measureTissues(s, x, ids);
  CHECK(m.fluidInTissue == 1);
  CHECK(m.fluidThroughTissue == 0);
  // (3) beyond the layer: d behind its outer face (in the gap before the backstop).
  x[fluid[2]] = surface + (r.scleraLayer[w] + d) * normal;
  m = measureTissues(s, x, ids);
  CHECK(m.fluidInTissue == 2);
  CHECK(m.fluidThroughTissue == 1);
  bool warned = false;
  for (const std::string& line : tissueReportLines(s, m, 0.1))
    warned = warned || line.rfind("warning: fluid in the tissue: 2 particles", 0) == 0;
  CHECK(warned);
  for (const std::string& line : tissueReportLines(s, rest, 0.1))
    CHECK(line.find("warning") == std::string::npos);
}

// The fluid stays out of the elastic sclera in the first 24 ms of a coupled eye scene (the tissue
// leak): no fluid particle is inside the tissue by the leak counter's criterion (a full spacing
// behind a sclera particle near it; tissue_particles.h). Fluid in the openings of the
// lattice-sampled face (the staircase's hollows, up to ~1 d outside the cavity surface) is
// allowed: that is the surface's discretisation, not penetration. The earlier criterion (no fluid
// beyond d/2 + u_max outside the surface) failed on those hollows (0.82 d, 6 particles), so the
// test was hidden. The counter does find real leaks: the 2 x 0.3 s run of the same protocol
// counts 3 fluid particles in the tissue at 0.1 s and 42 at 0.6 s (docs/methods/elasticity.md, "The
// limbus clamp and the bony orbit"); a sampling that lets fluid in at once (one tried layering:
// 2.03 d deep in 24 ms) would fail here. The counter itself is tested on constructed cases above.
TEST_CASE(
    "tissue: no fluid particle enters the elastic sclera's layer in the first 24 ms of a coupled "
    "eye scene",
    "[stability][leak][protocol][tissue]") {
  const PaperRun& run = paperRun();
  const Scenario& s = run.scenario;
  const double d = s.accuracy.particleSpacing;
  const sim::DynamicParticles& particles = s.world->particles;
  const TissueMeasures m = measureTissues(s, particles.x, particles.id);
  std::size_t fluid = 0;
  for (std::size_t i = 0; i < particles.size(); ++i)
    fluid += particles.material[i] == s.phases[0].materialIndex ||
             particles.material[i] == s.phases[1].materialIndex;
  INFO(fluid << " fluid particles after " << run.summary.steps << " steps: the farthest "
             << m.deepestFluid / d << " d outside the cavity surface, " << m.fluidInTissue
             << " in the tissue, " << m.fluidThroughTissue
             << " beyond its layer; sclera max displacement " << m.maxDisplacement[0] / d << " d");
  REQUIRE(fluid == s.phases[0].count + s.phases[1].count);
  CHECK(m.fluidInTissue == 0);
  CHECK(m.fluidThroughTissue == 0);
}

TEST_CASE("tissue: bad input is reported at its place with exit code 2",
          "[unit][protocol][tissue][cli]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_tissue_bad");
  const std::filesystem::path& dir = scratch.path();
  struct Case {
    const char* name;
    std::string text;
    std::string command;
    std::string message;
    std::string location;  // file:line:column
  };
  const fs::path mesh =
      fs::path(TAMPONADE_SOURCE_DIR) / "data" / "meshes" / "emmetropic_al23.58mm.stl";
  // Locations are file:line:column in paper_sclera_10kpa.toml as edited by each case.
  const std::vector<Case> cases = {
      {"zero modulus", paperWith("youngs_modulus = \"10 kPa\"", "youngs_modulus = \"0 kPa\""),
       "validate", "eye.sclera.youngs_modulus", ":32:18"},
      {"negative modulus", paperWith("youngs_modulus = \"1 kPa\"", "youngs_modulus = \"-1 kPa\""),
       "validate", "eye.orbital_fat.youngs_modulus", ":38:18"},
      {"poisson 0.5",
       paperWith("mode = \"elastic\"\nanchoring = \"outer",
                 "poisson_ratio = 0.5\nmode = \"elastic\"\nanchoring = \"outer"),
       "validate", "eye.sclera.poisson_ratio", ":33:17"},
      {"poisson negative",
       paperWith("mode = \"elastic\"\nanchoring = \"back",
                 "poisson_ratio = -0.1\nmode = \"elastic\"\nanchoring = \"back"),
       "validate", "eye.orbital_fat.poisson_ratio", ":39:17"},
      {"sclera thicker than the anatomy allows",
       paperWith("mode = \"elastic\"\nanchoring = \"outer",
                 "thickness = \"2 mm\"\nmode = \"elastic\"\nanchoring = \"outer"),
       "plan", "sclera thickness", ":33:13"},
      {"layered cavity wall asked for next to the elastic sclera",
       paperWith("particle_spacing = \"1.2 mm\"",
                 "particle_spacing = \"1.2 mm\"\nwall_model = \"layered\""),
       "plan", "wall_model = \"layered\", but the elastic sclera replaces part of the cavity wall",
       ":67:14"},
      {"forced elastic sclera on an imported mesh",
       paperWith(
           "kind = \"staphyloma\"          # the paper's MRI eye is myopic with an irregular "
           "posterior wall\n"
           "side = \"OD\"\naxial_length = \"26 mm\"\nstaphyloma_depth = \"1.5 "
           "mm\"\nstaphyloma_width = \"8 mm\"",
           "kind = \"mesh\"\nside = \"OD\"\nmesh = \"" + mesh.string() + "\"\nmesh_units = \"mm\""),
       "plan", "mode = \"elastic\" for the sclera on an imported mesh cavity, which has no anatomy",
       ":32:8"},
  };
  for (const Case& c : cases) {
    const fs::path file = dir / "bad.toml";
    std::ofstream(file) << c.text;
    const auto r = tamponade_test::runTamponade(c.command + " '" + file.string() + "'", dir);
    INFO(c.name << "\n" << r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(c.message) != std::string::npos);
    CHECK(r.output.find(file.string() + c.location) != std::string::npos);
  }
  // The library throws ProtocolError for the mesh case (what the CLI turns into exit code 2).
  const std::string meshText = cases.back().text;
  CHECK_THROWS_AS(assembleScenario(parseProtocolText(meshText, dir / "mesh.toml")), ProtocolError);
}

// Elastic tissue, validation 6 (docs/methods/elasticity.md): a stiff (2 MPa, human) sclera around
// the fluid-filled cavity, forced elastic, coupled in INDSPH's pressure solve, stays stable. The
// sclera is held at its outer surface, so under the fluid's pressure its layer can only be
// compressed: the static answer is u = p t_layer / E_sim for the simulated layer (2 particle
// layers, E scaled to keep E t), and the largest displacement must stay below twice that: a
// suddenly applied load overshoots an undamped spring by at most 2x its static deflection. No lower
// bound: the fill starts slightly under-dense next to the one-particle-thick tissue (mean C 0.94,
// docs/methods/solvers.md "Fluid fill") and the clamped pressure builds only as the fluid settles
// into that gap (0.1 um after 10 ms, 2.0 um at most over the 20 ms of the two-posture CLI run,
// against 2.03 um static).
TEST_CASE(
    "tissue: a 2 MPa sclera around the filled cavity stays stable, compressed less than 2 p t / E",
    "[stability][protocol][tissue]") {
  std::string text = tamponade_test::readText(kPhysiological);
  const std::string autoMode = "mode = \"auto\"";
  REQUIRE(text.find(autoMode) != std::string::npos);
  text.replace(text.find(autoMode), autoMode.size(), "mode = \"elastic\"");  // the sclera's
  const std::string version = "format_version = 1\n";
  REQUIRE(text.find(version) != std::string::npos);
  text.replace(text.find(version), version.size(), version + "solver = \"indsph\"\n");
  const tamponade_test::ScratchDirectory dir("tamponade_stiff");
  Protocol p = parseProtocolText(text, dir / "stiff.toml");
  Scenario s = assembleScenario(p);
  REQUIRE(s.pipelineOptions.solver == "indsph");
  REQUIRE(s.tissues[0].decision.elastic);
  REQUIRE(s.tissues[0].decision.forced);
  // The limbus clamp and the collar are in this scene too: the bound below holds with them.
  CHECK(s.tissues[0].limbusClamped > 0);
  s.world->gravity = s.schedule.front().gravity;
  sim::Pipeline pipeline = sim::assemblePipeline(*s.world, s.pipelineOptions);
  pipeline.attach(*s.world);
  int steps = 0;
  while (s.world->time < 0.01) pipeline.step(*s.world), ++steps;
  const sim::DynamicParticles& particles = s.world->particles;
  bool finite = true;
  for (std::size_t i = 0; i < particles.size(); ++i)
    finite = finite && particles.x[i].allFinite() && particles.v[i].allFinite();
  REQUIRE(finite);
  const TissueBody& sclera = s.tissues[0];
  const double staticCompression =
      sclera.loadPressure * sclera.layerThickness / sclera.simulatedModulus;  // [m]
  const TissueMeasures m = measureTissues(s, particles.x, particles.id);
  INFO(steps << " steps to t = " << s.world->time << " s: sclera max displacement "
             << m.maxDisplacement[0] << " m, static p t / E " << staticCompression << " m; fat "
             << m.maxDisplacement[1] << " m; cavity volume change " << m.cavityVolumeChange
             << " m^3");
  CHECK(m.maxDisplacement[0] < 2.0 * staticCompression);
  CHECK(m.maxDisplacement[0] > 0.0);  // the fluid loads it
  // Stable in the sense of the issue: nothing flew off (the domain check would have thrown), and
  // the cavity changed by less than the compressed layer's volume, A x 2 p t / E.
  CHECK(std::abs(m.cavityVolumeChange) < s.cavityArea * 2.0 * staticCompression);
}
