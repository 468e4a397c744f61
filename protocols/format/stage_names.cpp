#include "protocols/format/stage_names.h"

#include <vector>

#include "sim/world/stage_registry.h"

namespace protocols {

// Views of the registries' names: the registries are built once and never change, so the views
// stay valid.
std::span<const std::string_view> solverNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> all;
    for (const sim::SolverEntry& entry : sim::solverRegistry()) all.push_back(entry.name);
    return all;
  }();
  return names;
}

std::span<const std::string_view> effectSwitchNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> forceable;
    for (const sim::EffectEntry& entry : sim::effectRegistry())
      if (entry.forceable()) forceable.push_back(entry.name);
    return forceable;
  }();
  return names;
}

}  // namespace protocols
