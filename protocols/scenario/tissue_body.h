// The tissues of a scenario as data: each TissueBody (the sclera, the orbital fat) with its
// elastic-or-rigid decision and, when elastic, its particles; the retina samples the coverage is
// measured at, which follow an elastic sclera; and the constants of the tissue assembly
// (protocols/tissue/add_tissues.h explains the assembly).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/core/types.h"
#include "sim/solid/tissue_deformation.h"

namespace protocols {

// [1] thinnest sampled tissue layer in particle spacings: d/2 gap + two lattice layers.
inline constexpr double kMinTissueLayerSpacings = 2.5;
// [1] gap between an anchored sclera layer's outer surface (t_layer from the cavity) and the rigid
// backstop wall placed behind it (the orbit), in particle spacings. The outer, anchored lattice
// layer lies at depths (t_layer - d, t_layer], every free particle at most t_layer - d deep, so one
// spacing puts the wall 1-2 d from the anchored layer (inside its kernel support, as the cavity
// wall is for the fluid) and at least 2 d from every free particle (outside theirs: the wall can
// push no free particle). Two spacings left the anchored layer with no neighbour
// behind it: its number density deficient (mean 0.81 rest), INDSPH's pressure clamped at 0 there
// while the fluid next to the face read ~50 Pa, so the pressure solve drove fluid through the
// layer into the gap (10 kPa: 3 / 8 / 42 particles in the tissue at 0.1 / 0.3 / 0.6 s). Half a
// spacing (the wall within 1.5 d of the free layer) failed the 2 MPa sclera test: 207 um, bound
// 4.1 um. docs/methods/elasticity.md "Closing the gaps behind the sclera".
inline constexpr double kBackstopGapSpacings = 1.0;
// [1] the limbus clamp (docs/methods/elasticity.md "The limbus clamp and the bony orbit"): the
// sclera's anterior edge joins the cornea, here the rigid lens/IOL cap. Every sclera particle
// within this many spacings of a cap wall particle, or of the rigid collar that closes the seam
// from the cap's edge out to the backstop, is anchored, so the collar cannot push the free rim (it
// did, 0.14-0.3 mm, when those particles were free). Measured on the 2 MPa sclera test (10 ms):
// with 2 d (the kernel's support) two free particles 2.2-2.5 d from the collar moved 2.3 and 4.6 um
// (bound 4.1 um, elsewhere 0.1 um); with 3 d the largest displacement is 0.10 um, as without collar
// and clamp.
inline constexpr double kLimbusClampSpacings = 3.0;
// [1] the cap's rim (where the collar starts) reaches this far from the wall samples over the
// sclera: the cap and the sclera's wall samples are both at d/2, so a cap sample next to the
// boundary has one within ~d/2-d; one spacing takes the first row or two of the cap.
inline constexpr double kCapRimSpacings = 1.0;
// [1] the bony orbit around the elastic orbital fat: rigid wall particles (spacing d/2) at
// distances [kOrbitGapSpacings, kOrbitGapSpacings + 1) d from the nearest fat particle, outside
// the sclera's backstop shell, so the tissue assembly is enclosed by walls and fluid that gets
// through the tissue stays in the scene. Two spacings: no wall particle within the kernel's
// support of a fat particle (the sclera backstop's rule).
inline constexpr double kOrbitGapSpacings = 2.0;

struct TissueBody {
  std::string name;                    // "sclera" or "orbital fat"
  std::string material;                // material library name
  double youngsModulus = 0.0;          // [Pa] the tissue's (library, or the protocol's override)
  double poissonRatio = 0.0;           // [1]
  double density = 0.0;                // [kg/m^3]
  double thickness = 0.0;              // [m] used in the estimate
  double loadPressure = 0.0;           // [Pa] used in the estimate
  double estimatedDisplacement = 0.0;  // [m]
  sim::TissueDecision decision;
  // Elastic only.
  double layerThickness = 0.0;  // [m] mean sampled layer (>= kMinTissueLayerSpacings d)
  // [rad/s] first thickness mode of the layer, fixed on one face: pi c_p / (2 t_layer) with
  // c_p the P-wave speed of the simulated modulus. The elastic stage runs before the pressure
  // solve, so a layer loaded by the fluid answers as if softened by 1 + (omega_1 dt)^2.
  double thicknessModeFrequency = 0.0;
  double simulatedModulus = 0.0;  // [Pa] E (t / t_layer when thickened)
  int materialIndex = -1;         // in world.materials
  std::int32_t firstId = 0;       // particle ids firstId .. firstId + count - 1
  std::size_t count = 0;
  std::size_t anchored = 0;
  std::size_t limbusClamped = 0;  // sclera: of `anchored`, those anchored by the limbus clamp
  std::vector<sim::Vec3> restPositions;  // [m] by id - firstId
  std::string describe() const;          // one line for `tamponade plan` and notes
};

// The retina samples the coverage is measured at (RetinaMap order), #W.
struct RetinaSamples {
  std::vector<sim::Vec3> restPositions;  // [m]
  std::vector<sim::Vec3> normals;        // [1] outward (into the wall)
  std::vector<std::int32_t> followsId;   // tissue particle id the sample moves with, -1 = fixed
  // [m] sampled elastic sclera layer behind each sample (0: rigid wall or the lens/IOL cap); empty
  // when the sclera is not sampled. The leak counter (TissueMeasures) reads it.
  std::vector<double> scleraLayer;
  bool moves() const;
};

}  // namespace protocols
