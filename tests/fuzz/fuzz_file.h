// The fuzzed bytes as a file for readers that take a path (assimp, HDF5): one file per process
// in the system's temporary folder, rewritten for every input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace fuzz {

inline std::filesystem::path writeInput(const std::uint8_t* data, std::size_t size,
                                        const std::string& extension) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("tamponade-fuzz-" + std::to_string(getpid()) + extension);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace fuzz
