// `tamponade sweep`: parameter studies over protocol keys, run on this machine or as a Slurm job
// array, collected into one table and plots (docs/sweeps.md).

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "protocols/format/protocol_error.h"
#include "protocols/scenario/memory_estimate.h"
#include "protocols/sweep/sweep_collect.h"
#include "protocols/sweep/sweep_folder.h"
#include "protocols/sweep/sweep_plan.h"
#include "tools/cli.h"
#include "tools/cli_values.h"
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
    "       tamponade sweep collect DIR\n";

constexpr const char* kDescription =
    "Runs a base protocol at every combination of the values in the sweep file's [vary] table\n"
    "(or the lists' k-th values together, with combine = \"zip\"). Every point is built and\n"
    "validated first; one invalid point refuses the sweep with file:line:column. Each point runs\n"
    "in DIR/points/<id>/ as an ordinary run with its own report; DIR/sweep.csv, sweep.md and\n"
    "sweep.html (plots) collect them. Running the same command again skips finished points and\n"
    "resumes stopped ones; Ctrl-C stops every running point at a checkpoint.\n";

constexpr const char* kFooter =
    "Exit codes: 0 done; 1 a point failed, or Slurm refused; 2 bad sweep file or usage (nothing\n"
    "run); 130/143 stopped by Ctrl-C/SIGTERM (run the command again to continue).\n"
    "Docs: docs/sweeps.md\n";

struct SweepArgs {
  std::string file, out;
  int jobs = 0, threads = 0;
  long maxPoints = static_cast<long>(protocols::kDefaultMaxSweepPoints);
  bool dryRun = false, slurm = false, noSubmit = false;
  SlurmOptions slurmOptions;
};

// The options of a local sweep, the default when no sub-command is given.
void defineLocalOptions(CLI::App& app, SweepArgs& a) {
  const CLI::Validator count = positiveInteger(std::numeric_limits<int>::max());
  app.add_option("SWEEP.toml", a.file, "the sweep file");
  app.add_option("--out", a.out, "output folder of the sweep")->type_name("DIR");
  app.add_option("--jobs", a.jobs, "points at a time on this machine (default: one per core)")
      ->type_name("N")
      ->check(count);
  app.add_option("--threads", a.threads,
                 "threads per point (default: the cores shared between the jobs)")
      ->type_name("N")
      ->check(count);
  app.add_option("--max-points", a.maxPoints, "refuse sweeps with more points")
      ->type_name("N")
      ->check(positiveInteger())
      ->capture_default_str();
  app.add_flag("--dry-run", a.dryRun, "validate and list the points; run nothing, write nothing");
}

// The options of a sweep as a Slurm job array.
void defineSlurmOptions(CLI::App& app, SweepArgs& a) {
  const CLI::Validator count = positiveInteger(std::numeric_limits<int>::max());
  SlurmOptions& o = a.slurmOptions;
  CLI::Option* slurm =
      app.add_flag("--slurm", a.slurm,
                   "write DIR/slurm/sweep.sbatch, one array task per unfinished point,\n"
                   "and submit it with sbatch; the resource options become #SBATCH lines\n"
                   "(--cpus-per-task also sets the threads); --no-submit, --partition,\n"
                   "--time and --mem go with it");
  app.add_flag("--no-submit", a.noSubmit, "write the script only")->needs(slurm);
  app.add_option("--partition", o.partition, "Slurm partition")->type_name("P")->needs(slurm);
  app.add_option("--account", o.account, "Slurm account")->type_name("A");
  app.add_option("--time", o.time, "time limit of each array task")
      ->type_name("HH:MM:SS")
      ->needs(slurm);
  app.add_option("--mem", o.memory, "memory of each array task (e.g. 4G)")
      ->type_name("SIZE")
      ->needs(slurm);
  app.add_option("--cpus-per-task", o.cpusPerTask, "cores of each array task")
      ->type_name("N")
      ->check(count);
  app.add_option("--max-parallel", o.maxParallel, "array tasks at a time (default: no limit)")
      ->type_name("N")
      ->check(count);
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

// What the sub-commands name on the command line.
struct FolderArgs {
  std::string folder;
  long index = 0;
  int threads = 1;
};

// `tamponade sweep task DIR INDEX [--threads N]`: what a Slurm array task runs.
int sweepTask(const CLI::App& task, const FolderArgs& a) {
  const std::filesystem::path folder(a.folder);
  const protocols::SweepManifest m = protocols::readSweepManifest(folder);
  if (a.index >= static_cast<long>(m.points.size()))
    return usageError(task, "task index '" + std::to_string(a.index) + "' is not a point of " +
                                folder.string() + " (0 to " + std::to_string(m.points.size() - 1) +
                                ")");
  return runSweepPoint(folder, m, static_cast<std::size_t>(a.index), a.threads);
}

// status, collect and the hidden task: sub-commands of `tamponade sweep` over a sweep's folder.
void defineFolderCommands(CLI::App& app, FolderArgs& a) {
  for (const auto& [name, summary] :
       {std::pair{"status", "each point's state; failed points with their log"},
        std::pair{"collect", "(re)write DIR/sweep.csv, sweep.md and sweep.html"}}) {
    CLI::App* sub = addSubcommand(
        app, name, summary, std::string("usage: tamponade sweep ") + name + " DIR\n", summary);
    sub->add_option("DIR", a.folder, "the sweep's output folder")->required();
  }
  CLI::App* task = addSubcommand(app, "task", "run one point (what a Slurm array task runs)",
                                 "usage: tamponade sweep task DIR INDEX [--threads N]\n",
                                 "Runs point INDEX (0-based) of the sweep in DIR.\n");
  task->group("");  // not for users: the batch script calls it
  task->add_option("DIR", a.folder, "the sweep's output folder")->required();
  task->add_option("INDEX", a.index, "the point's index in the manifest, from 0")
      ->required()
      ->check(wholeNumber(0, std::numeric_limits<long>::max()));
  task->add_option("--threads", a.threads, "threads of the point")
      ->type_name("N")
      ->check(positiveInteger(std::numeric_limits<int>::max()));
}

// What the local or Slurm sweep needs beyond each option's own check.
std::string sweepArgsProblem(const SweepArgs& a) {
  if (a.file.empty()) return "give the sweep file";
  if (a.out.empty() && !a.dryRun) return "give the output folder with --out DIR";
  return {};
}

}  // namespace

int runSweepCommand(Args args) {
  CLI::App app("", "tamponade sweep");
  describeCommand(app, kUsage, kDescription, kFooter);
  SweepArgs a;
  defineLocalOptions(app, a);
  defineSlurmOptions(app, a);
  FolderArgs folder;
  defineFolderCommands(app, folder);
  if (const std::optional<int> exit = parseCommandLine(app, args)) return *exit;
  try {
    if (app.got_subcommand("status")) return sweepStatus(folder.folder);
    if (app.got_subcommand("collect")) return sweepCollect(folder.folder);
    if (app.got_subcommand("task")) return sweepTask(*app.get_subcommand("task"), folder);
    if (const std::string problem = sweepArgsProblem(a); !problem.empty())
      return usageError(app, problem);
    a.slurmOptions.submit = !a.noSubmit;
    return runSweep(a);
  } catch (const protocols::ProtocolError& e) {
    return printProtocolError(e);
  } catch (const protocols::SweepError& e) {
    std::fprintf(stderr, "tamponade sweep: %s\n", e.what());
    return 2;
  }
}

}  // namespace tools
