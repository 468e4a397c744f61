// Static equilibrium of two immiscible fluids in a closed cavity: the oil region of given volume
// that minimises
//
//   E = sigma A_interface + sigma cos(theta) A_wall,oil - (rho_oil - rho_aq) g . int_oil x dV
//
// (Young: gamma_oil,wall - gamma_aq,wall = sigma cos(theta), theta measured THROUGH THE AQUEOUS,
// docs/conventions.md; the last term is the oil's potential energy relative to the aqueous it
// displaces). Method: threshold dynamics with wetting (Xu, Wang & Wang 2017, J. Comput. Phys.
// 330:510, "An efficient threshold dynamics method for wetting on rough surfaces"), on a voxel
// grid holding the cavity as fluid volume fractions f. With chi_oil = u f, chi_aq = (1 - u) f,
// chi_wall = 1 - f and the heat kernel G_t, the areas are approximated by
//
//   A(i, j) ~ sqrt(pi / t) int chi_i G_t * chi_j dV   (Miranda et al. 2007; exact for a plane),
//
// and each iteration minimises the energy linearised about the current u (it is concave in u, so
// the energy never rises; Esedoglu & Otto 2015): the oil takes the voxels with the smallest
//
//   psi = sqrt(pi / t) sigma [G*f - 2 G*(u f)] + sqrt(pi / t_w) sigma cos(theta) (1 - G_w*f)
//         - (rho_oil - rho_aq) g . x
//
// (the wall term with a kernel of its own, t_w = r^2 t: wallKernelRatio below) until it holds its
// volume (a weighted quantile, so the volume is exact). t is lowered from a
// coarse start to its final value; at each t the iteration stops when no voxel changes. From a
// wetting angle of 40 deg the final stage thresholds to fractions of a voxel (volume_threshold.h).
// The method, its accuracy against Young-Laplace and its cost: docs/methods/equilibrium.md.
#pragma once

#include <limits>
#include <vector>

#include "sim/equilibrium/voxel_grid.h"

namespace sim::equilibrium {

struct EquilibriumProblem {
  VoxelGrid grid;
  std::vector<double> fluidFraction;  // [1] per voxel, 1 inside the cavity, 0 in the wall
  double oilDensity = 0.0;            // [kg/m^3]
  double aqueousDensity = 0.0;        // [kg/m^3]
  double tension = 0.0;               // [N/m] oil-aqueous interfacial tension sigma
  double contactAngle = 0.0;          // [rad] on the wall, through the aqueous, in (0, pi)
  Vec3 gravity = Vec3::Zero();        // [m/s^2] in the cavity's frame
  double oilFraction = 0.0;           // [1] of the cavity's volume, in (0, 1)
  // [m^2] the true area of the cavity's wall (0: unknown). When given, the wall term is scaled
  // so that the discrete wall area sqrt(pi / t) int f G*(1 - f) dV equals it: the voxels the
  // wall cuts hold wall and fluid at one point, which overstates that area by 3-6 % at the final
  // kernel and makes cos(theta) act as much too strong (docs/methods/equilibrium.md).
  double wallArea = 0.0;
};

enum class FinalThreshold {
  kByAngle,      // fractional from a wetting angle of 40 deg on, whole voxels below
  kWholeVoxels,  // whole voxels at every angle
  kFractional,   // fractions of a voxel at every angle
};

struct ThresholdDynamicsOptions {
  // [voxels] sqrt(t) / h at the end. The areas' error grows with sqrt(t) (a line energy at the
  // contact line), the pinning to the voxels with h / sqrt(t); docs/methods/equilibrium.md
  // measures the choice.
  double finalSmoothing = 1.5;
  double startSmoothing = 6.0;  // [voxels] sqrt(t) / h of the first stage; halved per stage
  int maxIterationsPerStage = 200;
  // How the final stage thresholds: to whole voxels, or to fractions of a voxel, u ramping from 1
  // to 0 over `fractionalWidth` voxels of a planar interface's psi (volume_threshold.h), so that
  // the contact line can move by less than a voxel (whole voxels pin it below a kernel of about
  // 3 voxels). By default the angle decides (fractionalFinalStage).
  FinalThreshold finalThreshold = FinalThreshold::kByAngle;
  double fractionalWidth = 1.0;  // [voxels]
  // The fractional stage ends when no voxel's u changes by more than this in an iteration.
  double fractionalTolerance = 1e-3;
  int maxFractionalIterations = 1500;
  // sqrt(t_wall / t): the wall term's kernel width over the interface's. 0 picks
  // wallKernelRatio(theta, fractional); 1 is Xu, Wang & Wang 2017's single kernel.
  double wallKernelRatio = 0.0;
};

// [1] The wall term's kernel width over the interface term's, per contact angle and final
// threshold. With one kernel for both (ratio 1) the aqueous at 18 deg spreads along the wall: at a
// point of the contact line the threshold keeps the oil only while the oil's wedge there exceeds
// pi (1 + cos theta) / 2, so the line's local angle falls to pi (1 - cos theta) / 2 (4.4 deg for
// 18 deg) and a film of the wetting phase runs ahead. A wider wall kernel raises that local angle;
// the ratio that makes it Young's, cos theta / (1 - 2 theta / pi) (1.19 at 18 deg), overshoots,
// because the kernel's line energy at the wall remains (Wang, Wang & Xu 2019, J. Comput. Phys.
// 392:291, choose a kernel per interface pair to the same end). The ratio is therefore calibrated
// against the axisymmetric Young-Laplace equilibrium of a 12 mm sphere at Bond 1.2, for each
// final threshold: with whole voxels 1.025 at 18 deg, 1.20 at 40 deg; with fractions 0.97 and
// 1.11; Young's pi / 2 at 90 deg; symmetric about 90 deg (docs/methods/equilibrium.md, "The wall
// kernel" and "Fractional thresholding", which also give the checks it was not calibrated on).
double wallKernelRatio(double contactAngle, bool fractional);

// Whether the final stage thresholds to fractions of a voxel under FinalThreshold::kByAngle: from
// a wetting angle (the smaller of theta and 180 deg - theta) of 40 deg on. There it reads pools of
// every depth within 0.5 points at the draft voxel, and the lens without gravity too; below, it
// reads thin pools up to 2.4 points low where whole voxels stay within 1
// (docs/methods/equilibrium.md, "Fractional thresholding").
bool fractionalFinalStage(double contactAngle);

struct EquilibriumSolution {
  VoxelGrid grid;
  std::vector<double> fluidFraction;  // [1] as given
  std::vector<double> oil;            // [1] u: the oil's share of each voxel's fluid
  double heatKernelTime = 0.0;        // [m^2] final t
  double energy = 0.0;                // [J] the approximate energy E_t at the end (+ a constant)
  int iterations = 0;                 // over all stages
  int stages = 0;
  bool converged = false;  // the last stage ended with no voxel changing
  double oilVolume = 0.0;  // [m^3] sum u f h^3
  // [m] sqrt(sigma / |(rho_oil - rho_aq) g|), the length over which the interface turns from its
  // far shape to the contact angle next to a wall (infinite without gravity or buoyancy); the
  // wall reader uses it (wall_oil.h).
  double capillaryLength = std::numeric_limits<double>::infinity();
  double cavityVolume = 0.0;  // [m^3] sum f h^3
};

// Throws SimError on a problem outside the method's range (no fluid, fill not in (0, 1), theta
// not in (0, pi), a tension <= 0, sizes that disagree).
EquilibriumSolution solveEquilibrium(const EquilibriumProblem& problem,
                                     const ThresholdDynamicsOptions& options = {});

}  // namespace sim::equilibrium
