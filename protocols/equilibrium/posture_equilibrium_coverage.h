// The retina coverage at each posture's static equilibrium, the reference a simulated posture is
// held against: in the report's "not steady" headline and in `tamponade bench accuracy`'s
// distance from the equilibrium (docs/accuracy.md).
#pragma once

#include <optional>
#include <vector>

#include "protocols/scenario/scenario.h"

namespace protocols {

// Whether the equilibrium solver has what it needs: a tension, and an angle it can hold. The
// solver refuses the same (sim/equilibrium/threshold_dynamics_xu2017.cpp); asking first saves
// voxelising the cavity for nothing. An absent angle is not taken as 90 deg here: a distance to an
// equilibrium at an angle the protocol never gave would mislead.
bool equilibriumDefined(const Scenario& scenario);

// Per posture of the schedule with `wanted[k]` (all postures when `wanted` is empty): the
// retina's oil-covered share at the posture's equilibrium at `fill`, solved at the accuracy
// preset's voxel (equilibriumVoxelSpacing); none where the equilibrium is not defined or the
// solver cannot compute it. A few seconds per posture.
std::vector<std::optional<double>> equilibriumRetinaCoverage(const Scenario& scenario, double fill,
                                                             const std::vector<bool>& wanted = {});

}  // namespace protocols
