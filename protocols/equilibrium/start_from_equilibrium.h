// schedule.start = "equilibrium": a simulated schedule's fluid starts where the first posture's
// static equilibrium puts it, instead of above a flat fill plane, so the run spends its time on
// what is dynamic (the posture changes) rather than on relaxing the fill. A schedule that begins
// with postures at their equilibrium starts its first simulated posture from the last of them
// (docs/methods/equilibrium.md, "Starting a simulation from an equilibrium").
#pragma once

#include <optional>

#include "protocols/format/protocol.h"
#include "protocols/scenario/scenario.h"

namespace protocols {

struct EquilibriumStart {
  bool applied = false;   // false: a fill-plane start, an equilibrium schedule, or one phase
  double seconds = 0.0;   // [s] wall-clock time of the solve and the reassignment
  std::size_t moved = 0;  // oil particles that changed place with an aqueous one
  int iterations = 0;     // of the equilibrium solve
  bool converged = false;
};

// The posture whose equilibrium the simulated fluid starts from: in a mixed schedule the last
// posture at its equilibrium before the first simulated one; with schedule.start = "equilibrium"
// the first posture; none for a fill-plane start, an equilibrium schedule or one phase.
std::optional<std::size_t> startingEquilibrium(const Protocol& protocol, const Scenario& scenario);

// The fluid particles keep their lattice positions, their number per phase, masses and
// materials; what changes is which positions hold oil: the oil particles take the positions with
// the largest oil share of the equilibrium (its voxel field, interpolated trilinearly and
// weighted by each voxel's fluid fraction), ties going to the side the oil floats to. The
// neighbour lists are rebuilt and a note is added to the scenario.
EquilibriumStart startFromEquilibrium(const Protocol& protocol, Scenario& scenario);

// assembleScenario, then startFromEquilibrium: what every command that runs a protocol uses.
Scenario assembleStartingScenario(const Protocol& protocol, const ScenarioOptions& options = {});

}  // namespace protocols
