// The first step of assembly: the scenario's title, its accuracy settings (the protocol's, or a
// preset chosen on the command line) and its posture schedule as gravity vectors in the eye frame.
#pragma once

#include "protocols/scenario/scenario.h"

namespace protocols {

// s.title, s.accuracy (with the note of a spacing coarser than the draft preset), s.schedule.
// Throws ProtocolError for a schedule without postures.
void setUpScenario(const Protocol& protocol, const ScenarioOptions& options, Scenario& s);

}  // namespace protocols
