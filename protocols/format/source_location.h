// Where a value came from in a protocol file, and a value carrying that place, so that every
// later stage (scenario assembly, the runner) can report an error at the line the user wrote.
#pragma once

#include <string>

namespace protocols {

struct SourceLocation {
  std::string file;  // the protocol file as the user named it
  int line = 0;      // 1-based; 0 = not written in the file (a default)
  int column = 0;    // 1-based

  bool isInFile() const { return line > 0; }
  // "file:line:column", or "file" for a default value.
  std::string toString() const;
};

// A value plus the place it was read from. Defaults carry a location with line 0.
template <class T>
struct Located {
  T value{};
  SourceLocation where;
};

}  // namespace protocols
