// assembleScenario: a validated Protocol made into a Scenario the engine can step
// (protocols/scenario/scenario.h says what a Scenario holds and the order of the steps).
#pragma once

#include "protocols/format/protocol.h"
#include "protocols/scenario/scenario.h"

namespace protocols {

// Throws ProtocolError (file:line:column of the value responsible) when the protocol cannot be
// made concrete: an anatomy parameter out of its range, a break off the retina, a solver or a
// forced effect this build does not have, a fill that leaves a phase without particles, an
// outputs.fields name that is not a particle field of the assembled pipeline (with "did you mean").
Scenario assembleScenario(const Protocol& protocol, const ScenarioOptions& options = {});

// Throws ProtocolError at accuracy.min_time_step when the scene's first step (`first`, chosen by
// the assembled pipeline before any step) had to be raised to the minimum: every step would be
// longer than the stages allow, which the engine refuses as unstable once running.
void requireStartTimeStep(const Scenario& scenario, const sim::TimeStepInfo& first);

}  // namespace protocols
