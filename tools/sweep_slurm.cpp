#include "tools/sweep_slurm.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "tools/sweep_point_process.h"

namespace tools {

namespace {

// A shell word in single quotes: safe for any path.
std::string shellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((std::filesystem::path(dir) / program).c_str(), X_OK) == 0)
      return true;
  return false;
}

// Runs `command`, returning its exit code and output (stdout and stderr).
int capture(const std::string& command, std::string& output) {
  std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return -1;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = ::pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

std::string arrayIndexList(const std::vector<std::size_t>& indices) {
  std::string list;
  for (std::size_t k = 0; k < indices.size();) {
    std::size_t end = k;
    while (end + 1 < indices.size() && indices[end + 1] == indices[end] + 1) ++end;
    list += fmt::format("{}{}", list.empty() ? "" : ",", indices[k]);
    if (end > k) list += fmt::format("-{}", indices[end]);
    k = end + 1;
  }
  return list;
}

std::string slurmScript(const std::filesystem::path& folder, const std::filesystem::path& tamponade,
                        const std::vector<std::size_t>& indices, const SlurmOptions& o) {
  std::ostringstream s;
  s << "#!/bin/bash\n"
       "# One array task per sweep point: `tamponade sweep task` runs the point (resuming it when\n"
       "# it has a checkpoint) and records it in points/<id>/point.json. Written by\n"
       "# `tamponade sweep --slurm`; submit it again, or run that command again, to redo the\n"
       "# points that failed or did not finish.\n"
    << "#SBATCH --job-name=tamponade-sweep\n"
    << "#SBATCH --array=" << arrayIndexList(indices)
    << (o.maxParallel > 0 ? fmt::format("%{}", o.maxParallel) : "") << "\n"
    << "#SBATCH --cpus-per-task=" << o.cpusPerTask << "\n"
    << "#SBATCH --output=" << (folder / "slurm" / "task-%a.log").string() << "\n";
  if (!o.time.empty()) s << "#SBATCH --time=" << o.time << "\n";
  if (!o.memory.empty()) s << "#SBATCH --mem=" << o.memory << "\n";
  if (!o.partition.empty()) s << "#SBATCH --partition=" << o.partition << "\n";
  if (!o.account.empty()) s << "#SBATCH --account=" << o.account << "\n";
  s << "exec " << shellQuoted(tamponade.string()) << " sweep task " << shellQuoted(folder.string())
    << " \"$SLURM_ARRAY_TASK_ID\" --threads \"${SLURM_CPUS_PER_TASK:-1}\"\n";
  return s.str();
}

int submitSweepToSlurm(const std::filesystem::path& relativeFolder,
                       const protocols::SweepManifest& manifest, const SlurmOptions& options) {
  const std::filesystem::path folder = std::filesystem::absolute(relativeFolder).lexically_normal();
  std::vector<std::size_t> indices;
  for (std::size_t p = 0; p < manifest.points.size(); ++p)
    if (pointNeedsRun(folder, manifest.points[p].id)) indices.push_back(p);
  if (indices.empty()) {
    std::printf("sweep: every point is done; nothing to submit (tamponade sweep collect %s)\n",
                relativeFolder.string().c_str());
    return 0;
  }
  std::filesystem::create_directories(folder / "slurm");
  const std::filesystem::path script = folder / "slurm" / "sweep.sbatch";
  {
    std::ofstream out(script, std::ios::trunc);
    out << slurmScript(folder, std::filesystem::read_symlink("/proc/self/exe"), indices, options);
  }
  std::printf("sweep: job script for %zu of %zu points: %s\n", indices.size(),
              manifest.points.size(), script.string().c_str());
  if (!options.submit) return 0;
  if (!onPath("sbatch")) {
    std::fprintf(stderr,
                 "tamponade sweep: Slurm's sbatch is not on PATH, so nothing was submitted. On a "
                 "cluster, load Slurm (e.g. module load slurm) and run the command again, or "
                 "submit the script yourself: sbatch %s. Without a cluster, drop --slurm to run "
                 "the sweep on this machine.\n",
                 script.string().c_str());
    return 1;
  }
  std::string output;
  const int code = capture("sbatch --parsable " + shellQuoted(script.string()), output);
  while (!output.empty() && (output.back() == '\n' || output.back() == ' ')) output.pop_back();
  if (code != 0) {
    std::fprintf(stderr, "tamponade sweep: sbatch refused the job (exit %d): %s\n", code,
                 output.c_str());
    return 1;
  }
  std::ofstream(folder / "slurm" / "jobs.txt", std::ios::app) << output << "\n";
  std::printf(
      "sweep: submitted Slurm job %s (%zu array tasks); follow it with\n"
      "  tamponade sweep status %s\nand when it has finished:\n"
      "  tamponade sweep collect %s\n",
      output.c_str(), indices.size(), relativeFolder.string().c_str(),
      relativeFolder.string().c_str());
  return 0;
}

}  // namespace tools
