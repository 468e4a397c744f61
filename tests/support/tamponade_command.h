// Runs the `tamponade` executable from a test, in a working directory, and captures its output:
// the one helper every command-line test uses (TAMPONADE_EXECUTABLE is the built binary's path,
// defined by each test target's CMakeLists).
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace tamponade_test {

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

// Passive OpenMP waiting: the CI machine is shared, and spinning threads that wait for a
// descheduled one made steps 100x slower there (tools/test.sh). stderr goes to a
// pipe, so `tamponade run` prints its plain (non-terminal) progress lines.
inline CommandResult runTamponade(const std::string& arguments,
                                  const std::filesystem::path& workingDirectory = ".") {
  const std::string command = "cd '" + workingDirectory.string() +
                              "' && OMP_WAIT_POLICY=passive '" + TAMPONADE_EXECUTABLE "' " +
                              arguments + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
    result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

inline std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace tamponade_test
