// Scenes for the interface tests: an oil droplet in aqueous in a closed box without
// gravity, and a sessile droplet on the floor of such a box.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "scene_fixtures.h"
#include "sim/boundary/wall_layers.h"
#include "sim/boundary/wetted_surface.h"
#include "sim/measure/droplet_pressure_jump.h"
#include "sim/measure/sessile_contact_angle.h"
#include "sim/measure/wall_nearest_material.h"
#include "sim/measure/wall_phase_fraction.h"
#include "sim/solid/fixed_particles.h"

namespace sim::testing {

inline Material liquid(const char* name, Real rho, Real mu) {
  Material m;
  m.name = name;
  m.restDensity = rho;      // [kg/m^3]
  m.dynamicViscosity = mu;  // [Pa s]
  return m;
}

inline constexpr int kFloorTag = 1;  // wall tag of the box floor (y = 0); other walls keep 0

struct DropletScene {
  TankSpec spec;
  std::unique_ptr<World> world;
  int oil = 0, aqueous = 1;
  int tissue = -1;             // the tissue floor's material (DropletSpec::tissueFloorLayers)
  Vec3 centre = Vec3::Zero();  // [m] centre of the droplet sphere as placed
  Real radius = 0;             // [m] equivalent radius of the droplet's lattice volume
  // [m] height of the floor as the fluid fills it, the lattice's lower cell face: 0 with layered
  // walls (half-way between the wall's surface layer and the first fluid layer), (kWallGap - 0.5)
  // d with one Akinci layer, whose particle centres are at y = 0.
  Real floorHeight = 0;
};

struct DropletSpec {
  Real radius = 0;               // [m] droplet radius R
  Real spacing = 0;              // [m] particle spacing d
  Real halfWidth = 0;            // [m] half the inner width of the cubic box (fluid part)
  Real sigma = 0;                // [N/m]
  Real oilDensity = 970;         // [kg/m^3] silicone oil (reference-data.md section 1.1)
  Real aqueousDensity = 1000;    // [kg/m^3]
  Real oilViscosity = 1e-3;      // [Pa s]
  Real aqueousViscosity = 1e-3;  // [Pa s]
  // [1] particle masses are rho0 d^3 (1 + excess): a small uniform compression gives the closed
  // box a positive background pressure, so the Tait equation's clamp at p = 0 (free-surface
  // treatment) never acts where the droplet's outside is slightly expanded.
  Real massExcess = 0.01;
  // Sessile: the droplet centre sits at height (cos of the start angle) R above the floor, i.e.
  // a cap cut by the floor; <= -1 means a free droplet centred in the box.
  Real sessileStartCos = -2;
  Real boxHeight = 0;  // [m] inner height for sessile scenes (0: same as the width)
  // [1] shape perturbation of a free droplet, r(theta) = R (1 + eps P2(cos theta)) with theta
  // from the +y axis (the l = 2 mode of the oscillation benchmark)
  Real p2Amplitude = 0;
  // [1] 0: the walls are one Akinci 2012 surface layer and the lattice starts kWallGap d from
  // them; n >= 1: n layers of lattice wall particles (sim/boundary/wall_layers.h) continuing the
  // fluid lattice, which then starts d/2 from the faces (the layered wall's rest state).
  int wallLayers = 0;
  // [d] each lattice position moved by up to this much per axis (std::mt19937, seed 7: the same
  // sequence on every platform); the phase is decided at the lattice site.
  Real jitter = 0;
  Real maxTimeStep = 0;  // [s] WorldParameters::maxTimeStep when > 0
  // n >= 1 (layered walls only): the lowest n lattice layers are an elastic tissue on the
  // floor's wall, unjittered, its top layer the floor tag's wetted surface
  // (sim/boundary/wetted_surface.h); all but the top `tissueFreeLayers` layers are anchored.
  int tissueFloorLayers = 0;
  int tissueFreeLayers = 0;
  Real tissueYoungsModulus = 5e4;  // [Pa]
  Vec3 gravity = Vec3::Zero();     // [m/s^2]
  bool cachePairKernels = true;    // WorldParameters::cachePairKernels
};

// Fills the box from `origin` with nx x ny x nz lattice sites of spacing d, one particle at each
// site's centre moved by up to `jitter` d per axis (std::mt19937, seed 7: the same start every
// run), of the material `materialAt(site centre)` returns and mass rest density d^3 (1 +
// massExcess). Shared by the droplet, meniscus and ridge scenes.
template <class MaterialAt>
void fillJitteredLattice(World& w, const Vec3& origin, int nx, int ny, int nz, Real d, Real jitter,
                         Real massExcess, MaterialAt materialAt) {
  std::mt19937 random(7);
  const auto offset = [&] {
    return jitter * d * (2.0 * static_cast<Real>(random()) / 4294967295.0 - 1.0);
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec3 x = origin + d * Vec3(i + 0.5, j + 0.5, k + 0.5);
        const int m = materialAt(x);
        const Vec3 moved = jitter > 0 ? Vec3(x + Vec3(offset(), offset(), offset())) : x;
        w.particles.add(moved, Vec3::Zero(),
                        w.materials[m].restDensity * d * d * d * (1 + massExcess), m);
      }
}

// Fills the closed box on a lattice of spacing d starting kWallGap d from the walls; particles
// within R of the centre are oil, the others aqueous. The droplet radius reported is the
// radius of a sphere with the oil lattice's volume (N_oil d^3), which is what the pressure jump
// of the relaxed droplet follows, not the nominal R.
inline DropletScene dropletScene(const DropletSpec& s) {
  DropletScene out;
  const Real d = s.spacing;
  const bool layered = s.wallLayers > 0;
  const Real gap = layered ? 0.0 : (kWallGap - 0.5) * d;
  // Layered walls continue the fluid lattice: the box holds whole cells.
  auto cells = [&](Real length) { return layered ? std::round(length / d) * d : length; };
  const Real width = cells(2 * s.halfWidth);
  require(s.tissueFloorLayers == 0 || layered, "a tissue floor continues a layered wall's lattice");
  const Real tissueTop = s.tissueFloorLayers * d;  // [m]
  const Real height = cells(s.boxHeight > 0 ? s.boxHeight : width) + tissueTop;
  out.spec.innerMin = Vec3::Zero();
  out.spec.innerMax = Vec3(width + 2 * gap, height + 2 * gap, width + 2 * gap);
  out.spec.closedTop = true;
  WorldParameters params;
  params.particleSpacing = d;
  params.gravity = s.gravity;
  params.domain = tankDomain(out.spec, d);
  if (layered) {  // room for the layers behind the faces
    params.domain.extend(out.spec.innerMin - Vec3::Constant((s.wallLayers + 1) * d));
    params.domain.extend(out.spec.innerMax + Vec3::Constant((s.wallLayers + 1) * d));
  }
  if (s.maxTimeStep > 0) params.maxTimeStep = s.maxTimeStep;
  params.cachePairKernels = s.cachePairKernels;
  out.world = std::make_unique<World>(params);
  World& w = *out.world;
  out.oil = w.materials.add(liquid("oil", s.oilDensity, s.oilViscosity));
  out.aqueous = w.materials.add(liquid("aqueous", s.aqueousDensity, s.aqueousViscosity));
  w.materials.setInterfacialTension(out.oil, out.aqueous, s.sigma);
  if (s.tissueFloorLayers > 0) {
    Material tissue;
    tissue.name = "tissue";
    tissue.kind = MaterialKind::kElastic;
    tissue.restDensity = 1000;  // [kg/m^3]
    tissue.youngsModulus = s.tissueYoungsModulus;
    tissue.poissonRatio = 0.3;
    out.tissue = w.materials.add(tissue);
  }
  if (layered)
    addTankWalls(w, out.spec, d, 0, WallLayers{s.wallLayers});
  else
    addTankWalls(w, out.spec, d);
  // The floor gets its own tag so that a contact angle can be set on it alone.
  for (std::size_t b = 0; b < w.walls.size(); ++b)
    if (w.walls.normal[b].y() < -0.5) w.walls.tag[b] = kFloorTag;
  const bool sessile = s.sessileStartCos > -1;
  // The floor's fluid side is y = gap (above a tissue floor, its top); the first fluid lattice
  // layer sits d/2 above it.
  out.floorHeight = gap + tissueTop;
  out.centre =
      sessile ? Vec3(0.5 * out.spec.innerMax.x(), out.floorHeight + s.sessileStartCos * s.radius,
                     0.5 * out.spec.innerMax.z())
              : Vec3(0.5 * out.spec.innerMax);
  const int nx = static_cast<int>(std::lround(width / d));
  const int ny = static_cast<int>(std::lround(height / d));
  int oilCount = 0;
  fillJitteredLattice(
      w, Vec3::Constant(gap), nx, ny, nx, d, s.jitter, s.massExcess, [&](const Vec3& x) {
        if (x.y() < out.floorHeight) return out.tissue;
        const Vec3 r = x - out.centre;
        const Real c = r.norm() > 0 ? r.y() / r.norm() : 0;
        const bool isOil = r.norm() < s.radius * (1 + s.p2Amplitude * 0.5 * (3 * c * c - 1));
        oilCount += isOil;
        return isOil ? out.oil : out.aqueous;
      });
  out.radius = std::cbrt(3.0 * oilCount * d * d * d / (4.0 * std::numbers::pi));
  for (Index i = 0; i < static_cast<Index>(w.particles.size()); ++i) {
    if (w.particles.material[i] != out.tissue) continue;
    Vec3& x = w.particles.x[i];  // back to its lattice site (the jitter moved it < d/2)
    for (int a = 0; a < 3; ++a) x[a] = gap + d * (std::floor((x[a] - gap) / d) + 0.5);
    if (x.y() > out.floorHeight - d) setWettedSurfaceTag(w.particles, i, kFloorTag);
    if (x.y() < out.floorHeight - s.tissueFreeLayers * d) setFixed(w.particles, i);
  }
  w.initialize();
  return out;
}

// A closed spherical cavity (validation 5): one layer of wall particles on a sphere of radius
// Rs about the origin (a Fibonacci point set, about one point per d^2 of area, outward normals,
// Akinci volumes computed by the World), filled with aqueous up to kWallGap d from the wall; the
// particles beyond the plane x.axis > offset are oil.
struct CavitySpec {
  Real cavityRadius = 0;         // [m] Rs, the fluid side of the wall
  Real spacing = 0;              // [m] d
  Real sigma = 0;                // [N/m]
  Real oilDensity = 970;         // [kg/m^3]
  Real aqueousDensity = 1000;    // [kg/m^3]
  Real viscosity = 1e-3;         // [Pa s] both phases
  Real massExcess = 0.01;        // [1] as DropletSpec::massExcess
  Vec3 gravity = Vec3::Zero();   // [m/s^2]
  Vec3 oilAxis = Vec3::UnitY();  // the oil starts beyond a plane normal to this axis...
  Real oilOffset = 0;            // [m] ...at this signed distance from the centre
  // [m] > 0: the oil starts instead as the column of this radius about oilAxis (it touches the
  // wall at both poles; under gravity it must rise and spread into a layer)
  Real oilColumnRadius = 0;
  // [1] 0: the one Akinci layer above. n >= 1: layered walls cut from one cubic lattice of
  // spacing d (centred on the cavity, no point at the centre): the lattice points within Rs are
  // fluid, those in the shell Rs < |x| <= Rs + n d are wall particles of volume d^3, layer
  // floor((|x| - Rs) / d), normal x / |x|. Fluid and walls then form one lattice, at rest
  // number density everywhere, and the wall's surface is a staircase about the sphere.
  int latticeWallLayers = 0;
};

struct CavityScene {
  std::unique_ptr<World> world;
  int oil = 0, aqueous = 1;
  Real oilVolumeFraction =
      0;  // [1] oil particles' rest volume over all fluid particles' rest volume
  std::vector<Real> wallArea;  // [m^2] per wall particle (equal areas: 4 pi Rs^2 / N)
};

inline CavityScene cavityScene(const CavitySpec& s) {
  CavityScene out;
  const Real d = s.spacing, rs = s.cavityRadius;
  WorldParameters params;
  params.particleSpacing = d;
  params.gravity = s.gravity;
  const Real reach = rs + (s.latticeWallLayers + 3) * d;
  params.domain = Box(Vec3::Constant(-reach), Vec3::Constant(reach));
  out.world = std::make_unique<World>(params);
  World& w = *out.world;
  out.oil = w.materials.add(liquid("oil", s.oilDensity, s.viscosity));
  out.aqueous = w.materials.add(liquid("aqueous", s.aqueousDensity, s.viscosity));
  if (s.sigma > 0) w.materials.setInterfacialTension(out.oil, out.aqueous, s.sigma);
  const Vec3 axis = s.oilAxis.normalized();
  auto isOil = [&](const Vec3& x) {
    return s.oilColumnRadius > 0 ? (x - x.dot(axis) * axis).norm() < s.oilColumnRadius
                                 : x.dot(axis) > s.oilOffset;
  };
  if (s.latticeWallLayers > 0) {
    const int n = static_cast<int>(std::ceil(rs / d)) + s.latticeWallLayers + 1;
    const Real shell = rs + s.latticeWallLayers * d;
    std::size_t surface = 0;
    Real oilVolume = 0, volume = 0;
    for (int i = -n; i < n; ++i)
      for (int j = -n; j < n; ++j)
        for (int k = -n; k < n; ++k) {
          const Vec3 x = d * Vec3(i + 0.5, j + 0.5, k + 0.5);
          const Real r = x.norm();
          if (r <= rs) {
            const int mat = isOil(x) ? out.oil : out.aqueous;
            w.particles.add(x, Vec3::Zero(),
                            w.materials[mat].restDensity * d * d * d * (1 + s.massExcess), mat);
            volume += d * d * d;
            if (mat == out.oil) oilVolume += d * d * d;
          } else if (r <= shell) {
            const int layer = std::min(static_cast<int>((r - rs) / d), s.latticeWallLayers - 1);
            addLayeredWallParticle(w.walls, x, x / r, 0, d * d * d, layer);
            if (layer == 0) ++surface;
          }
        }
    const auto& layerOf = wallLayerField(w.walls);
    out.wallArea.assign(w.walls.size(), 0);
    for (std::size_t b = 0; b < w.walls.size(); ++b)
      if (layerOf[b] == 0)
        out.wallArea[b] = 4 * std::numbers::pi * rs * rs / static_cast<Real>(surface);
    out.oilVolumeFraction = oilVolume / volume;
    w.initialize();
    return out;
  }
  // Fibonacci sphere (golden-angle spiral): equal-area points, spacing close to d everywhere.
  const auto n = static_cast<std::size_t>(std::lround(4 * std::numbers::pi * rs * rs / (d * d)));
  const Real golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (std::size_t k = 0; k < n; ++k) {
    const Real y = 1 - 2 * (k + 0.5) / static_cast<Real>(n);
    const Real r = std::sqrt(1 - y * y), phi = golden * static_cast<Real>(k);
    const Vec3 u(r * std::cos(phi), y, r * std::sin(phi));
    w.walls.add(rs * u, u);
  }
  out.wallArea.assign(n, 4 * std::numbers::pi * rs * rs / static_cast<Real>(n));
  // The fluid: concentric Fibonacci shells of radii Rs - kWallGap d - k d, each particle with
  // the volume of its shell's share (the shell spans +-d/2 radially), so the fluid fills the
  // cavity up to Rs - (kWallGap - 1/2) d as a lattice block fills a box. (A cubic lattice cut
  // at Rs - kWallGap d fills only the sphere of that radius: 62 % of the cavity at Rs = 8 d, and
  // under gravity the fluid slumped and left the top 1.7 mm of a 3 mm cavity empty.)
  Real oilVolume = 0, volume = 0;
  for (Real r = rs - kWallGap * d; r > 0.25 * d; r -= d) {
    const Real outer = r + 0.5 * d, inner = std::max(r - 0.5 * d, Real(0));
    const Real shellVolume =
        4 * std::numbers::pi / 3 * (outer * outer * outer - inner * inner * inner);
    const auto count =
        std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(shellVolume / (d * d * d))));
    const Real v = shellVolume / static_cast<Real>(count);  // [m^3]
    for (std::size_t k = 0; k < count; ++k) {
      const Real y = 1 - 2 * (k + 0.5) / static_cast<Real>(count);
      const Real rho = std::sqrt(1 - y * y), phi = golden * static_cast<Real>(k);
      const Vec3 x = r * Vec3(rho * std::cos(phi), y, rho * std::sin(phi));
      const int mat = isOil(x) ? out.oil : out.aqueous;
      w.particles.add(x, Vec3::Zero(), w.materials[mat].restDensity * v * (1 + s.massExcess), mat);
      volume += v;
      if (mat == out.oil) oilVolume += v;
    }
  }
  out.oilVolumeFraction = oilVolume / volume;
  w.initialize();
  return out;
}

