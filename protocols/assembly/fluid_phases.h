// The two fluid phases of a scenario (aqueous and the tamponade, from the material library with
// the protocol's overrides) and the World they live in, with their materials.
#pragma once

#include <string>

#include "protocols/scenario/scenario.h"

namespace protocols {

FluidPhase phaseFromLibrary(const std::string& name, bool isTamponade);
// The library agent with the protocol's overrides, or the custom agent.
FluidPhase tamponadePhase(const TamponadeSpec& tamponade);

// s.phases ([0] aqueous, [1] tamponade) and s.world: the domain around the cavity with room for
// the tissues, the first posture's gravity, the accuracy's time-step bounds, the phases'
// materials.
void createWorld(const Protocol& protocol, Scenario& s);

}  // namespace protocols
