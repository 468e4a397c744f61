// The engine's one error type: library code throws it with context; only tools/ turns it into an
// exit code (docs/developer-guide.md code rule 2: no singletons; the library never calls exit()).
#pragma once

#include <stdexcept>
#include <string>

namespace sim {

class SimError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws SimError(what) when `condition` is false. For validating user-facing parameters,
// not for internal invariants (those are asserts).
inline void require(bool condition, const std::string& what) {
  if (!condition) throw SimError(what);
}
// The same for a fixed message: nothing is built unless it throws. Checks that run every step
// (Pipeline::step's) would otherwise allocate a std::string each time for a message longer than
// the 15 characters a string holds without the heap.
inline void require(bool condition, const char* what) {
  if (!condition) throw SimError(what);
}

}  // namespace sim
