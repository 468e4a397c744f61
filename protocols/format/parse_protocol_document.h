// Reading a protocol from a TOML document already parsed, and perhaps edited: a sweep point is
// its base protocol with the swept keys replaced (protocols/sweep/). Kept apart from
// parse_protocol.h so that only the protocols layer sees toml++.
#pragma once

#include <toml++/toml.h>
#include <filesystem>

#include "protocols/format/protocol.h"

namespace protocols {

// As parseProtocolText() after its TOML parse. `file` names the document; a value parsed from
// another file (its source region names that file) is reported at its own file, line and column.
Protocol parseProtocolDocument(const toml::table& document, const std::filesystem::path& file);

}  // namespace protocols
