// The protocol layer's error type. A protocol is validated in full before anything runs, so the
// error carries every problem found, each as `file:line:column: what is wrong — how to fix it`.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "protocols/format/source_location.h"

namespace protocols {

struct Diagnostic {
  SourceLocation where;
  std::string what;  // what is wrong, naming the key and the offending value
  std::string fix;   // how to fix it (may be empty when nothing useful can be said)

  // `file:line:column: what — fix`
  std::string toString() const;
};

class ProtocolError : public std::runtime_error {
 public:
  explicit ProtocolError(std::vector<Diagnostic> diagnostics);

  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace protocols
