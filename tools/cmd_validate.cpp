// `tamponade validate PROTOCOL`: parse and check a protocol, print it normalised in SI (exit 0),
// or print every problem as file:line:column and exit 2. Creates no file either way.
#include <cstdio>
#include <optional>
#include <string>

#include "protocols/format/describe_protocol.h"
#include "protocols/format/parameter_table.h"
#include "protocols/format/parse_protocol.h"
#include "tools/cli.h"
#include "tools/protocol_error_print.h"

namespace tools {

namespace {

constexpr const char* kUsage =
    "usage: tamponade validate PROTOCOL.toml\n"
    "       tamponade validate --reference   (print the generated tables of docs/protocols.md)\n";

constexpr const char* kDescription =
    "Checks a protocol file without running anything and prints it normalised in SI units,\n"
    "defaults filled in. On errors prints each as file:line:column and exits with code 2.\n";

int printReference() {
  std::printf("<!-- begin parameter-reference -->\n%s<!-- end parameter-reference -->\n\n",
              protocols::renderParameterReference().c_str());
  std::printf("<!-- begin unit-table -->\n%s<!-- end unit-table -->\n\n",
              protocols::renderUnitTable().c_str());
  std::printf("<!-- begin accuracy-presets -->\n%s<!-- end accuracy-presets -->\n",
              protocols::renderAccuracyPresetTable().c_str());
  return 0;
}

}  // namespace

int runValidate(Args args) {
  CLI::App app("", "tamponade validate");
  describeCommand(app, kUsage, kDescription);
  std::string file;
  bool reference = false;
  CLI::Option* fileOption = app.add_option("PROTOCOL.toml", file, "the protocol to check");
  app.add_flag("--reference", reference,
               "print the generated tables of docs/protocols.md (every key, the units, the\n"
               "accuracy presets)")
      ->excludes(fileOption);
  if (const std::optional<int> exit = parseCommandLine(app, args)) return *exit;
  if (reference) return printReference();
  if (file.empty()) return usageError(app, "give the protocol file");
  try {
    const protocols::Protocol protocol = protocols::parseProtocol(file);
    std::fputs(protocols::describeProtocol(protocol).c_str(), stdout);
    return 0;
  } catch (const protocols::ProtocolError& e) {
    return printProtocolError(e);
  }
}

}  // namespace tools
