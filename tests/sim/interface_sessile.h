// The sessile-droplet run of validation 3 (contact angle), shared by the `[contact_angle]` tests
// (interface_contact_angle.cpp) and `sim_interface_bench sessile` (interface_bench.cpp): an oil
// droplet of the volume of a hemisphere of R0 = 3 mm on the floor of a closed aqueous box without
// gravity, the contact angle set on the floor only (kFloorTag), free-slip walls, the angle measured
// by fitting a spherical cap to the interface (sim/measure/sessile_contact_angle.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "interface_fixtures.h"
#include "interface_settle.h"
#include "sim/measure/sessile_contact_angle.h"
#include "sim/measure/sessile_young_laplace.h"

namespace sim::testing {

struct SessileCase {
  Real theta = 90;         // [deg] requested, through the oil
  Real startCos = 0;       // [1] cos of the start angle (through aqueous: centre at startCos R
                           //     above the floor); 0 is the hemisphere
  Real tEnd = 0.05;        // [s] about 2 capillary times sqrt(rho R^3 / sigma) = 26 ms
  Real perR = 6;           // [1] R0 / d
  Real halfWidthPerR = 2;  // [1] least half box width over R0 (sessileScene widens flat caps' box)
  std::string solver = "wcsph";
  int wallLayers = 0;        // [1] 0: one Akinci layer (WCSPH scenes); >= 1 layered walls
  Real viscosity = 0.005;    // [Pa s] both phases
  bool print = false;        // print the angle ten times during the run
  Real jitter = 0;           // [d] DropletSpec::jitter of the start lattice
  int relaxSteps = 0;        // steps with the velocities reset after each, before the run
  Real r0 = 0.003;           // [m] radius of the hemisphere whose volume the droplet has
  Real boxHeightPerR = 1.6;  // [1] least inner box height over R0 (raised to clear the caps by 2 h)
  // Measure the angle from the footprint (the first layer's oil disc, capAngleOfFootprint)
  // instead of the cap fit: above 150 deg the cap fit cannot tell the angle (footprintAngle).
  bool footprint = false;
  int tissueFloorLayers = 0;       // DropletSpec::tissueFloorLayers (an elastic floor)
  int tissueFreeLayers = 0;        // DropletSpec::tissueFreeLayers
  Real tissueYoungsModulus = 5e4;  // [Pa]
  StageOverride backgroundPressure =
      StageOverride::kAuto;  // the background_pressure stage (auto: the rule)
  SurfaceStressForm surfaceStress = SurfaceStressForm::kAuto;  // PipelineOptions::surfaceStress
  // Under gravity (towards the floor) a droplet heavier than the aqueous is pressed onto the
  // floor and is no spherical cap: its outline is then read against the Young-Laplace droplet
  // (sim/measure/sessile_young_laplace.h), with c held (`angle`) and with c free (`shapeAngle`,
  // the reading of validation 3 under gravity); the cap fit is printed for comparison only.
  Real dropletDensity = 970;  // [kg/m^3] the droplet's (the aqueous is 1000)
  Real gravity = 0;           // [m/s^2]
  // [kg/m^3] World::gravityReferenceDensity: gravity relative to this density (the aqueous's
  // 1000 takes the hydrostatic level out of the pressure, as the eye scenes run); 0: plain.
  Real gravityReferenceDensity = 0;
};

// The elastic tissue floor of the [contact_angle] tissue test and of `sim_contact_angle_bench
// --walls tissue`: three lattice layers of 50 kPa tissue on the three-layer wall, the top one free.
inline void useTissueFloor(SessileCase& c) {
  c.wallLayers = 3;
  c.tissueFloorLayers = 3;
  c.tissueFreeLayers = 1;
  c.tissueYoungsModulus = 5e4;
}

struct SessileResult : AngleRunResult {
  bool adhesion = false;  // the pipeline has the wall_adhesion stage
  // At the end, in units of d: how far the lowest fluid particle is below the floor (negative:
  // all above it), and the largest displacement of a tissue particle (tissue floors only).
  Real deepestFluidBelowFloor = 0;
  Real maxTissueDisplacement = 0;
  // Under gravity: the Young-Laplace shape fit with c free (youngLaplaceShapeOfPoints), means
  // over the last fifth of the run: its angle [deg] and nominal c / fitted c [1]. 0 without.
  Real shapeAngle = 0;
  Real shapeSigmaRatio = 0;
  Real shapeFinalAngle = 0;  // [deg] the shape fit at the end
};

// [m] Sphere radius of the cap that has the volume of a hemisphere of radius r0 and cos(theta
// through the oil) = u: cap volume pi R^3 (2 + u)(1 - u)^2 / 3 = 2/3 pi r0^3.
inline Real sessileCapRadius(Real r0, Real u) {
  return r0 * std::cbrt(2.0 / ((2 + u) * (1 - u) * (1 - u)));
}

// [m] Height above the floor of that cap's top, R (1 - u).
inline Real sessileCapTop(Real r0, Real u) { return sessileCapRadius(r0, u) * (1 - u); }

// [m] Radius of that cap's base (its contact radius), R sin(theta).
inline Real sessileCapBase(Real r0, Real u) {
  return sessileCapRadius(r0, u) * std::sqrt(1 - u * u);
}

// The scene of a sessile case before any step: the droplet as the cap of start angle
// acos(-startCos) and the hemisphere's volume, the requested angle set on the floor.
inline DropletScene sessileScene(const SessileCase& c) {
  const Real r0 = c.r0;  // [m]
  DropletSpec s;
  s.spacing = r0 / c.perR;
  const Real h = 2.0 * s.spacing;  // [m] kernel support (World's supportRadiusFactor 2)
  const Real requestedCos = std::cos(c.theta * std::numbers::pi / 180);
  // The side walls clear the contact line of the start cap and of the requested one by 2 h, so
  // that no particle at the contact line reads a neighbour that reads a side wall. In a fixed
  // 2 R0 box the 18 deg cap (base 2.03 R0) met the side walls, which held it: 18 read 18.7 on
  // the layered wall and 34.7 on tissue, where with room both recede alike
  // (docs/methods/interface.md, validation 3). At 2 R0 the 120 deg cap (base 0.73 R0) stays 5 h
  // from them. Rounded up to whole cells: the single-layer box is filled with round(width / d)
  // cells, so a width of 41.6 d (2.6 R0 at R0/8) put the lattice 0.4 d into the side wall (it blew
  // up in 13 steps). The 1e-9 keeps a whole number of cells that round-off lifts above it.
  const Real clear =
      std::max(sessileCapBase(r0, -c.startCos), sessileCapBase(r0, requestedCos)) + 2 * h;
  const Real cells = std::ceil(2 * std::max(c.halfWidthPerR * r0, clear) / s.spacing - 1e-9);
  s.halfWidth = 0.5 * s.spacing * cells;
  // The lid clears the top of both the start cap and the requested angle's cap by 2 h. A droplet
  // whose top comes within the (neutral, 90 deg) lid's support bridges floor and lid and is held
  // there: in the old fixed 1.6 R0 box the 150 deg cap's top (1.49 R0) sat 0.7 d below the lid,
  // and 150 deg requested read 142.6-144.8 deg, 165 deg 151-153, the bridge's angle, not the
  // floor's (docs/methods/interface.md, validation 3).
  s.boxHeight =
      std::max(c.boxHeightPerR * r0,
               std::max(sessileCapTop(r0, -c.startCos), sessileCapTop(r0, requestedCos)) + 2 * h);
  s.sigma = 0.04;
  s.oilDensity = c.dropletDensity;
  s.gravity = Vec3(0, -c.gravity, 0);
  s.oilViscosity = s.aqueousViscosity = c.viscosity;
  s.wallLayers = c.wallLayers;
  s.tissueFloorLayers = c.tissueFloorLayers;
  s.tissueFreeLayers = c.tissueFreeLayers;
  s.tissueYoungsModulus = c.tissueYoungsModulus;
  // WCSPH: 2 % excess mass keeps the Tait clamp at p = 0 from acting. An incompressible solver:
  // rest mass (the closed box is full; an excess could never be removed from it).
  s.massExcess = c.solver == "wcsph" ? 0.02 : 0.0;
  s.sessileStartCos = c.startCos;
  s.jitter = c.jitter;
  // Keep the hemisphere's volume 2/3 pi R0^3 for other starts, u = -startCos (the centre
  // startCos R above the floor).
  s.radius = sessileCapRadius(r0, -c.startCos);
  auto scene = dropletScene(s);
  scene.world->materials.setContactAngle(scene.oil, kFloorTag, c.theta);
  scene.world->gravityReferenceDensity = c.gravityReferenceDensity;
  return scene;
}

// What touches the floor: the oil particles in the first fluid layer (centre below d), the
// radius of their disc about the oil's axis (the largest horizontal distance), and the aqueous
// particles of that layer inside the disc, i.e. a film under the droplet.
struct FloorContact {
  int oil = 0, aqueousUnder = 0;
  Real radius = 0;  // [m]
  Real height = 0;  // [m] mean height of the layer's oil particles above the floor
};

// `floor` [m]: the floor's height (DropletScene::floorHeight).
inline FloorContact floorContact(const World& w, int oil, Real d, Real floor) {
  const auto& p = w.particles;
  Vec3 axis = Vec3::Zero();
  Real oilCount = 0;
  for (Index i = 0; i < p.size(); ++i)
    if (p.material[i] == oil) axis += p.x[i], oilCount += 1;
  axis /= std::max<Real>(oilCount, 1);
  const auto radial = [&](Index i) {
    return std::hypot(p.x[i].x() - axis.x(), p.x[i].z() - axis.z());
  };
  FloorContact c;
  for (Index i = 0; i < p.size(); ++i)
    if (p.material[i] == oil && p.x[i].y() < floor + d) {
      ++c.oil;
      c.radius = std::max(c.radius, radial(i));
      c.height += p.x[i].y() - floor;
    }
  c.height /= std::max(c.oil, 1);
  for (Index i = 0; i < p.size(); ++i)
    if (p.material[i] != oil && p.x[i].y() > floor && p.x[i].y() < floor + d &&
        radial(i) < c.radius - d)
      ++c.aqueousUnder;
  return c;
}

inline SessileResult runSessile(const SessileCase& c) {
  auto scene = sessileScene(c);
  World& w = *scene.world;
  const Real spacing = w.particleSpacing();
  PipelineOptions options;
  options.solver = c.solver;
  options.wcsph.speedOfSound = 2;  // 12 x sqrt(2 sigma / (rho R)): density error < 1 %
  options.wcsph.artificialViscosity = 0.1;
  // Free slip: on a no-slip wall a contact line cannot move at all (Huh & Scriven 1971); the
  // SPH wall friction pinned it (measured: 2 deg in 0.05 s).
  options.wallFriction = false;
  // The box is full (its jittered start would read as a free surface to the automatic rule).
  options.closedDomain = StageOverride::kOn;
  options.surfaceStress = c.surfaceStress;
  if (c.backgroundPressure != StageOverride::kAuto)
    options.forced["background_pressure"] = c.backgroundPressure;
  Pipeline pipeline = assemblePipeline(w, options);
  pipeline.attach(w);
  if (c.print) std::printf("%s", pipeline.describe().c_str());
  SessileResult r;
  r.adhesion = pipeline.hasStage("wall_adhesion");
  const WallPlane floor{Vec3(0, scene.floorHeight, 0), Vec3::UnitY()};
  // Interface points closer than d to the floor are left out: the wall layer distorts them.
  // [1/m^2] delta rho g / sigma of the Young-Laplace droplet (0: the spherical cap).
  const Real capillaryConstant = (c.dropletDensity - w.materials[scene.aqueous].restDensity) *
                                 c.gravity / w.materials.interfacialTensions().front().sigma;
  require(
      capillaryConstant >= 0,
      "sessile droplet under gravity: it must be heavier than the aqueous to stay on the floor");
  const auto sectionAngle = [&](Real volume, Real radius, Real height) {
    return capillaryConstant > 0
               ? youngLaplaceAngleOfFootprint(volume, capillaryConstant, radius, height)
               : capAngleOfFootprint(volume, radius, height);
  };
  const auto footprintAngle = [&](const CapFit& fit, const FloorContact& contact) {
    return contact.oil == 0 ? Real(180) : sectionAngle(fit.volume, contact.radius, contact.height);
  };
  // Under gravity the cap fit's place is taken by the Young-Laplace outline fit, which costs about
  // a second: it is read every 10th step (the mean over the last fifth then has 20+ samples).
  int calls = 0;
  Real lastOutlineAngle = 0;
  const auto outlineAngle = [&](const CapFit& fit) {
    return youngLaplaceAngleOfPoints(fit.points, floor.point, floor.normal, fit.centroid,
                                     fit.volume, capillaryConstant);
  };
  // The shape fit frees c as well (a few tens of outline fits): every 50th measurement.
  const auto shapeFit = [&](const CapFit& fit) {
    return youngLaplaceShapeOfPoints(fit.points, floor.point, floor.normal, fit.centroid,
                                     fit.volume, capillaryConstant);
  };
  std::vector<YoungLaplaceShapeFit> shapeFits;
  const auto measure = [&](const World& world) {
    const CapFit fit = fitSessileCap(world, scene.oil, floor, spacing);
    if (c.footprint)
      return footprintAngle(fit, floorContact(world, scene.oil, spacing, scene.floorHeight));
    if (capillaryConstant > 0) {
      if (calls % 50 == 0) shapeFits.push_back(shapeFit(fit));
      if (calls++ % 10 == 0) lastOutlineAngle = outlineAngle(fit);
      return lastOutlineAngle;
    }
    return fit.contactAngle;
  };
  const auto describe = [&](const World& world) {
    const CapFit fit = fitSessileCap(world, scene.oil, floor, spacing);
    const FloorContact contact = floorContact(world, scene.oil, spacing, scene.floorHeight);
    // The layer's oil as a disc of its area (one particle per d^2): a second footprint reading
    // that does not hang on the outermost particle.
    const Real areaRadius = std::sqrt(contact.oil / std::numbers::pi) * spacing;  // [m]
    char line[480];
    const int used = capillaryConstant > 0
                         ? std::snprintf(line, sizeof line, "Young-Laplace outline fit %.1f deg; ",
                                         outlineAngle(fit))
                         : 0;
    std::snprintf(
        line + used, sizeof line - used,
        "theta = %.1f deg (through oil; centroid %.1f deg; free sphere %.1f deg, R = %.2f mm, "
        "rms %.3f mm)  "
        "floor layer: %d oil, %d aqueous under it, contact radius %.2f d, footprint angle "
        "%.1f deg (by its area %.1f deg)",
        fit.contactAngle, fit.centroidAngle, fit.sphereAngle, fit.sphere.radius * 1e3,
        fit.sphere.rmsResidual * 1e3, contact.oil, contact.aqueousUnder, contact.radius / spacing,
        footprintAngle(fit, contact),
        contact.oil == 0 ? 180.0 : sectionAngle(fit.volume, areaRadius, contact.height));
    std::string out(line);
    if (capillaryConstant > 0) {
      const YoungLaplaceShapeFit shape = shapeFit(fit);
      char more[160];
      std::snprintf(more, sizeof more,
                    "; shape fit (c free) %.1f deg, sigma_eff / sigma %.3f, rms %.3f d",
                    shape.angle, shape.nominalRatio, shape.rmsResidual / spacing);
      out += more;
    }
    return out;
  };
  for (int k = 0; k < c.relaxSteps; ++k) {
    pipeline.step(w);
    for (Vec3& v : w.particles.v) v.setZero();
  }
  std::map<std::int32_t, Vec3> tissueStart;  // [m] by particle id
  for (Index i = 0; i < w.particles.size(); ++i)
    if (w.particles.material[i] == scene.tissue) tissueStart[w.particles.id[i]] = w.particles.x[i];
  static_cast<AngleRunResult&>(r) =
      stepAndMeasureAngle(w, pipeline, c.tEnd, c.print, measure, describe);
  if (capillaryConstant > 0 && !c.footprint)
    r.shapeFinalAngle = shapeFit(fitSessileCap(w, scene.oil, floor, spacing)).angle;
  for (const YoungLaplaceShapeFit& f : shapeFits) {
    r.shapeAngle += f.angle / static_cast<Real>(shapeFits.size());
    r.shapeSigmaRatio += f.nominalRatio / static_cast<Real>(shapeFits.size());
  }
  r.deepestFluidBelowFloor = -std::numeric_limits<Real>::infinity();
  for (Index i = 0; i < w.particles.size(); ++i) {
    if (w.particles.material[i] == scene.tissue) {
      const Real moved = (w.particles.x[i] - tissueStart.at(w.particles.id[i])).norm() / spacing;
      r.maxTissueDisplacement = std::max(r.maxTissueDisplacement, moved);
    } else {
      r.deepestFluidBelowFloor =
          std::max(r.deepestFluidBelowFloor, (scene.floorHeight - w.particles.x[i].y()) / spacing);
    }
  }
  return r;
}

}  // namespace sim::testing
