// `tamponade validate PROTOCOL`: parse and check a protocol, print it normalised in SI (exit 0),
// or print every problem as file:line:column and exit 2. Creates no file either way.
#include <cstdio>
#include <string>

#include "protocols/format/describe_protocol.h"
#include "protocols/format/parameter_table.h"
#include "protocols/format/parse_protocol.h"
#include "tools/commands.h"
#include "tools/protocol_error_print.h"

namespace tools {

namespace {

constexpr const char* kUsage =
    "usage: tamponade validate PROTOCOL.toml\n"
    "       tamponade validate --reference   (print the generated tables of docs/protocols.md)\n\n"
    "Checks a protocol file without running anything and prints it normalised in SI units,\n"
    "defaults filled in. On errors prints each as file:line:column and exits with code 2.\n";

}  // namespace

int runValidate(Args args) {
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (args.size() == 1 && args[0] == "--reference") {
    std::printf("<!-- begin parameter-reference -->\n%s<!-- end parameter-reference -->\n\n",
                protocols::renderParameterReference().c_str());
    std::printf("<!-- begin unit-table -->\n%s<!-- end unit-table -->\n\n",
                protocols::renderUnitTable().c_str());
    std::printf("<!-- begin accuracy-presets -->\n%s<!-- end accuracy-presets -->\n",
                protocols::renderAccuracyPresetTable().c_str());
    return 0;
  }
  if (args.size() != 1 || args[0].starts_with("-")) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  try {
    const protocols::Protocol protocol = protocols::parseProtocol(std::string(args[0]));
    std::fputs(protocols::describeProtocol(protocol).c_str(), stdout);
    return 0;
  } catch (const protocols::ProtocolError& e) {
    return printProtocolError(e);
  }
}

}  // namespace tools
