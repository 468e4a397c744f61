// docs/methods/interface.md validation 3: a sessile oil droplet in aqueous (no gravity) settles to
// the requested contact angle, measured by fitting a spherical cap to its interface
// (interface_sessile.h); a heavy droplet under gravity, measured by fitting its Young-Laplace
// shape.
#include <catch2/catch.hpp>

#include <cstdio>

#include "interface_ridge.h"
#include "interface_sessile.h"

using namespace sim;

namespace {

// The scene the angle is reached in (docs/methods/interface.md, validation 3): INDSPH with three
// layers of lattice wall particles (the fluid at rest density up to d/2 from the floor, no wall
// over-density layer), and a start lattice jittered by up to 0.2 d: on the exact lattice, which the
// layered wall continues, the first fluid layer sits in the wall lattice's hollows and the contact
// line locks (measured from the hemisphere: 120 deg requested stalled at 110 deg, 150 at 128 deg).
// 0.1 s is four capillary times sqrt(rho R^3 / sigma) = 26 ms.
testing::SessileCase layeredCase(Real theta, Real tEnd) {
  testing::SessileCase c;
  c.theta = theta;
  c.solver = "indsph";
  c.wallLayers = 3;
  c.jitter = 0.2;
  c.tEnd = tEnd;
  return c;
}

testing::SessileResult settle(Real theta, Real tEnd = 0.1, Real perR = 6) {
  testing::SessileCase c = layeredCase(theta, tEnd);
  c.perR = perR;
  return testing::runSessile(c);
}

// +-5 deg: the acceptance for 30-150 deg. The cap fit (the cap of the droplet's volume,
// sim/measure/sessile_contact_angle.h) reads static lattice caps of 30-150 deg within 1.3 deg
// (interface_units.cpp) and the start hemisphere at 89.8 deg; the 90 deg run (no wall force at
// all) settles at 86.3 deg, the bias of the tension's wall treatment (R = 6 d; 85.8 at R = 8 d).
// Measured (window mean over the last fifth) with the corrected surface stress (INDSPH's
// automatic choice): 59.7 deg for 60, 120.2 deg for 120 (0.1 s); 33.4 deg for 30 (0.3 s). Since
// the wall stress sits on the larger phase (the aqueous) 120 reads 123.7 (118.4 over
// 0.3 s); 30 and 60 are unchanged (the aqueous carried it before too). Since background_pressure
// leaves contact-line particles unshifted: 32.9 / 60.0 / 123.1 for 30 / 60 / 120; 30 at R0 = 8 d
// with the side walls clear of its contact line: 32.6 (see its test).
void checkSessileAngle(Real requested, Real tEnd = 0.1, Real perR = 6) {
  const testing::SessileResult r = settle(requested, tEnd, perR);
  std::printf(
      "sessile %.0f deg requested: %.1f deg measured (%.1f at the end), %ld steps, %.1f s\n",
      requested, r.angle, r.finalAngle, r.steps, r.seconds);
  REQUIRE(r.adhesion);
  REQUIRE(r.finite);
  CHECK(r.angle == Approx(requested).margin(5.0));
}

}  // namespace

TEST_CASE("Sessile droplet spreads to a 60 deg contact angle (through oil)",
          "[validation][interface][contact_angle]") {
  checkSessileAngle(60.0);
}

TEST_CASE("Sessile droplet retracts to a 120 deg contact angle (through oil)",
          "[validation][interface][contact_angle]") {
  checkSessileAngle(120.0);
}

// 90 deg: no wall stress acts (gamma_wB - gamma_wA = sigma cos 90 = 0), so what this checks is
// the bias of the tension's own wall treatment. 0.3 s, as for 30 deg: the droplet's equilibrium is
// about 4 deg flatter than asked, reached from both sides (`sim_interface_bench
// sessile 90 T START indsph 3 6 0.005 0.2`): from the hemisphere 86.3 (window over 0.24-0.3 s),
// from the 80 deg cap 85.9 and from the 100 deg cap 86.5 (0.5 s). The oil's centroid height, a
// measure without interface points, gives the same angle within 1 deg (87.3). It is not the
// measurement, the surface-stress form (symmetric 85.9), the pressure solver (WCSPH 85.2), the
// density difference (oil at 1000 kg/m^3: 85.5), XSPH (off: 86.2) or the particle shift next to
// walls (off within the wall's reach: 86.1); unshifted interface particles read 88.9, but that
// shift is what keeps the tension from clumping (validation 1b). docs/methods/interface.md,
// validation 3.
TEST_CASE("Sessile droplet holds a 90 deg contact angle (through oil)",
          "[validation][interface][contact_angle]") {
  checkSessileAngle(90.0, 0.3);
}

