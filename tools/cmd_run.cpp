// `tamponade run PROTOCOL [--out DIR] [--accuracy draft|standard|fine] [--threads N]`: assembles
// and runs a protocol, writing frames, the coverage series and the report into the output folder.
// The protocol is validated and the scene assembled before the folder is created.

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "protocols/assembly/assemble_scenario.h"
#include "protocols/equilibrium/posture_equilibrium.h"
#include "protocols/equilibrium/start_from_equilibrium.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/io/io_error.h"
#include "protocols/report/report_format.h"
#include "protocols/run/rebuild_report.h"
#include "protocols/run/run_equilibrium.h"
#include "protocols/run/run_scenario.h"
#include "tools/accuracy_option.h"
#include "tools/cli.h"
#include "tools/cli_values.h"
#include "tools/commands.h"
#include "tools/phase_printer.h"
#include "tools/progress_printer.h"
#include "tools/protocol_error_print.h"

namespace tools {
namespace {

constexpr const char* kUsage =
    "usage: tamponade run PROTOCOL.toml [--out DIR] [--accuracy draft|standard|fine] [--threads "
    "N]\n"
    "                     [--max-memory SIZE]\n"
    "       tamponade run --resume DIR [--threads N] [--max-memory SIZE]\n";

constexpr const char* kDescription =
    "Runs the protocol: frames.h5 + frames.xmf (ParaView), the coverage time series, and\n"
    "report.html, coverage.csv, summary.json in the output folder (default: the protocol's\n"
    "outputs.folder). Checkpoints go to DIR/checkpoint.h5 every 1024 steps and on Ctrl-C or\n"
    "SIGTERM (after at most 15 more steps); --resume DIR continues such a run, with the same\n"
    "result as an uninterrupted run at the same thread count.\n"
    "Progress: a bar with ETA on a terminal, a plain line every 10 % (or 30 s) otherwise.\n";

constexpr const char* kFooter =
    "Exit codes: 0 done; 2 bad protocol or usage (file:line:column, nothing created); 1 the run\n"
    "failed; 130 stopped by Ctrl-C (SIGINT), 143 stopped by SIGTERM (128 + signal number, the\n"
    "shell convention), each after writing the checkpoint.\n";

// The command line of `tamponade run`.
struct RunArgs {
  std::string file, out, resume, accuracy;
  int threads = 0;
  long stopAfter = -1;
  double memoryLimit = 0;  // [B] 0: what the machine has available
};

void defineRunOptions(CLI::App& app, RunArgs& a) {
  CLI::Option* file = app.add_option("PROTOCOL.toml", a.file, "the protocol to run");
  CLI::Option* resume = app.add_option("--resume", a.resume,
                                       "continue the stopped run in DIR from its checkpoint (no "
                                       "PROTOCOL,\n--out or --accuracy with it)")
                            ->type_name("DIR")
                            ->excludes(file);
  app.add_option("--out", a.out, "output folder (default: the protocol's outputs.folder)")
      ->type_name("DIR")
      ->excludes(resume);
  addAccuracyOption(app, a.accuracy)->excludes(resume);
  app.add_option("--threads", a.threads, "OpenMP threads (default OMP_NUM_THREADS)")
      ->type_name("N")
      ->check(positiveInteger(std::numeric_limits<int>::max()));
  app.add_option("--max-memory", a.memoryLimit,
                 "refuse a scene whose estimated memory exceeds SIZE (e.g. 4 GiB) before\n"
                 "anything is allocated, naming the spacing that would fit (default: what the\n"
                 "machine has available)")
      ->type_name("SIZE")
      ->transform(memorySize());
  app.add_option("--stop-after-steps", a.stopAfter,
                 "stop as if interrupted at step N and exit 1 (for tests)")
      ->type_name("N")
      ->check(positiveInteger());
}

// Set by SIGINT/SIGTERM; the run checkpoints and stops at its next checkpointable step.
// Lock-free atomics, so storing to them is async-signal-safe.
std::atomic<bool> gStop{false};
std::atomic<int> gSignal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);
extern "C" void onSignal(int signalNumber) {
  gSignal.store(signalNumber);
  gStop.store(true);
}

// One line per posture at its equilibrium (of an equilibrium schedule, or those a mixed one
// begins with).
void printEquilibriumProgress(const protocols::EquilibriumProgress& p) {
  std::printf(
      "posture %zu/%zu (%s): equilibrium in %.2f s (%d iterations%s), retina %s "
      "covered\n",
      p.posture + 1, p.postures, p.label.c_str(), p.seconds, p.iterations,
      p.converged ? "" : ", not settled", protocols::formatPercent(p.retinaCoverage).c_str());
  std::fflush(stdout);
}

// A schedule of equilibrium postures: one line per posture, then the report.
int runEquilibrium(const protocols::Protocol& protocol, protocols::Scenario& scenario,
                   const std::filesystem::path& folder) {
  protocols::RunOptions run;
  run.outputFolder = folder;
  const protocols::RunSummary summary =
      protocols::runEquilibriumSchedule(protocol, scenario, run, printEquilibriumProgress);
  std::printf(
      "equilibria finished in %.1f s; mean retinal coverage %s over the schedule\noutput: %s\n",
      summary.wallSeconds, protocols::formatPercent(summary.retinaCoverage).c_str(),
      folder.string().c_str());
  return 0;
}

// Creates the output folder; why it cannot be used, in words ("" when it can): a file in its
// place, a parent that is a file, no permission (std::filesystem's own message would name neither
// the fix nor the option).
std::string outputFolderProblem(const std::filesystem::path& folder) {
  std::error_code ec;
  if (std::filesystem::exists(folder, ec) && !std::filesystem::is_directory(folder, ec))
    return "exists and is not a folder — choose another --out (or outputs.folder) or remove it";
  std::filesystem::create_directories(folder, ec);
  if (ec)
    return "cannot be created: " + ec.message() +
           " — choose another --out (or outputs.folder) where you may write";
  return {};
}

// What to do about a folder that holds a run already (it may still be running: two runs never
// share a folder, so nothing is removed here).
std::string occupiedFolderAdvice(const std::filesystem::path& folder) {
  if (std::filesystem::exists(folder / "checkpoint.h5"))
    return "if it was stopped, continue it with tamponade run --resume " + folder.string() +
           "; otherwise choose another --out or remove the folder";
  if (!std::filesystem::exists(folder / "summary.json"))
    return "it has no checkpoint, so it cannot be resumed (stopped before its first one, or "
           "still running): remove frames.h5 and frames.xmf from it to run into it again, or "
           "choose another --out";
  return "choose another --out or remove it";
}

}  // namespace