// Closed forms of validation 5, for a cavity of radius 1 (every length over Rs) and an oil
// volume fraction v of the cavity; coverage = oil-wetted share of the wall area.
// (b) No tension, flat interface normal to gravity: the oil fills a cap of height x, volume
// fraction x^2 (3 - x) / 4, and covers the zone above it, area fraction x / 2.
inline Real flatCoverage(Real v) {
  Real lo = 0, hi = 2;
  for (int k = 0; k < 100; ++k) {
    const Real x = 0.5 * (lo + hi);
    (x * x * (3 - x) / 4 < v ? lo : hi) = x;
  }
  return 0.25 * (lo + hi);
}
// (a) No gravity: the oil is the lens between the cavity and a sphere of radius r whose centre
// is c from the cavity's; the spheres meet at theta through the oil when the outward normals'
// cosine (1 + r^2 - c^2) / (2 r) is -cos(theta), i.e. c^2 = 1 + r^2 + 2 r cos(theta). Lens volume
// of two spheres (radii 1, r, distance c): pi (1 + r - c)^2 (c^2 + 2 c r - 3 r^2 + 2 c + 6 r - 3)
// / (12 c); its wall part is the zone beyond the plane at a = (c^2 + 1 - r^2) / (2 c), area
// fraction (1 - a) / 2. The volume grows with r (bisection on log r). Valid for v below the
// flat-interface limit of theta (r -> infinity).
struct LensShape {
  Real coverage = 0;  // [1]
  Real radius = 0;    // [1] r / Rs
  Real distance = 0;  // [1] c / Rs
};
inline LensShape lensCoverage(Real v, Real thetaOilDeg) {
  const Real ct = std::cos(thetaOilDeg * std::numbers::pi / 180);
  auto shape = [ct](Real r) {
    const Real c = std::sqrt(1 + r * r + 2 * r * ct);
    const Real volume = std::numbers::pi * (1 + r - c) * (1 + r - c) *
                        (c * c + 2 * c * r - 3 * r * r + 2 * c + 6 * r - 3) / (12 * c);
    return std::pair<Real, Real>(volume / (4 * std::numbers::pi / 3), c);
  };
  Real lo = 1e-6, hi = 1e4;
  for (int k = 0; k < 200; ++k) {
    const Real r = std::sqrt(lo * hi);
    (shape(r).first < v ? lo : hi) = r;
  }
  const Real r = std::sqrt(lo * hi), c = shape(r).second;
  return {0.5 * (1 - (c * c + 1 - r * r) / (2 * c)), r, c};
}