// 30 deg from the hemisphere: the contact line travels 60 deg and the flat cap overlaps the
// wall's wetted layer over its whole base, the hardest case of the 30-150 band. 0.3 s (12
// capillary times). R0 = 8 d, where the cap is 3.6 d tall: with the side walls 2 h clear of the
// contact line (the fixture's rule) it reads 32.6 (32.6 at the end; 33.5 in a
// box one cell narrower, coming down 0.3 deg per 0.03 s). At R0 = 6 d, 2.7 d tall, it reads 35.3,
// outside by 0.3 deg. In a 2 R0 box at R0 = 6 d, whose side walls
// stood 1.8 d from the 30 deg cap's contact line and held it at 32.9 (docs/methods/interface.md,
// validation 3). With the symmetric (neutral-wall) surface stress the cap retracted
// to 34.9 deg in 0.3 s, and the hemisphere spread only to 39.2 deg in 0.1 s (before the
// background pressure, in that box): the one-sided colour gradient at the wall is what brings 30
// deg within 5 deg.
// Tagged [long] (about 6 min on an idle core): `bash tools/test.sh -L long` runs it; the default
// suite keeps 60, 90 and 120 deg here and the library oils' 162 deg in the cavity
// (interface_cavity.cpp).
TEST_CASE("Sessile droplet spreads to a 30 deg contact angle (through oil)",
          "[validation][long][interface][contact_angle]") {
  checkSessileAngle(30.0, 0.3, 8);
}

// On an elastic tissue floor (the retina over an elastic sclera): three lattice layers of tissue
// (E = 50 kPa, 1000 kg/m^3) on the layered wall, the top layer free and the floor tag's wetted
// surface, the two below anchored. The angle must be the one asked: the elastocapillary length
// sigma / E = 0.8 um is 1/600 of d, so the substrate barely deforms and Young's relation holds as
// on a rigid wall. With elastic material in the scene the background_pressure stage is off (its
// shift pushed fluid through sampled tissue, docs/methods/interface.md validation 1b), so the
// reference is the layered wall without it: 120.9 deg (60 deg: 57.8). Measured on tissue (R0/6, 0.3
// s, window mean): 120.8 (60 deg: 60.7) with the tissue out of wall_adhesion's pair sum, as the
// walls are; 121.4 (60 deg: 62.0) with it in; all layers anchored 118.8. Without wall_adhesion and
// the tension's wall mirror on tissue, the same droplet settles at 83-85 deg (`sim_interface_bench
// sessile 120 0.3 0 indsph 3 6 0.005 0.2 tissue=3 free=1`). 0.3 s: the angle overshoots to 128 at
// 0.06 s and settles from 0.15 s on, so a 0.1 s window would read a transient. Also: no fluid
// particle gets below the tissue's top, and the tissue moves less than 0.1 d, the decision rule's
// bound for a tissue that barely moves (sim/solid/tissue_deformation.h), so the comparison with a
// rigid wall holds. Measured 0.049 d at 0.3 s (0.025 d at 0.05 s), in a ring under the contact
// line, tangential and up; at E = 500 kPa none above 0.02 d, so it is the layer's elastic answer to
// the loads at the contact line, not a drift.
TEST_CASE(
    "Sessile droplet on an elastic tissue floor retracts to a 120 deg contact angle (through oil)",
    "[validation][interface][contact_angle][elasticity]") {
  testing::SessileCase c = layeredCase(120, 0.3);
  testing::useTissueFloor(c);
  const testing::SessileResult r = testing::runSessile(c);
  std::printf(
      "sessile 120 deg on tissue: %.1f deg measured (%.1f at the end), %ld steps, %.1f s; "
      "deepest fluid %.2f d below the tissue's top, largest tissue displacement %.3f d\n",
      r.angle, r.finalAngle, r.steps, r.seconds, r.deepestFluidBelowFloor, r.maxTissueDisplacement);
  REQUIRE(r.adhesion);
  REQUIRE(r.finite);
  CHECK(r.angle == Approx(120.0).margin(5.0));
  // The fluid's first layer sits d/2 above the tissue's top; a particle below the top has passed
  // between tissue particles.
  CHECK(r.deepestFluidBelowFloor <= 0.0);
  CHECK(r.maxTissueDisplacement < 0.1);
}

// 150 deg on a sessile ridge: a cylindrical droplet (R0 = 12 d, 16 d long between neutral end
// walls, interface_ridge.h), whose straight contact lines are 8.6 d apart however steep the
// angle. Started as the 150 deg segment it settles at 148.3-149.2 deg from 0.42 s on (window
// 148.5, `sim_interface_bench ridge 150 0.6 150 12 0.005 16`, 10k particles, 304 s on one
// thread; 148.4 with contact-line particles unshifted by background_pressure); started as the
// 135 deg segment it stays at 145.0-145.8 from 0.24 s on, the band's edge. So the balance lies
// in 145-149, with about 4 deg of hysteresis. With the wall stress on the oil, the other rule
// (WallLayerPhase::kNonWetting), the same run reads 143.7 (143.5 at the end) and
// fails the check.
TEST_CASE("Sessile ridge holds a 150 deg contact angle (through oil)",
          "[validation][interface][contact_angle]") {
  testing::RidgeCase c;
  c.theta = 150;
  c.startTheta = 150;
  c.r0PerD = 12;
  c.viscosity = 0.005;
  c.depthPerD = 16;
  c.tEnd = 0.6;
  const testing::RidgeResult r = testing::runRidge(c);
  std::printf("ridge 150 deg requested: %.1f deg measured (%.1f at the end), %ld steps, %.1f s\n",
              r.angle, r.finalAngle, r.steps, r.seconds);
  REQUIRE(r.finite);
  CHECK(r.angle == Approx(150.0).margin(5.0));
}

