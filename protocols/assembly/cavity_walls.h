// The cavity wall of a scenario: the retina samples (Poisson-disk points of the mesh with their
// regions and areas, where the coverage is measured), the breaks on them, the one-layer wall on
// the samples, and its replacement by three lattice layers (accuracy.wall_model,
// layered_cavity_walls.h).
#pragma once

#include "meshing/sample_surface.h"
#include "protocols/scenario/scenario.h"

namespace protocols {

// Retina samples at `spacing`, breaks, and the one-layer wall on the samples (s.world->walls).
meshing::SurfaceSamples buildWalls(const Protocol& protocol, Scenario& s, double spacing);

// Whether the wall is layered: "auto" takes it unless an elastic tissue replaced part of the
// one-layer wall or the fill is a comparison mass rule.
bool chooseLayeredWalls(const Protocol& protocol, const ScenarioOptions& options, Scenario& s);

// The one-layer wall replaced by three lattice layers, each particle tagged with its nearest
// retina sample's regions (the wall stages key the contact angle by tag).
void replaceWithLayeredWalls(Scenario& s, double spacing);

}  // namespace protocols
