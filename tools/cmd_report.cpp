// `tamponade report DIR`: rebuilds report.html, coverage.csv and summary.json of a run from its
// frames.h5 (coverage recomputed from the frames; protocols/run/rebuild_report.h).
#include <cstdio>
#include <filesystem>
#include <string>

#include "protocols/format/protocol_error.h"
#include "protocols/io/io_error.h"
#include "protocols/run/rebuild_report.h"
#include "tools/commands.h"

namespace tools {

int runReport(Args args) {
  constexpr const char* kUsage =
      "usage: tamponade report DIR\n\n"
      "Rebuilds report.html, coverage.csv and summary.json in DIR from DIR/frames.h5.\n";
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (args.size() != 1 || args[0].starts_with("-")) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::filesystem::path folder(args[0]);
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
