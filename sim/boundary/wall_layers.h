// Layered static walls: a wall sampled as several layers of particles behind its surface, each
// with a known volume, so that a fluid particle near the wall sees a full kernel support of
// particles (the number density of a fluid at rest next to a flat wall is then the bulk value,
// unlike a single Akinci 2012 surface layer, which over-estimates it by ~55 % at d/2 from a face;
// docs/methods/solvers.md "Layered walls"). Such walls are the static particles of Wang et al.
// 2023, section 4.3: INDSPH solves for their own stiffness kappa_b (eq. 21).
//
// Which layer a wall particle belongs to is kept in the wall field "wall_layer" (0 = the surface
// layer, d/2 behind the wall surface; 1 = the next one, ...). The field exists only when a scene
// added layered walls (DESIGN principle 1): its presence is how solvers know the walls are layered.
// Coverage, contact-angle and report code must use the surface layer only (isSurfaceWall).
#pragma once

#include <cstdint>
#include <vector>

#include "sim/core/particle_set.h"

namespace sim {

inline constexpr const char* kWallLayerField = "wall_layer";

// How many layers a wall gets. For the cubic spline with support h = 2d, two layers (at d/2 and
// 3d/2 behind the surface) fill the support of a fluid particle at d/2 in front of it; the third
// (5d/2) fills the support of the surface layer itself, so that a wall particle's rest number
// density is reached only when fluid sits in front of it and intruding fluid compresses it.
struct WallLayers {
  int count = 3;  // [1] >= 1
};

// True when the walls were sampled as layers (the "wall_layer" field exists).
bool hasLayeredWalls(const WallParticles& walls);
// The layer index of every wall particle (adds the field, all zeros, if absent).
std::vector<std::int32_t>& wallLayerField(WallParticles& walls);
// True for a surface-layer wall particle (always true for single-layer Akinci walls).
bool isSurfaceWall(const WallParticles& walls, std::size_t b);

// Adds one layered wall particle: position [m], outward normal (into the wall), caller tag,
// volume [m^3] (> 0: the scene knows it), layer index (0 = surface).
void addLayeredWallParticle(WallParticles& walls, const Vec3& position, const Vec3& outwardNormal,
                            int tag, Real volume, int layer);

// Adds layers behind a sampled surface (e.g. the Poisson-disk samples of a cavity mesh): sample s
// at `points[s]` with outward unit normal `normals[s]` (pointing into the wall material) and area
// `areas[s]` [m^2] gets `layers.count` particles at depths (k + 1/2) d, k = 0, 1, ..., along its
// normal, each of volume areas[s] d (1 + kappa_s (k + 1/2) d)^2 with kappa_s = `curvature[s]`
// [1/m] the surface's curvature there, positive when the wall curves around the fluid (a sphere
// of radius R seen from inside: kappa_s = 1/R, the offset surface is larger); empty = flat.
// Tags are copied from `tags` (empty: 0). Returns the number of particles added.
std::size_t addWallLayersBehindSurface(WallParticles& walls, const std::vector<Vec3>& points,
                                       const std::vector<Vec3>& normals,
                                       const std::vector<Real>& areas,
                                       const std::vector<Real>& curvature,
                                       const std::vector<int>& tags, Real spacing,
                                       const WallLayers& layers);

}  // namespace sim
