#include "tools/sweep_local.h"

#include <sys/wait.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <deque>
#include <map>

#include "protocols/report/report_format.h"
#include "protocols/sweep/sweep_collect.h"
#include "tools/sweep_point_process.h"

namespace tools {

namespace {

std::atomic<int> gSweepSignal{0};
extern "C" void onSweepSignal(int signalNumber) { gSweepSignal.store(signalNumber); }

// SIGINT/SIGTERM without SA_RESTART, so that waitpid() returns and the signal is passed on.
void catchStopSignals() {
  struct sigaction action {};
  action.sa_handler = onSweepSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

std::string pointResult(const std::filesystem::path& folder, const protocols::SweepManifest& m,
                        const PointLaunch& launch) {
  const protocols::SweepManifestPoint& point = m.points[launch.index];
  if (launch.record.state != protocols::PointState::kDone)
    return std::string(launch.record.state == protocols::PointState::kStopped ? "stopped"
                                                                              : "FAILED") +
           " (exit " + std::to_string(launch.record.exitCode) + "; see " +
           (protocols::pointFolder(folder, point.id) / "run.log").string() + ")";
  const auto rows = protocols::collectSweep(
      protocols::SweepManifest{m.title, m.sweepFile, m.base, m.keys, m.plotRegions, {point}},
      folder);
  if (rows.empty() || !rows[0].hasResults() || rows[0].regions.empty()) return "done";
  return "done, retina " + protocols::formatPercent(rows[0].regions[0].finalFraction);
}

std::string describePoint(const protocols::SweepManifest& m, std::size_t index) {
  std::string text;
  for (std::size_t k = 0; k < m.keys.size(); ++k)
    text += (k ? ", " : "") + m.keys[k] + " = " + m.points[index].values[k];
  return text;
}

struct SweepProgress {
  std::size_t total = 0, finished = 0, failed = 0;
  double secondsSum = 0.0;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  void report(const std::string& id, const std::string& what, double seconds, std::size_t queued,
              std::size_t running, int jobs) {
    ++finished;
    secondsSum += seconds;
    const double perPoint = secondsSum / static_cast<double>(finished);
    const double eta = perPoint * static_cast<double>(queued + running) / std::max(jobs, 1);
    std::printf("[%zu/%zu] %s %s in %.1f s; %zu running, %zu queued, ETA %.0f s\n", finished, total,
                id.c_str(), what.c_str(), seconds, running, queued, eta);
    std::fflush(stdout);
  }
};

}  // namespace

int runSweepLocally(const std::filesystem::path& folder, const protocols::SweepManifest& manifest,
                    const LocalSweepOptions& options) {
  std::deque<std::size_t> queue;
  for (std::size_t p = 0; p < manifest.points.size(); ++p)
    if (pointNeedsRun(folder, manifest.points[p].id)) queue.push_back(p);
  std::printf("sweep: %zu points, %zu to run (%zu done already), %d at a time, %d thread%s each\n",
              manifest.points.size(), queue.size(), manifest.points.size() - queue.size(),
              options.jobs, options.threadsPerPoint, options.threadsPerPoint == 1 ? "" : "s");
  std::fflush(stdout);
  catchStopSignals();
  const PointResources resources{options.threadsPerPoint, options.memoryPerPoint, "local"};
  std::map<pid_t, PointLaunch> running;
  SweepProgress progress{queue.size()};
  std::vector<std::string> failed;
  while (!queue.empty() || !running.empty()) {
    while (gSweepSignal.load() == 0 && !queue.empty() &&
           static_cast<int>(running.size()) < options.jobs) {
      PointLaunch launch = launchPoint(folder, manifest, queue.front(), resources);
      queue.pop_front();
      running.emplace(launch.pid, std::move(launch));
    }
    if (gSweepSignal.load() != 0) queue.clear();
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno != EINTR) break;
      for (const auto& [child, launch] : running) ::kill(child, gSweepSignal.load());
      continue;
    }
    auto it = running.find(pid);
    if (it == running.end()) continue;
    const protocols::PointRecord r = finishPoint(folder, manifest, it->second, status);
    if (r.state == protocols::PointState::kFailed)
      failed.push_back(manifest.points[it->second.index].id);
    progress.report(manifest.points[it->second.index].id + " (" +
                        describePoint(manifest, it->second.index) + ")",
                    pointResult(folder, manifest, it->second), r.wallSeconds, queue.size(),
                    running.size() - 1, options.jobs);
    running.erase(it);
  }
  protocols::writeSweepTables(manifest, protocols::collectSweep(manifest, folder), folder);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - progress.start).count();
  if (const int signal = gSweepSignal.load(); signal != 0) {
    std::printf(
        "sweep stopped after %.1f s; run the same command again to continue (finished "
        "points are kept, stopped ones resume)\n",
        seconds);
    return 128 + signal;
  }
  std::printf("sweep finished in %.1f s: %zu of %zu points run, %zu failed\n", seconds,
              progress.finished, progress.total, failed.size());
  for (const std::string& id : failed) std::printf("  failed: %s\n", id.c_str());
  if (!failed.empty()) std::printf("run the same command again to retry the failed points\n");
  std::printf("table: %s\nplots: %s\n", (folder / "sweep.csv").string().c_str(),
              (folder / "sweep.html").string().c_str());
  return failed.empty() ? 0 : 1;
}

int runSweepPoint(const std::filesystem::path& folder, const protocols::SweepManifest& manifest,
                  std::size_t index, int threads) {
  if (!pointNeedsRun(folder, manifest.points[index].id)) {
    std::printf("sweep point %s is done already\n", manifest.points[index].id.c_str());
    return 0;
  }
  catchStopSignals();
  PointLaunch launch = launchPoint(folder, manifest, index, PointResources{threads, {}, "slurm"});
  int status = 0;
  while (::waitpid(launch.pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("lost the sweep point's process");
    ::kill(launch.pid, gSweepSignal.load());  // Slurm's SIGTERM at the time limit: checkpoint
  }
  const protocols::PointRecord r = finishPoint(folder, manifest, launch, status);
  std::printf("sweep point %s: %s\n", manifest.points[index].id.c_str(),
              pointResult(folder, manifest, launch).c_str());
  return r.exitCode;
}

}  // namespace tools
