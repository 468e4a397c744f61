// `tamponade sweep`: parameter studies over protocol keys, run on this machine or as a Slurm job
// array, collected into one table and plots (docs/sweeps.md).

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "protocols/format/protocol_error.h"
#include "protocols/scenario/memory_estimate.h"
#include "protocols/sweep/sweep_collect.h"
#include "protocols/sweep/sweep_folder.h"
#include "protocols/sweep/sweep_plan.h"
#include "tools/cli_args.h"
#include "tools/commands.h"
#include "tools/protocol_error_print.h"
#include "tools/sweep_local.h"
#include "tools/sweep_point_process.h"
#include "tools/sweep_slurm.h"

namespace tools {
namespace {

constexpr const char* kUsage =
    "usage: tamponade sweep SWEEP.toml --out DIR [--jobs N] [--threads N] [--max-points N]\n"
    "                                 [--dry-run]\n"
    "       tamponade sweep SWEEP.toml --out DIR --slurm [--partition P] [--account A]\n"
    "                                 [--time HH:MM:SS] [--mem SIZE] [--cpus-per-task N]\n"
    "                                 [--max-parallel N] [--no-submit]\n"
    "       tamponade sweep status DIR\n"
    "       tamponade sweep collect DIR\n\n"
    "Runs a base protocol at every combination of the values in the sweep file's [vary] table\n"
    "(or the lists' k-th values together, with combine = \"zip\"). Every point is built and\n"
    "validated first; one invalid point refuses the sweep with file:line:column. Each point runs\n"
    "in DIR/points/<id>/ as an ordinary run with its own report; DIR/sweep.csv, sweep.md and\n"
    "sweep.html (plots) collect them. Running the same command again skips finished points and\n"
    "resumes stopped ones; Ctrl-C stops every running point at a checkpoint.\n\n"
    "  --jobs N          points at a time on this machine (default: one per core)\n"
    "  --threads N       threads per point (default: the cores shared between the jobs)\n"
    "  --max-points N    refuse sweeps with more points (default 1000)\n"
    "  --dry-run         validate and list the points; run nothing, write nothing\n"
    "  --slurm           write DIR/slurm/sweep.sbatch, one array task per unfinished point, and\n"
    "                    submit it with sbatch (--no-submit: write it only); the resource\n"
    "                    options become #SBATCH lines (--cpus-per-task also sets the threads)\n"
    "  status DIR        each point's state; failed points with their log\n"
    "  collect DIR       (re)write DIR/sweep.csv, sweep.md and sweep.html\n"
    "Exit codes: 0 done; 1 a point failed, or Slurm refused; 2 bad sweep file or usage (nothing\n"
    "run); 130/143 stopped by Ctrl-C/SIGTERM (run the command again to continue).\n"
    "Docs: docs/sweeps.md\n";

struct SweepArgs {
  std::string file, out;
  int jobs = 0, threads = 0;
  long maxPoints = static_cast<long>(protocols::kDefaultMaxSweepPoints);
  bool dryRun = false, slurm = false;
  SlurmOptions slurmOptions;
};

int usage(const std::string& problem = {}) {
  if (!problem.empty()) std::fprintf(stderr, "tamponade sweep: %s\n", problem.c_str());
  std::fputs(kUsage, stderr);
  return 2;
}

SweepArgs parseSweepArgs(Args args) {
  SweepArgs a;
  for (std::size_t k = 0; k < args.size(); ++k) {
    const std::string arg(args[k]);
    auto value = [&]() -> std::string {
      if (k + 1 >= args.size()) throw UsageError(arg + " needs a value");
      return std::string(args[++k]);
    };
    if (arg == "--out")
      a.out = value();
    else if (arg == "--jobs")
      a.jobs = static_cast<int>(parsePositiveInteger(value(), "--jobs"));
    else if (arg == "--threads")
      a.threads = static_cast<int>(parsePositiveInteger(value(), "--threads"));
    else if (arg == "--max-points")
      a.maxPoints = parsePositiveInteger(value(), "--max-points");
    else if (arg == "--dry-run")
      a.dryRun = true;
    else if (arg == "--slurm")
      a.slurm = true;
    else if (arg == "--no-submit")
      a.slurmOptions.submit = false;
    else if (arg == "--partition")
      a.slurmOptions.partition = value();
    else if (arg == "--account")
      a.slurmOptions.account = value();
    else if (arg == "--time")
      a.slurmOptions.time = value();
    else if (arg == "--mem")
      a.slurmOptions.memory = value();
    else if (arg == "--cpus-per-task")
      a.slurmOptions.cpusPerTask =
          static_cast<int>(parsePositiveInteger(value(), "--cpus-per-task"));
    else if (arg == "--max-parallel")
      a.slurmOptions.maxParallel =
          static_cast<int>(parsePositiveInteger(value(), "--max-parallel"));
    else if (!arg.starts_with("-") && a.file.empty())
      a.file = arg;
    else
      throw UsageError("unexpected argument '" + arg + "'");
  }
  if (a.file.empty()) throw UsageError("give the sweep file");
  if (a.out.empty() && !a.dryRun) throw UsageError("give the output folder with --out DIR");
  if (!a.slurm && (!a.slurmOptions.partition.empty() || !a.slurmOptions.time.empty() ||
                   !a.slurmOptions.memory.empty() || !a.slurmOptions.submit))
    throw UsageError("--partition, --time, --mem and --no-submit go with --slurm");
  return a;
}

int listPoints(const protocols::SweepPlan& plan) {
  std::printf("%zu points, every one a valid protocol:\n", plan.points.size());
  for (const auto& p : plan.points)
    std::printf("  %s  %s\n", p.id.c_str(), plan.describe(p).c_str());
  return 0;
}

LocalSweepOptions localOptions(const SweepArgs& a, std::size_t points) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  LocalSweepOptions o;
  o.jobs = a.jobs > 0 ? a.jobs : std::max(1, std::min<int>(cores, static_cast<int>(points)));
  o.threadsPerPoint = a.threads > 0 ? a.threads : std::max(1, cores / o.jobs);
  if (const auto memory = protocols::machineMemoryLimit())
    o.memoryPerPoint = *memory / static_cast<double>(o.jobs);
  return o;
}

int runSweep(const SweepArgs& a) {
  const protocols::SweepPlan plan =
      protocols::planSweep(a.file, static_cast<std::size_t>(a.maxPoints));
  if (a.dryRun) return listPoints(plan);
  const std::filesystem::path folder(a.out);
  const protocols::SweepManifest manifest = protocols::manifestOf(plan);
  if (const std::string why = protocols::sweepFolderConflict(manifest, folder); !why.empty()) {
    std::fprintf(stderr, "tamponade sweep: output folder %s %s\n", folder.string().c_str(),
                 why.c_str());
    return 2;
  }
  protocols::writeSweepFolder(plan, folder);
  if (a.slurm) return submitSweepToSlurm(folder, manifest, a.slurmOptions);
  return runSweepLocally(folder, manifest, localOptions(a, plan.points.size()));
}

int sweepStatus(const std::filesystem::path& folder) {
  const protocols::SweepManifest m = protocols::readSweepManifest(folder);
  std::array<std::size_t, 5> counts{};
  std::string lines;
  const std::string host = hostName();
  for (const auto& point : m.points) {
    protocols::PointRecord r = protocols::readPointRecord(protocols::pointFolder(folder, point.id));
    std::string state(protocols::pointStateName(r.state));
    // A local point whose process is gone was interrupted with its sweep (a kill, a reboot).
    if (r.state == protocols::PointState::kRunning && r.host == host && r.pid > 0 &&
        ::kill(static_cast<pid_t>(r.pid), 0) != 0) {
      r.state = protocols::PointState::kStopped;
      state = "interrupted";
    }
    ++counts[static_cast<std::size_t>(r.state)];
    if (r.state == protocols::PointState::kFailed || r.state == protocols::PointState::kStopped ||
        r.state == protocols::PointState::kRunning)
      lines +=
          "  " + point.id + "  " + state +
          (r.state == protocols::PointState::kFailed ? " (exit " + std::to_string(r.exitCode) + ")"
                                                     : "") +
          "  " + (protocols::pointFolder(folder, point.id) / "run.log").string() + "\n";
  }
  std::printf("%s: %zu points: %zu done, %zu running, %zu pending, %zu failed, %zu stopped\n%s",
              folder.string().c_str(), m.points.size(), counts[2], counts[1], counts[0], counts[3],
              counts[4], lines.c_str());
  const std::filesystem::path jobs = folder / "slurm" / "jobs.txt";
  if (std::filesystem::exists(jobs)) {
    std::ifstream in(jobs);
    std::string id, last;
    while (in >> id) last = id;
    std::printf("submitted to Slurm as job %s: pending points may still be queued (squeue -j %s)\n",
                last.c_str(), last.c_str());
  } else if (counts[3] + counts[4] + counts[0] > 0 && counts[1] == 0) {
    std::printf("run the sweep command again (same file and --out) to run what is not done\n");
  }
  return 0;
}

int sweepCollect(const std::filesystem::path& folder) {
  const protocols::SweepManifest m = protocols::readSweepManifest(folder);
  const auto rows = protocols::collectSweep(m, folder);
  protocols::writeSweepTables(m, rows, folder);
  std::size_t done = 0;
  for (const auto& row : rows) done += row.hasResults() ? 1 : 0;
  std::printf("%zu of %zu points have results\ntable: %s\nplots: %s\n", done, rows.size(),
              (folder / "sweep.csv").string().c_str(), (folder / "sweep.html").string().c_str());
  return 0;
}

// `tamponade sweep task DIR INDEX [--threads N]`: what a Slurm array task runs.
int sweepTask(Args args) {
  if (args.size() != 2 && !(args.size() == 4 && args[2] == "--threads"))
    return usage("task takes DIR INDEX [--threads N]");
  const std::filesystem::path folder(args[0]);
  const protocols::SweepManifest m = protocols::readSweepManifest(folder);
  const std::string indexText(args[1]);
  const bool numeric =
      !indexText.empty() && indexText.find_first_not_of("0123456789") == std::string::npos;
  const std::size_t index = numeric ? std::stoul(indexText) : m.points.size();
  if (index >= m.points.size())
    return usage("task index '" + indexText + "' is not a point of " + folder.string() + " (0 to " +
                 std::to_string(m.points.size() - 1) + ")");
  const int threads =
      args.size() == 4 ? static_cast<int>(parsePositiveInteger(std::string(args[3]), "--threads"))
                       : 1;
  return runSweepPoint(folder, m, index, threads);
}

}  // namespace

int runSweepCommand(Args args) {
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  try {
    if (!args.empty() && (args[0] == "status" || args[0] == "collect")) {
      if (args.size() != 2) return usage(std::string(args[0]) + " takes the sweep's folder");
      return args[0] == "status" ? sweepStatus(std::filesystem::path(args[1]))
                                 : sweepCollect(std::filesystem::path(args[1]));
    }
    if (!args.empty() && args[0] == "task") return sweepTask(args.subspan(1));
    return runSweep(parseSweepArgs(args));
  } catch (const UsageError& e) {
    return usage(e.what());
  } catch (const protocols::ProtocolError& e) {
    return printProtocolError(e);
  } catch (const protocols::SweepError& e) {
    std::fprintf(stderr, "tamponade sweep: %s\n", e.what());
    return 2;
  }
}

}  // namespace tools
