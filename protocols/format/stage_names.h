// The pressure solvers and effects a protocol may name: the engine's registries
// (sim/world/stage_registry.h) are their only list, so a solver or effect added there is a valid
// `solver` or [effects] key of the protocol format without any change here.
#pragma once

#include <span>
#include <string_view>

namespace protocols {

// Every registered pressure solver, in registry order.
std::span<const std::string_view> solverNames();

// The effects a protocol may force on or off (EffectEntry::forceable), in registry order.
std::span<const std::string_view> effectSwitchNames();

}  // namespace protocols
