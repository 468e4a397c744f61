// The two-phase dam break of the solver comparison (Wang et al. 2023, section 5.1,
// Figures 3, 4 and 7): a heavy column and a light column of the same size stand side by side at
// the back of a tank and are released at once. The heavy fluid collapses under the light one and
// surges along the floor, the light fluid is thrown over it: a violent flow with a moving
// interface at the chosen density ratio. The paper gives the scene only as a figure; the sizes
// here are ours (say so when comparing numbers).
//
// Geometry (up = +y, surge along +x): heavy column x in [0, a], light column x in [a, 2a], both
// 2a high and `depth` deep, in a closed tank 4a long and 3a high. Lattice particles of mass
// rho0 d^3 start 1.2 d from the walls (the engine's wall gap, sim/scenes/dam_break.cpp).
#pragma once

#include <memory>
#include <string>

#include "sim/scenes/box_scene.h"
#include "sim/world/stage_registry.h"

namespace protocols {

struct TwoPhaseDamBreakSpec {
  double columnWidth = 0.04;     // [m] a
  double spacing = 0.005;        // [m] d
  double depth = 0.02;           // [m] fluid extent in z
  double heavyDensity = 1000.0;  // [kg/m^3]
  double densityRatio = 10.0;    // [1] heavy / light (2 means 1:2)
  std::string solver = "indsph";
  double gravity = 9.81;  // [m/s^2] along -y
};

struct TwoPhaseDamBreak {
  TwoPhaseDamBreakSpec spec;
  sim::TankSpec tank;
  std::unique_ptr<sim::World> world;  // initialised; material 0 heavy, 1 light
  sim::PipelineOptions options;       // solver by name; WCSPH speed of sound from the columns
  double potentialEnergy = 0.0;       // [J] sum m g (y - floor) at release: no kinetic energy
                                      // can exceed it (energy conservation with dissipation)
};

// Throws sim::SimError for an unknown solver or sizes that leave a column under 4 particles wide.
TwoPhaseDamBreak buildTwoPhaseDamBreak(const TwoPhaseDamBreakSpec& spec);

}  // namespace protocols
