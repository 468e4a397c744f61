// Every `tamponade` sub-command: a function taking the arguments after its name and returning
// the process exit code (0 ok, 1 run-time failure, 2 bad input or usage). One file per command.
#pragma once

#include <span>
#include <string_view>

namespace tools {

using Args = std::span<const std::string_view>;

struct Command {
  std::string_view name;
  std::string_view summary;
  int (*run)(Args args);
};

}  // namespace tools