// Oil coverage of the cavity wall, two ways: the area share of wall particles whose nearest
// fluid particle is oil (wallNearestMaterial: the interface's position on the wall, whatever gap
// the fluid leaves at the wall), and the area share whose Shepard oil fraction is >= 0.5
// (wallPhaseFraction: the definition of protocols/coverage, where a wall particle with no fluid
// within h counts as not covered); plus the "dry" share (no fluid within h) and the contact
// angle of the interface fitted as a sphere (points more than 2 d inside the wall; 0 if the fit
// fails).
// [deg] The angle through the oil at which an interface fitted as the sphere `f` meets a cavity of
// radius `rs` about the origin, the oil's centroid at `oilCentre` [m]. The outward normals of the
// cavity and of the fitted sphere meet at cos beta = (Rs^2 + r^2 - c^2) / (2 Rs r). The oil's
// interior angle is 180 deg minus the angle between its region's outward normals: theta =
// acos(-cos beta) when the oil is inside the fitted sphere (a bulging lens), acos(cos beta) when
// it is outside (a concave interface).
inline Real cavityAngleThroughOil(const SphereFit& f, Real rs, const Vec3& oilCentre) {
  const Real c = f.centre.norm(), r = f.radius;
  const Real cosBeta = (rs * rs + r * r - c * c) / (2 * rs * r);
  const bool oilInside = (oilCentre - f.centre).norm() < r;
  return std::acos(std::clamp(oilInside ? -cosBeta : cosBeta, Real(-1), Real(1))) * 180 /
         std::numbers::pi;
}

