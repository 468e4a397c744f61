// The anatomy library's one error type. Library code throws it with context (what, where, how to
// fix it); only tools/ turns it into an exit code (bad parameters are exit code 2 there).
#pragma once

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

}  // namespace anatomy
