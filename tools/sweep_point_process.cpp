#include "tools/sweep_point_process.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace tools {

namespace {

// Files a run writes into its folder; an attempt that left no checkpoint is started afresh, so
// they go first (`tamponade run` refuses a folder holding frames).
constexpr const char* kRunFiles[] = {"frames.h5",     "frames.xmf",    "summary.json",
                                     "report.html",   "coverage.csv",  "checkpoint.h5",
                                     "interfaces.h5", "interfaces.xmf"};

void clearEarlierAttempt(const std::filesystem::path& folder) {
  for (const char* name : kRunFiles) std::filesystem::remove(folder / name);
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().filename().string().starts_with("interface_"))
      std::filesystem::remove(entry.path());
}

std::filesystem::path selfExecutable() { return std::filesystem::read_symlink("/proc/self/exe"); }

std::vector<std::string> runArguments(const std::filesystem::path& folder, bool resume,
                                      const PointResources& resources) {
  std::vector<std::string> args = {selfExecutable().string(), "run"};
  if (resume) {
    args.insert(args.end(), {"--resume", folder.string()});
  } else {
    args.insert(args.end(), {(folder / "protocol.toml").string(), "--out", folder.string()});
  }
  args.insert(args.end(), {"--threads", std::to_string(resources.threads)});
  if (resources.memoryLimit)
    args.insert(args.end(),
                {"--max-memory",
                 std::to_string(static_cast<long>(*resources.memoryLimit / 1048576.0)) + " MiB"});
  return args;
}

// In the child: output to run.log (appended: every attempt stays readable), then exec.
[[noreturn]] void execRun(const std::filesystem::path& log, const std::vector<std::string>& args) {
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd >= 0) {
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
  }
  std::string line = "== tamponade sweep: ";
  for (const auto& a : args) line += a + " ";
  line += "\n";
  if (::write(STDOUT_FILENO, line.data(), line.size()) < 0) {
    // nothing to do: the log is only informative
  }
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execv(argv[0], argv.data());
  std::perror("tamponade sweep: cannot start tamponade run");
  ::_exit(127);
}

}  // namespace

std::string hostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

bool pointNeedsRun(const std::filesystem::path& sweepFolder, const std::string& id) {
  const std::filesystem::path folder = protocols::pointFolder(sweepFolder, id);
  return protocols::readPointRecord(folder).state != protocols::PointState::kDone ||
         !std::filesystem::exists(folder / "summary.json");
}

PointLaunch launchPoint(const std::filesystem::path& sweepFolder,
                        const protocols::SweepManifest& manifest, std::size_t index,
                        const PointResources& resources) {
  const std::filesystem::path folder =
      protocols::pointFolder(sweepFolder, manifest.points[index].id);
  const bool resume = std::filesystem::exists(folder / "checkpoint.h5");
  if (!resume) clearEarlierAttempt(folder);
  const std::vector<std::string> args = runArguments(folder, resume, resources);
  PointLaunch launch{index, 0, std::chrono::steady_clock::now(),
                     protocols::readPointRecord(folder)};
  std::fflush(nullptr);
  launch.pid = ::fork();
  if (launch.pid < 0) throw std::runtime_error("cannot start a process for the sweep point");
  if (launch.pid == 0) execRun(folder / "run.log", args);
  launch.record.state = protocols::PointState::kRunning;
  launch.record.attempts += 1;
  launch.record.backend = resources.backend;
  launch.record.host = hostName();
  launch.record.pid = launch.pid;
  protocols::writePointRecord(folder, launch.record);
  return launch;
}

protocols::PointRecord finishPoint(const std::filesystem::path& sweepFolder,
                                   const protocols::SweepManifest& manifest, PointLaunch& launch,
                                   int waitStatus) {
  protocols::PointRecord& r = launch.record;
  r.exitCode = WIFEXITED(waitStatus) ? WEXITSTATUS(waitStatus)
                                     : 128 + (WIFSIGNALED(waitStatus) ? WTERMSIG(waitStatus) : 0);
  r.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - launch.start).count();
  r.pid = 0;
  // 130/143: stopped by SIGINT/SIGTERM after writing its checkpoint (`tamponade run --help`).
  r.state = r.exitCode == 0                          ? protocols::PointState::kDone
            : r.exitCode == 130 || r.exitCode == 143 ? protocols::PointState::kStopped
                                                     : protocols::PointState::kFailed;
  protocols::writePointRecord(protocols::pointFolder(sweepFolder, manifest.points[launch.index].id),
                              r);
  return r;
}

}  // namespace tools
