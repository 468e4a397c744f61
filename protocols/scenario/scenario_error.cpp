#include "protocols/scenario/scenario_error.h"

#include "protocols/format/protocol_error.h"

namespace protocols {

void failAt(const SourceLocation& where, const std::string& what, const std::string& fix) {
  throw ProtocolError({Diagnostic{where, what, fix}});
}

SourceLocation spacingSource(const Protocol& p) {
  if (p.accuracy.particleSpacing.where.isInFile()) return p.accuracy.particleSpacing.where;
  if (p.accuracy.preset.where.isInFile()) return p.accuracy.preset.where;
  return SourceLocation{p.file.string(), 0, 0};
}

}  // namespace protocols
