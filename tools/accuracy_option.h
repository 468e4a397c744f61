// The `--accuracy NAME` option of `tamponade plan` and `tamponade run`, defined in one place so
// both commands accept the same names and print the same message for a wrong one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "protocols/format/protocol.h"
#include "tools/cli.h"
#include "tools/cli_values.h"

namespace tools {

// Adds --accuracy to `app`; the preset's name lands in `name`.
inline CLI::Option* addAccuracyOption(CLI::App& app, std::string& name) {
  const std::vector<std::string> names(protocols::kAccuracyPresetNames.begin(),
                                       protocols::kAccuracyPresetNames.end());
  return app.add_option("--accuracy", name, "accuracy preset instead of the protocol's own")
      ->type_name("NAME")
      ->check(oneOf(names));
}

// The preset named by --accuracy, nullopt when the option was not given.
inline std::optional<protocols::AccuracyPreset> accuracyPreset(const std::string& name) {
  if (name.empty()) return std::nullopt;
  return protocols::accuracyPresetFromName(name);
}

}  // namespace tools
