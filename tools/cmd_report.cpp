// `tamponade report DIR`: rebuilds report.html, coverage.csv and summary.json of a run from its
// frames.h5 (coverage recomputed from the frames; protocols/run/rebuild_report.h).
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "protocols/format/protocol_error.h"
#include "protocols/io/io_error.h"
#include "protocols/run/rebuild_report.h"
#include "tools/cli.h"

namespace tools {

int runReport(Args args) {
  CLI::App app("", "tamponade report");
  describeCommand(
      app, "usage: tamponade report DIR\n",
      "Rebuilds report.html, coverage.csv and summary.json in DIR from DIR/frames.h5.\n");
  std::string dir;
  app.add_option("DIR", dir, "the folder of a run")->required();
  if (const std::optional<int> exit = parseCommandLine(app, args)) return *exit;
  const std::filesystem::path folder(dir);
  if (!std::filesystem::exists(folder / "frames.h5")) {
    // An equilibrium schedule writes its report, interfaces and no frames: nothing to rebuild.
    if (std::filesystem::exists(folder / "interface_1.ply"))
      std::fprintf(stderr,
                   "tamponade report: %s holds equilibria (duration = \"equilibrium\"), whose "
                   "report the run wrote; to make it again, run the protocol again (seconds)\n",
                   folder.string().c_str());
    else
      std::fprintf(stderr, "tamponade report: %s has no frames.h5; give the folder of a run\n",
                   folder.string().c_str());
    return 2;
  }
  try {
    protocols::rebuildReport(folder);
  } catch (const protocols::ProtocolError& e) {
    for (const protocols::Diagnostic& d : e.diagnostics())
      std::fprintf(stderr, "%s\n", d.toString().c_str());
    return 2;
  }
  std::printf("report rebuilt: %s\n", (folder / "report.html").string().c_str());
  return 0;
}

}  // namespace tools