struct CavityState {
  Real coverage = 0;         // [1] nearest fluid is oil
  Real shepardCoverage = 0;  // [1] phi >= 0.5
  Real dry = 0;              // [1] no fluid within h
  Real angle = 0;            // [deg] through the oil, from the fitted sphere and the cavity
  Vec3 axis = Vec3::Zero();  // [1] direction of the area centroid of the oil-covered wall (the
                             // cap's axis; zero if nothing is covered)
};
inline CavityState measureCavity(const CavityScene& scene, Real rs) {
  const World& w = *scene.world;
  const std::vector<Real> phi = wallPhaseFraction(w, scene.oil);
  const std::vector<int> nearest = wallNearestMaterial(w);
  // A wall particle is dry when no fluid particle lies within h: its Shepard sum is empty.
  std::vector<char> wet(phi.size(), 0);
  const NeighborList& nw = w.wallNeighbors();
  for (Index i = 0; i < w.particles.size(); ++i)
    for (const Index* b = nw.begin(i); b != nw.end(i); ++b)
      if ((w.particles.x[i] - w.walls.x[*b]).norm() < w.supportRadius()) wet[*b] = 1;
  Real oilNear = 0, oilShepard = 0, dry = 0, total = 0;
  Vec3 axisSum = Vec3::Zero();
  for (std::size_t b = 0; b < phi.size(); ++b) {
    const Real a = scene.wallArea[b];
    total += a;
    if (nearest[b] == scene.oil) {
      oilNear += a;
      axisSum += a * w.walls.x[b];
    }
    if (phi[b] >= 0.5) oilShepard += a;
    if (!wet[b]) dry += a;
  }
  CavityState out;
  out.coverage = oilNear / total;
  out.shepardCoverage = oilShepard / total;
  out.dry = dry / total;
  if (axisSum.norm() > 0) out.axis = axisSum.normalized();
  std::vector<Vec3> points = interfacePairMidpoints(w, scene.oil);
  const Real inner = rs - 2 * w.particleSpacing();
  std::erase_if(points, [inner](const Vec3& x) { return x.norm() > inner; });
  if (points.size() >= 8) {
    out.angle = cavityAngleThroughOil(fitSphere(points), rs, centreOfMaterial(w, scene.oil));
  }
  return out;
}

}  // namespace sim::testing
