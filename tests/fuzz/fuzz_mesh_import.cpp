// libFuzzer harness: the mesh importer (assimp behind meshing::importMesh) on arbitrary bytes,
// read as STL, OBJ, PLY or OFF by the first byte (docs/fuzzing.md). A MeshError is the importer's
// answer to bad input; anything else (another exception, a crash, a sanitizer report, a hang
// beyond -timeout) is a finding.
#include <array>
#include <cstddef>
#include <cstdint>

#include "meshing/import_mesh.h"
#include "meshing/mesh_error.h"
#include "tests/fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static constexpr std::array<const char*, 4> kExtensions{".stl", ".obj", ".ply", ".off"};
  const auto path = fuzz::writeInput(data + 1, size - 1, kExtensions[data[0] % 4]);
  try {
    (void)meshing::importMesh(path.string(), meshing::LengthUnit::millimetre);
  } catch (const meshing::MeshError&) {
  }
  return 0;
}
