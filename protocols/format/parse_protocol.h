// Reading a protocol file: parse + validate everything before anything runs
// (docs/developer-guide.md data flow). On any problem, throws ProtocolError listing every problem
// found, each as `file:line:column: what is wrong — how to fix it`.
#pragma once

#include <filesystem>
#include <string_view>

#include "protocols/format/protocol.h"
#include "protocols/format/protocol_error.h"

namespace protocols {

Protocol parseProtocol(const std::filesystem::path& file);

// The same from text in memory. `file` names it in messages, and relative paths in it (the eye
// mesh) are resolved against `file`'s folder.
Protocol parseProtocolText(std::string_view text, const std::filesystem::path& file);

}  // namespace protocols
