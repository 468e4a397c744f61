// The fluid of a scenario: lattice points inside the cavity split into the two phases along the
// first posture's fill direction (a lighter tamponade floats) by count, so the tamponade's share
// is the fill fraction (MassRule), with their masses; the gravity reference; and the start of the
// fill (one lattice with a layered wall, or the start-up shifting pass, relax_fill.h).
#pragma once

#include "protocols/scenario/scenario.h"

namespace protocols {

// The fluid particles of both phases in s.world, their counts, volumes and masses, and notes.
void fillFluid(const Protocol& protocol, const ScenarioOptions& options, Scenario& s);

// The hydrostatic background out of the pressure (ScenarioOptions::removeHydrostaticBackground)
// when every tissue is rigid.
void chooseGravityReference(const ScenarioOptions& options, Scenario& s);

// After World::initialize: the start's density measured (layered walls: fluid and wall are one
// lattice) or the start-up shifting pass (kRelaxedFill), with its note.
void startFluidFill(const ScenarioOptions& options, Scenario& s);

}  // namespace protocols
