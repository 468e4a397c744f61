#include "protocols/format/protocol_error.h"

namespace protocols {

std::string SourceLocation::toString() const {
  if (!isInFile()) return file;
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

std::string Diagnostic::toString() const {
  std::string text = where.toString() + ": " + what;
  if (!fix.empty()) text += " \u2014 " + fix;
  return text;
}

namespace {

std::string joinDiagnostics(const std::vector<Diagnostic>& diagnostics) {
  std::string text;
  for (const Diagnostic& d : diagnostics) {
    if (!text.empty()) text += '\n';
    text += d.toString();
  }
  return text;
}

}  // namespace

ProtocolError::ProtocolError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(joinDiagnostics(diagnostics)), diagnostics_(std::move(diagnostics)) {}

}  // namespace protocols