// 150 deg (and the +-10 deg band outside 30-150) are benchmark runs (docs/methods/interface.md,
// validation 3). 150 deg is not met on a round droplet.
// - Round droplet (`sim_interface_bench sessile 150 T START indsph 3 R_PER_D MU 0.2 0 1.5`):
//   with the wall stress on the larger phase both starts meet at 144-145 deg at R/8
//   once the contact line is mobile (mu 0.005 Pa s: 145.0 from its own cap over 0.96-1.2 s,
//   144.1 from the hemisphere at 1.28 s, after a plateau at 148 from 0.16 to 0.64 s).
//   With mu 0.05 the line is slower (capillary speed sigma / mu: 141.7 from the hemisphere at 1 s).
//   R/12 meets at 143-144 from both starts (mu 0.005, 0.6 s); at R/6 it climbs past 155. With
//   the stress on the oil it receded off the floor at R/6-R/16. A 0.4 s run would
//   pass on the 148 plateau, a transient, so none is written.
// - Sessile ridge, a cylindrical droplet with straight contact lines (`sim_interface_bench ridge
//   150 T START R0_PER_D`, interface_ridge.h), with the wall stress on the oil: with R0 = 12 d it
//   settled at 141.9-143.8 deg, from below and from above; R0 = 18 and 24 d still descending at
//   145.
// 165 deg: the round droplet's footprint (capAngleOfFootprint; the cap fit cannot resolve
// 165 from 180) shrinks until it leaves the floor at R/12, and at R/8 with mu 0.005 (before
// 0.08 s). With mu 0.05 it held 168-173 at R/8 for 1.2 s: the viscosity slowing the recession,
// not an equilibrium, so no test is written on it. On the R0 = 24 d ridge (wall stress on
// the oil) it held 163.6 from its own segment but stayed pinned at 150.7 from
// the 150 deg segment (29k particles, 342 s per 0.2 s). Not asserted, since a failing check would
// only restate the open item. (A round droplet touching the
// 1.6 R0 lid reads 142.6-144.8; the fixture clears it.) 15 deg (d = R/8, 3-4 min a run) holds 16.6
// from its own cap and 23.6 from the 25 deg cap.

// 150 deg on a round droplet pressed onto the floor by gravity, read as drop shape analysis reads
// a real one: the Young-Laplace outline of the droplet's volume fitted with the angle and the
// capillary constant c = delta rho g / sigma both free (youngLaplaceShapeOfPoints). Without
// gravity a round 150 deg droplet's footprint (1.6 d radius at R0 = 8 d) is smaller than the
// kernel's support; a droplet of perfluoro-n-octane's 1760 kg/m^3 in water (Bond 1.7) sits on a
// footprint 6.5 d wide. R0 = 8 d, from the hemisphere, 0.3 s: 151.9 deg (152.3 at the end; 826
// steps, 152 s on one thread), and the fit's sigma_eff / sigma 0.820: the simulated droplet is
// flatter than the nominal balance of weight and tension makes it, by the same factor at 135
// and 165 deg (docs/methods/interface.md validation 3; an open error of its own). With c held
// at its nominal value the same droplet reads 138.8 deg and fails the band; at R0 = 16 d the shape
// fit reads 149.6 (135: 134.3, 165: 162.4; benchmark runs). +-5 deg: the band, which the
// fit itself meets on static droplets of known angle and tension within 2 deg
// (test_sessile_young_laplace.cpp).
TEST_CASE("Sessile droplet under gravity reads 150 deg by its Young-Laplace shape (through oil)",
          "[validation][interface][contact_angle]") {
  testing::SessileCase c = layeredCase(150, 0.3);
  c.perR = 8;
  c.halfWidthPerR = 1.5;
  c.dropletDensity = 1760;
  c.gravity = 9.81;
  const testing::SessileResult r = testing::runSessile(c);
  std::printf(
      "sessile 150 deg under gravity: shape fit %.1f deg (%.1f at the end), sigma_eff / sigma "
      "%.3f; with c held %.1f deg; %ld steps, %.1f s\n",
      r.shapeAngle, r.shapeFinalAngle, r.shapeSigmaRatio, r.angle, r.steps, r.seconds);
  REQUIRE(r.adhesion);
  REQUIRE(r.finite);
  CHECK(r.shapeAngle == Approx(150.0).margin(5.0));
  // The droplet stays pressed onto the floor: none of the fluid gets into the wall.
  CHECK(r.deepestFluidBelowFloor <= 0.0);
}
