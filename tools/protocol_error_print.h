// How every `tamponade` sub-command that reads a protocol reports a ProtocolError: each
// diagnostic on its own line (file:line:column: what — how to fix), then the count; exit code 2.
#pragma once

#include <cstdio>

#include "protocols/format/protocol_error.h"

namespace tools {

inline int printProtocolError(const protocols::ProtocolError& e) {
  for (const protocols::Diagnostic& d : e.diagnostics())
    std::fprintf(stderr, "%s\n", d.toString().c_str());
  std::fprintf(stderr, "%zu problem%s found; nothing was run.\n", e.diagnostics().size(),
               e.diagnostics().size() == 1 ? "" : "s");
  return 2;
}

}  // namespace tools
