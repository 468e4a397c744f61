// The static equilibrium of one posture in a scenario's cavity (sim/equilibrium/, threshold
// dynamics with wetting), measured as the coverage metrics measure a simulated frame: per retina
// sample, oil-covered or not, read below the voxel scale (sim/equilibrium/wall_oil.h).
// docs/methods/equilibrium.md: the energy, the method, its measured accuracy and cost.
#pragma once

#include <string>

#include "meshing/triangle_mesh.h"
#include "protocols/coverage/wall_oil_fraction.h"
#include "protocols/scenario/scenario.h"
#include "sim/equilibrium/threshold_dynamics_xu2017.h"

namespace protocols {

// Whether every posture of the schedule asks for its equilibrium.
bool isEquilibriumSchedule(const Scenario& scenario);

// How many postures at their equilibrium the schedule begins with (a protocol puts them before
// the simulated ones): 0 for a simulated schedule, all of them for an equilibrium schedule, in
// between for a mixed one, whose first simulated posture starts from the last of them.
std::size_t leadingEquilibria(const Scenario& scenario);

// The postures at equilibrium a mixed schedule begins with, which a run solves before it
// simulates the rest; 0 for a simulated schedule and for an equilibrium schedule (a runner asked
// to simulate one, as `tamponade bench accuracy` does, holds each posture its nominal second).
std::size_t equilibriaBeforeSimulation(const Scenario& scenario);

// Voxel spacing per accuracy preset [m]: 0.3 / 0.25 / 0.2 mm at draft / standard / fine (the
// solver's sqrt(t) is 1.5 voxels). Coarser voxels leave the supine eye's thin aqueous pool
// unresolved (+8 points at 0.5 mm); measured in a 12 mm sphere against Young-Laplace and in the
// emmetropic eye against 0.2 mm: docs/methods/equilibrium.md.
double equilibriumVoxelSpacing(const std::string& preset);

// The cavity as voxel fluid fractions, built once per scenario.
struct CavityVoxels {
  sim::equilibrium::VoxelGrid grid;
  std::vector<double> fluidFraction;
  double wallArea = 0.0;  // [m^2] the cavity mesh's area (calibrates the solver's wall term)
};
CavityVoxels voxelizeCavity(const Scenario& scenario, double voxelSpacing);

struct PostureEquilibrium {
  WallOilFractions wall;  // per retina sample: 1 / kOil where covered, 0 / kAqueous elsewhere
  sim::equilibrium::EquilibriumSolution solution;
  meshing::TriangleMesh interface;  // [m] eye frame
  double seconds = 0.0;             // [s] wall-clock time of the solve and the reading
};

// The equilibrium under `gravity` [m/s^2] (eye frame) at the protocol's fill. A fill of 1 leaves
// no interface: every retina sample is oil-covered and nothing is solved.
PostureEquilibrium solvePostureEquilibrium(const Scenario& scenario, const CavityVoxels& cavity,
                                           double fill, const sim::Vec3& gravity);

}  // namespace protocols
