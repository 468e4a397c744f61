// A fresh, empty directory for one test's files: the one helper every test uses instead of
// removing and creating a temporary path by hand.
#pragma once

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>

namespace tamponade_test {

// <system temp dir>/<name>-<process id>-<count>, emptied on construction and removed with
// everything in it on destruction. The process id keeps two test runs apart (two checkouts may
// test at once on one machine); the count keeps two directories of one process apart.
class ScratchDirectory {
 public:
  explicit ScratchDirectory(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              (name + "-" + std::to_string(::getpid()) + "-" + std::to_string(nextCount()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    if (!path_.empty()) std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  // Movable so that a helper can fill one and return it; the moved-from object removes nothing.
  ScratchDirectory(ScratchDirectory&& other) noexcept : path_(std::move(other.path_)) {
    other.path_.clear();
  }
  ScratchDirectory& operator=(ScratchDirectory&&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // Implicit, so that the directory passes wherever a test helper takes a path.
  operator const std::filesystem::path&() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // For interfaces that take a file name as a string.
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  static int nextCount() {
    static std::atomic<int> count{0};
    return count++;
  }
  std::filesystem::path path_;
};

}  // namespace tamponade_test
