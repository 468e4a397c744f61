// `tamponade version`: prints the version.
#include <cstdio>
#include <optional>

#include "tools/cli.h"

namespace tools {

int runVersion(Args args) {
  CLI::App app("", "tamponade version");
  describeCommand(app, "usage: tamponade version\n", "Prints the version of the toolkit.\n");
  if (const std::optional<int> exit = parseCommandLine(app, args)) return *exit;
  std::printf("tamponade %s\n", TAMPONADE_VERSION);
  return 0;
}

}  // namespace tools
