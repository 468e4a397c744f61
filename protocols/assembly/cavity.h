// The cavity of a scenario: a parametric eye from anatomy (emmetropic, myopic, staphyloma) or an
// imported mesh in the protocol's units, its volume and area, and the memory check that refuses a
// spacing beyond the machine before any particle is allocated.
#pragma once

#include "protocols/scenario/scenario.h"

namespace protocols {

// Sets s.cavity, s.eye (parametric kinds), s.cavityVolume, s.cavityArea.
void buildCavity(const Protocol& protocol, Scenario& s);

// Sets s.memory; refuses (ProtocolError at the spacing) a scene over options.memoryLimit, naming
// the finest spacing that fits.
void checkMemory(const Protocol& protocol, const ScenarioOptions& options, Scenario& s,
                 double spacing);

}  // namespace protocols
