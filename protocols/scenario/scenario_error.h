// How assembly refuses a protocol it cannot make concrete: a ProtocolError at the value
// responsible (docs/protocols.md, "Error messages").
#pragma once

#include <string>

#include "protocols/format/protocol.h"
#include "protocols/format/source_location.h"

namespace protocols {

[[noreturn]] void failAt(const SourceLocation& where, const std::string& what,
                         const std::string& fix);

// Where the spacing came from: the explicit particle_spacing, else the preset line, else the file.
// Failures of sampling and of the engine depend on it, so they are reported there.
SourceLocation spacingSource(const Protocol& protocol);

}  // namespace protocols
