// The error type of protocols/coverage: inconsistent array sizes or bad options, named with the
// function, the array and the sizes that disagree.
#pragma once

#include <stdexcept>
#include <string>

namespace protocols {

class CoverageError : public std::runtime_error {
 public:
  explicit CoverageError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace protocols
