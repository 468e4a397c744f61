// Writes the seed inputs of the run_files harness (docs/fuzzing.md): a checkpoint and a frames
// file as small as the writers make them (three particles, one frame, one series row), so that
// the fuzzer starts from valid files and mutates their structure.
//   make_run_file_seeds FOLDER   writes FOLDER/checkpoint.h5 and FOLDER/frames.h5
#include <cstdio>
#include <filesystem>

#include "protocols/io/checkpoint.h"
#include "protocols/io/frame_writer.h"

namespace {

void fillFluid(sim::FieldRegistry& fluid) {
  fluid.resize(3);
  auto& position = fluid.add<sim::Vec3>({"position", "m", true, true});
  auto& density = fluid.add<sim::Real>({"density", "kg/m^3", true, true});
  auto& phase = fluid.add<int>({"phase", "1", true, true});
  for (int i = 0; i < 3; ++i) {
    position[i] = sim::Vec3(1e-3 * i, 0, 0);
    density[i] = 1000 + i;
    phase[i] = i % 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_run_file_seeds FOLDER\n");
    return 2;
  }
  const std::filesystem::path folder = argv[1];
  std::filesystem::create_directories(folder);
  sim::FieldRegistry fluid;
  fillFluid(fluid);

  protocols::CheckpointState state;
  state.time = 0.25;
  state.step = 7;
  state.dt = 1e-4;
  state.realCounters["coverage"] = 0.5;
  state.integerCounters["frames"] = 1;
  state.blobs["protocol_hash"] = {1, 2, 3, 4};
  state.groups["fluid"] = &fluid;
  protocols::writeCheckpoint(folder / "checkpoint.h5", state);

  protocols::RunMetadata metadata;
  metadata.protocolText = "[eye]\n";
  metadata.strings["protocol_file"] = "seed.toml";
  metadata.numbers["particle_spacing [m]"] = 1e-3;
  protocols::FrameWriterOptions options;
  options.overwrite = true;
  protocols::FrameWriter frames(folder / "frames.h5", metadata, options);
  frames.writeFrame(0.25, 7, {{"fluid", &fluid}});
  frames.appendSeries("coverage", 0.25, {0.5}, {"retina"}, {"1"});
  frames.close();
  return 0;
}
