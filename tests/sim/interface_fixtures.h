// Scenes for the interface tests (issue 6): an oil droplet in aqueous in a closed box without
// gravity, and a sessile droplet on the floor of such a box.
#pragma once

#include <cmath>
#include <memory>
#include <numbers>

#include "scene_fixtures.h"

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
  Vec3 centre = Vec3::Zero();  // [m] centre of the droplet sphere as placed
  Real radius = 0;             // [m] equivalent radius of the droplet's lattice volume
};

struct DropletSpec {
  Real radius = 0;            // [m] droplet radius R
  Real spacing = 0;           // [m] particle spacing d
  Real halfWidth = 0;         // [m] half the inner width of the cubic box (fluid part)
  Real sigma = 0;             // [N/m]
  Real oilDensity = 970;      // [kg/m^3] silicone oil (reference-data.md section 1.1)
  Real aqueousDensity = 1000; // [kg/m^3]
  Real oilViscosity = 1e-3;   // [Pa s]
  Real aqueousViscosity = 1e-3;  // [Pa s]
  // [1] particle masses are rho0 d^3 (1 + excess): a small uniform compression gives the closed
  // box a positive background pressure, so the Tait equation's clamp at p = 0 (free-surface
  // treatment) never acts where the droplet's outside is slightly expanded.
  Real massExcess = 0.01;
  // Sessile: the droplet centre sits at height (cos of the start angle) R above the floor, i.e.
  // a cap cut by the floor; <= -1 means a free droplet centred in the box.
  Real sessileStartCos = -2;
  Real boxHeight = 0;         // [m] inner height for sessile scenes (0: same as the width)
  // [1] shape perturbation of a free droplet, r(theta) = R (1 + eps P2(cos theta)) with theta
  // from the +y axis (the l = 2 mode of the oscillation benchmark)
  Real p2Amplitude = 0;
};

// Fills the closed box on a lattice of spacing d starting kWallGap d from the walls; particles
// within R of the centre are oil, the others aqueous. The droplet radius reported is the
// radius of a sphere with the oil lattice's volume (N_oil d^3), which is what the pressure jump
// of the relaxed droplet follows, not the nominal R.
inline DropletScene dropletScene(const DropletSpec& s) {
  DropletScene out;
  const Real d = s.spacing;
  const Real gap = (kWallGap - 0.5) * d;
  const Real width = 2 * s.halfWidth;
  const Real height = s.boxHeight > 0 ? s.boxHeight : width;
  out.spec.innerMin = Vec3::Zero();
  out.spec.innerMax = Vec3(width + 2 * gap, height + 2 * gap, width + 2 * gap);
  out.spec.closedTop = true;
  WorldParameters params;
  params.particleSpacing = d;
  params.gravity = Vec3::Zero();
  params.domain = tankDomain(out.spec, d);
  out.world = std::make_unique<World>(params);
  World& w = *out.world;
  out.oil = w.materials.add(liquid("oil", s.oilDensity, s.oilViscosity));
  out.aqueous = w.materials.add(liquid("aqueous", s.aqueousDensity, s.aqueousViscosity));
  w.materials.setInterfacialTension(out.oil, out.aqueous, s.sigma);
  addTankWalls(w, out.spec, d);
  // The floor gets its own tag so that a contact angle can be set on it alone.
  for (std::size_t b = 0; b < w.walls.size(); ++b)
    if (w.walls.normal[b].y() < -0.5) w.walls.tag[b] = kFloorTag;
  const bool sessile = s.sessileStartCos > -1;
  // The floor's fluid side is y = 0; the first lattice layer sits at gap + d/2.
  out.centre = sessile ? Vec3(0.5 * out.spec.innerMax.x(), s.sessileStartCos * s.radius,
                              0.5 * out.spec.innerMax.z())
                       : Vec3(0.5 * out.spec.innerMax);
  const int nx = static_cast<int>(std::lround(width / d));
  const int ny = static_cast<int>(std::lround(height / d));
  int oilCount = 0;
  for (int k = 0; k < nx; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec3 x = Vec3::Constant(gap) + d * Vec3(i + 0.5, j + 0.5, k + 0.5);
        const Vec3 r = x - out.centre;
        const Real c = r.norm() > 0 ? r.y() / r.norm() : 0;
        const bool isOil = r.norm() < s.radius * (1 + s.p2Amplitude * 0.5 * (3 * c * c - 1));
        const int m = isOil ? out.oil : out.aqueous;
        oilCount += isOil;
        w.particles.add(x, Vec3::Zero(), w.materials[m].restDensity * d * d * d * (1 + s.massExcess),
                        m);
      }
  out.radius = std::cbrt(3.0 * oilCount * d * d * d / (4.0 * std::numbers::pi));
  w.initialize();
  return out;
}

}  // namespace sim::testing
