// The one exception type of meshing/: bad mesh files, meshes that cannot be repaired, bad
// sampling parameters. The message always names the file (or "mesh" when there is none), what is
// wrong and how to fix it, so tools/ can print it unchanged.
#pragma once

#include <stdexcept>
#include <string>

namespace meshing {

class MeshError : public std::runtime_error {
 public:
  // `source`: the file name, or a short description such as "mesh" for meshes built in memory.
  MeshError(const std::string& source, const std::string& what, const std::string& fix)
      : std::runtime_error(source + ": " + what + (fix.empty() ? "" : " (" + fix + ")")),
        source_(source) {}

  const std::string& source() const { return source_; }

 private:
  std::string source_;
};

}  // namespace meshing
