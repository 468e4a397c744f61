// libFuzzer harness: the protocol reader on arbitrary bytes (docs/fuzzing.md).
// A ProtocolError is the reader's answer to bad input; anything else escaping it (another
// exception, a crash, a sanitizer report, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "protocols/format/parse_protocol.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    (void)protocols::parseProtocolText(text, "fuzz/protocol.toml");
  } catch (const protocols::ProtocolError&) {
  }
  return 0;
}
