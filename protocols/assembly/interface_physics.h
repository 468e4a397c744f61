// The oil-aqueous interface's physics data in the World: the interfacial tension between the two
// phases and the contact angle on every wall tag, with the notes on how well the wall holds it.
// The stage rules switch interfacial tension and wall adhesion on when both phases are present
// (sim::effectRegistry()).
#pragma once

#include "protocols/scenario/scenario.h"

namespace protocols {

void setInterfacePhysics(Scenario& s);

}  // namespace protocols
