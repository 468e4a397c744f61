// The dam break of Martin & Moyce (1952, Phil. Trans. R. Soc. A 244:312, Part IV): a water column
// of width a and height n^2 a collapses along a dry horizontal floor; the surge front z(t) is
// compared with the experiment in Z = z/a versus T = n t sqrt(g/a). Used by the validation test
// (tests/sim/test_dam_break.cpp) and by `tamponade bench engine`.
//
// Geometry: the up axis is +y, the surge runs along +x from the back wall at x = 0. The column
// spans the full depth of the tank in z. Two uses:
//  - quasi-2D (validation): a slab a few spacings deep between side walls. Martin & Moyce's
//    column spanned the whole width of their channel, so the flow is two-dimensional; a thin slab
//    reproduces that at a fraction of the particles. The walls are free-slip (no wall friction):
//    at a = 5 cm the boundary layer under the surge is far thinner than one spacing, and a
//    no-slip side wall only one slab-depth away would brake the whole slab, which the wide
//    experimental channel did not do.
//  - 3D (benchmark): the depth equals the width, a column of a x n^2 a x a, the usual SPH
//    dam-break benchmark shape.
#pragma once

#include <memory>
#include <string>

#include "sim/scenes/box_scene.h"
#include "sim/world/stage_registry.h"

namespace sim {

struct DamBreakSpec {
  Real columnWidth = 0.05;     // [m] a, along x (the surge direction)
  Real heightRatio = 2.0;      // [1] n^2: column height = n^2 a (Martin & Moyce used 1 and 2)
  Real depth = 0.0;            // [m] fluid extent in z; 0 = 4 spacings (quasi-2D slab)
  Real spacing = 0.05 / 16;    // [m] particle spacing d
  Real tankLengthRatio = 4.0;  // [1] inner tank length along x in units of a (the front reaches
                               //     Z = 3.2 at T = 2.65 in the experiment)
  std::string solver = "wcsph";
  KernelKind kernel = KernelKind::kCubicSpline;
  Real gravity = 9.81;           // [m/s^2] magnitude, along -y
  bool cachePairKernels = true;  // WorldParameters::cachePairKernels
  // [1] the column's initial density over the rest density (particle mass ratio rho0 d^3).
  // SPlisHSPlasH's regular fluid blocks give each particle the volume 0.8 d^3, so they start at
  // 0.8: a column that first settles by a fifth of its volume (docs/benchmarks.md).
  Real initialDensityRatio = 1.0;
};

struct DamBreakScene {
  DamBreakSpec spec;
  TankSpec tank;
  std::unique_ptr<World> world;
  PipelineOptions options;  // solver by name; WCSPH speed of sound from the column height
  Real backWall = 0.0;      // [m] x of the back wall (Z is measured from here)
  Real timeScale = 0.0;     // [s] t per unit of T: T = t / timeScale = n t sqrt(g/a)
};

// Builds and initialises the scene (walls, column, World::initialize). Throws SimError on bad
// input (non-positive sizes, an unknown solver, a column that does not fit the tank).
DamBreakScene buildDamBreak(const DamBreakSpec& spec);

// Dimensionless surge-front position Z = z/a: the leading edge of the furthest particle that has
// at least `minNeighbors` fluid neighbours (particle centre + d/2, the edge of its lattice cell),
// measured from the back wall. The neighbour threshold ignores single drops thrown ahead of the
// front, which the experiment's front (read from photographs of the continuous sheet) also ignores.
Real surgeFront(const DamBreakScene& scene, Index minNeighbors = 4);

}  // namespace sim
