// The `--accuracy NAME` option of `tamponade plan` and `tamponade run`, parsed in one place so both
// commands accept the same names and print the same message for a wrong one.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

#include "protocols/format/protocol.h"

namespace tools {

// The preset named `value`, or nullopt after telling the user (on stderr, naming `command`)
// which names exist; the caller then exits 2.
inline std::optional<protocols::AccuracyPreset> parseAccuracyOption(std::string_view command,
                                                                    std::string_view value) {
  auto preset = protocols::accuracyPresetFromName(value);
  if (!preset)
    std::fprintf(stderr, "tamponade %s: unknown accuracy '%s' (use draft, standard or fine)\n",
                 std::string(command).c_str(), std::string(value).c_str());
  return preset;
}

}  // namespace tools
