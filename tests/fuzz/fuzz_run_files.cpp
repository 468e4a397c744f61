// libFuzzer harness: the readers of a run's files, checkpoint.h5 (readCheckpoint) and frames.h5
// (FrameReader: frames, fields, series, run info), on arbitrary bytes (docs/fuzzing.md). An
// IoError is their answer to a damaged file; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <map>

#include "protocols/io/checkpoint.h"
#include "protocols/io/frame_reader.h"
#include "protocols/io/io_error.h"
#include "tests/fuzz/fuzz_file.h"

namespace {

void readFrames(const std::filesystem::path& path) {
  protocols::FrameReader reader(path);
  for (const auto& frame : reader.frames())
    for (const auto& group : frame.groups)
      for (const auto& field : reader.fieldNames(frame.index, group))
        (void)reader.readField(frame.index, group, field);
  for (const auto& group : reader.staticGroups())
    for (const auto& field : reader.staticFieldNames(group))
      (void)reader.readStaticField(group, field);
  (void)reader.runInfo();
  for (const auto& name : reader.seriesNames()) (void)reader.readSeries(name);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = fuzz::writeInput(data, size, ".h5");
  try {
    (void)protocols::readCheckpoint(path, {});
  } catch (const protocols::IoError&) {
  }
  try {
    readFrames(path);
  } catch (const protocols::IoError&) {
  }
  return 0;
}
