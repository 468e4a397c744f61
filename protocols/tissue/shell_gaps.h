// Closing the wall shell behind an anchored sclera (docs/methods/elasticity.md "The limbus band,
// watertight"): the cap's rim where the limbus collar starts, the fan over the cap/sclera crease,
// the openings the backstop's samples leave, and the limbus clamp band's face.
#pragma once

#include <vector>

#include "meshing/point_index.h"
#include "meshing/triangle_mesh.h"
#include "protocols/scenario/tissue_body.h"
#include "sim/core/particle_set.h"

namespace protocols {

// A cap wall particle on the rim: within 1.5 d of a sclera particle or kCapRimSpacings d of a wall
// sample over the sclera.
bool onCapRim(const sim::Vec3& x, const meshing::PointIndex& scleraGrid,
              const meshing::PointIndex& coveredGrid, double d);

// Wall particles in the fan from the collar's end to the backstop point (at most d/2 apart).
int fanPieces(const sim::Vec3& collarEnd, const sim::Vec3& backstopPoint, double angle,
              double depth, double d);

// What fillShellGaps and wallClampBand need of the assembly.
struct ShellGapInput {
  const std::vector<sim::Vec3>& covered;    // cavity wall samples over the sclera
  const std::vector<double>& coveredLayer;  // [m] their sampled sclera layer
  const std::vector<int>& coveredTag;
  const std::vector<sim::Vec3>& freeSclera;  // free sclera particles at rest
  const std::vector<sim::Vec3>& fat;         // elastic fat particles (empty: none)
  double d;                                  // [m]
};

// Wall particles (appended to added*) where the shell behind the sclera has openings; returns how
// many.
std::size_t fillShellGaps(const meshing::TriangleMesh& cavityMesh, const ShellGapInput& in,
                          std::vector<sim::Vec3>& added, std::vector<sim::Vec3>& addedNormal,
                          std::vector<int>& addedTag);

// The limbus clamp band's interior: anchored sclera particles beyond the elastic support of every
// free one.
std::vector<char> clampBandInterior(const TissueBody& sclera,
                                    const sim::DynamicParticles& particles,
                                    const std::vector<sim::Vec3>& freeSclera, double d);

// [1] the band is walled within this many spacings of the cavity surface (shell_gaps.cpp: why).
inline constexpr double kBandFaceSpacings = 1.5;

// Wall particles on the band's face; returns how many.
std::size_t wallClampBand(const meshing::TriangleMesh& cavityMesh, const ShellGapInput& in,
                          const std::vector<sim::Vec3>& scleraRest,
                          const std::vector<char>& interior, std::vector<sim::Vec3>& added,
                          std::vector<sim::Vec3>& addedNormal, std::vector<int>& addedTag);

}  // namespace protocols
