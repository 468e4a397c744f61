// The anatomy library's one error type. Library code throws it with context (what, where, how to
// fix it); only tools/ turns it into an exit code (bad parameters are exit code 2 there).
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>

namespace anatomy {

class AnatomyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws AnatomyError(what) when `condition` is false. For user-facing parameters only.
inline void require(bool condition, const std::string& what) {
  if (!condition) throw AnatomyError(what);
}

// "12.35 mm": a length [m] as messages show it (clinical unit, two decimals).
inline std::string mmText(double metres) {
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), "%.2f mm", metres * 1e3);
  return buffer;
}

}  // namespace anatomy