int runRun(Args args) {
  CLI::App app("", "tamponade run");
  describeCommand(app, kUsage, kDescription, kFooter);
  RunArgs a;
  defineRunOptions(app, a);
  if (const std::optional<int> exit = parseCommandLine(app, args)) return *exit;
  if (a.file.empty() && a.resume.empty())
    return usageError(app, "give the protocol file, or --resume DIR");
  const std::string &file = a.file, &out = a.out, &resume = a.resume;
  const int threads = a.threads;
  protocols::ScenarioOptions options;
  options.accuracy = accuracyPreset(a.accuracy);
  if (a.memoryLimit > 0) options.memoryLimit = a.memoryLimit;
#ifdef _OPENMP
  if (threads > 0) omp_set_num_threads(threads);
#endif
  if (!options.memoryLimit) options.memoryLimit = protocols::machineMemoryLimit();
  try {
    if (!resume.empty() &&
        !std::filesystem::exists(std::filesystem::path(resume) / "checkpoint.h5")) {
      const bool started = std::filesystem::exists(std::filesystem::path(resume) / "frames.h5");
      std::fprintf(stderr, "tamponade run: %s has no checkpoint.h5 to resume from%s\n",
                   resume.c_str(),
                   started ? ": the run stopped before its first checkpoint (every 1024 steps and "
                             "on Ctrl-C or SIGTERM); run the protocol again after removing "
                             "frames.h5 and frames.xmf from the folder"
                           : "; give the folder of a stopped run");
      return 2;
    }
    const protocols::Protocol protocol = resume.empty()
                                             ? protocols::parseProtocol(file)
                                             : protocols::loadRunProtocol(resume, options);
    options.progress = PhasePrinter("run");
    protocols::Scenario scenario = protocols::assembleStartingScenario(protocol, options);
    const std::filesystem::path folder(!resume.empty() ? resume
                                       : out.empty()   ? protocol.outputs.folder.value
                                                       : out);
    if (resume.empty() && std::filesystem::exists(folder / "frames.h5")) {
      std::fprintf(stderr, "tamponade run: %s already holds a run (frames.h5); %s\n",
                   folder.string().c_str(), occupiedFolderAdvice(folder).c_str());
      return 2;
    }
    if (const std::string problem = outputFolderProblem(folder); !problem.empty()) {
      std::fprintf(stderr, "tamponade run: output folder %s %s\n", folder.string().c_str(),
                   problem.c_str());
      return 2;
    }
    // The scenario's notes are about the particle simulation, which an equilibrium run skips.
    if (protocols::isEquilibriumSchedule(scenario))
      return runEquilibrium(protocol, scenario, folder);
    for (const auto& note : scenario.notes) std::fprintf(stderr, "note: %s\n", note.c_str());

    ProgressPrinter printer;
    protocols::RunOptions run;
    run.outputFolder = folder;
    run.resume = !resume.empty();
    run.stopAfterSteps = a.stopAfter;
    run.stopRequested = &gStop;
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    if (options.accuracy)
      run.accuracyOverride =
          std::string(protocols::kAccuracyPresetNames[static_cast<std::size_t>(*options.accuracy)]);
    run.progress = [&](const protocols::RunProgress& p) { printer(p); };
    run.equilibriumProgress = printEquilibriumProgress;
    const protocols::RunSummary summary = protocols::runScenario(protocol, scenario, run);
    printer.finish();
    if (summary.stopped) {
      std::printf(
          "run stopped at t = %.6g s (step %ld) with a checkpoint; continue with\n"
          "  tamponade run --resume %s\n",
          summary.simulatedTime, summary.steps, folder.string().c_str());
      std::fflush(stdout);
      const int signalNumber = gSignal.load();
      return signalNumber != 0 ? 128 + signalNumber : 1;
    }
    for (std::size_t k = 0; k < scenario.schedule.size(); ++k) {
      const protocols::ScheduledPosture& posture = scenario.schedule[k];
      if (posture.untilSteady && posture.endedSteady)
        std::printf("posture %zu (%s): %s after %.4g s\n", k + 1, posture.label.c_str(),
                    *posture.endedSteady ? "steady" : "not steady, stopped at its maximum",
                    posture.duration);
    }
    std::printf(
        "run finished: %ld steps, %zu frames, %.4g s simulated in %.1f s; mean retinal "
        "coverage %s\noutput: %s\n",
        summary.steps, summary.frames, summary.simulatedTime, summary.wallSeconds,
        protocols::formatPercent(summary.retinaCoverage).c_str(), folder.string().c_str());
    return 0;
  } catch (const protocols::ProtocolError& e) {
    return printProtocolError(e);
  } catch (const protocols::IoError& e) {
    if (resume.empty()) throw;  // writing a new run failed: exit 1 (main)
    // A checkpoint or frames file that does not belong to this run, or is damaged, is bad input.
    std::fprintf(stderr, "tamponade run: cannot resume: %s\n", e.what());
    return 2;
  }
}

}  // namespace tools
