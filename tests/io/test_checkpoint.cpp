// Checkpoints: bit-identical round trip of every checkpointed field plus scalars, counters and
// blobs; mismatches named precisely and leaving the registries untouched; atomic replacement.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <fstream>

#include "io_test_support.h"
#include "protocols/io/checkpoint.h"
#include "protocols/io/io_error.h"
#include "tests/support/scratch_directory.h"

using protocols::CheckpointState;
using protocols::IoError;
using protocols::readCheckpoint;
using protocols::writeCheckpoint;

namespace {

CheckpointState sampleState(sim::DynamicParticles& fluid, sim::WallParticles& walls) {
  CheckpointState state;
  state.time = 1.0 / 3.0;
  state.step = 123456789012LL;
  state.dt = 2.5e-5;
  state.realCounters["coverage_integral"] = 0.1 + 0.2;
  state.integerCounters["frames_written"] = 42;
  state.integerCounters["posture_index"] = -1;
  state.blobs["rng"] = {0, 1, 2, 255, 0, 128};
  state.blobs["empty"] = {};
  state.groups = {{"fluid", &fluid.fields}, {"wall", &walls.fields}};
  return state;
}

}  // namespace

TEST_CASE("checkpoints restore every checkpointed field bit-identically", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid, restoredFluid;
  sim::WallParticles walls, restoredWalls;
  iotest::fillFluid(fluid, 400, 11);
  iotest::fillWall(walls, 300, 12);
  writeCheckpoint(dir / "checkpoint.h5", sampleState(fluid, walls));
  CHECK_FALSE(std::filesystem::exists(dir / "checkpoint.h5.tmp"));

  // The resumed run rebuilds its particle sets (same sizes, same fields) and restores them.
  iotest::fillFluid(restoredFluid, 400, 99);
  iotest::fillWall(restoredWalls, 300, 98);
  const auto scratchBefore = restoredFluid.fields.get<sim::Real>("scratch");
  const CheckpointState read = readCheckpoint(
      dir / "checkpoint.h5", {{"fluid", &restoredFluid.fields}, {"wall", &restoredWalls.fields}});

  CHECK(read.time == 1.0 / 3.0);
  CHECK(read.step == 123456789012LL);
  CHECK(read.dt == 2.5e-5);
  CHECK(read.realCounters == std::map<std::string, double>{{"coverage_integral", 0.1 + 0.2}});
  CHECK(read.integerCounters ==
        std::map<std::string, std::int64_t>{{"frames_written", 42}, {"posture_index", -1}});
  CHECK(read.blobs.at("rng") == std::vector<std::uint8_t>{0, 1, 2, 255, 0, 128});
  CHECK(read.blobs.at("empty").empty());

  for (auto [original, restored] : {std::pair{&fluid.fields, &restoredFluid.fields},
                                    std::pair{&walls.fields, &restoredWalls.fields}}) {
    for (const auto& field : *original) {
      INFO(field->info().name);
      const sim::FieldBase* other = restored->find(field->info().name);
      const std::size_t bytes =
          field->size() * field->components() * (field->kind() == sim::ScalarKind::kReal ? 8 : 4);
      const bool equal = std::memcmp(field->rawData(), other->rawData(), bytes) == 0;
      // Checkpointed fields are restored exactly; the others keep the resumed run's values.
      CHECK(equal == field->info().checkpointed);
    }
  }
  CHECK(restoredFluid.fields.get<sim::Real>("scratch") == scratchBefore);
}

TEST_CASE("checkpoint mismatches are reported by name and restore nothing", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid;
  sim::WallParticles walls;
  iotest::fillFluid(fluid, 50, 1);
  iotest::fillWall(walls, 20, 2);
  writeCheckpoint(dir / "checkpoint.h5", sampleState(fluid, walls));

  sim::DynamicParticles other;
  sim::WallParticles otherWalls;
  iotest::fillFluid(other, 50, 3);
  iotest::fillWall(otherWalls, 20, 4);
  const std::vector<sim::Vec3> before = other.x;

  SECTION("a field this run checkpoints but the checkpoint lacks") {
    other.fields.add<sim::Real>({"interface_curvature", "1/m", true, false});
    other.fields.add<sim::Vec3>({"surface_normal", "1", true, false});
    try {
      readCheckpoint(dir / "checkpoint.h5",
                     {{"fluid", &other.fields}, {"wall", &otherWalls.fields}});
      FAIL("missing fields accepted");
    } catch (const IoError& e) {
      CHECK(e.object() == "/groups/fluid");
      CHECK_THAT(e.what(), Catch::Contains("'interface_curvature', 'surface_normal'") &&
                               Catch::Contains("absent from the checkpoint"));
    }
  }
  SECTION("a field the checkpoint holds but this run does not checkpoint") {
    sim::DynamicParticles plain;  // no "stress" field
    for (std::size_t i = 0; i < 50; ++i) plain.add(sim::Vec3::Zero(), sim::Vec3::Zero(), 0, 0);
    CHECK_THROWS_WITH(readCheckpoint(dir / "checkpoint.h5",
                                     {{"fluid", &plain.fields}, {"wall", &otherWalls.fields}}),
                      Catch::Contains("'stress'") && Catch::Contains("does not checkpoint them"));
  }
  SECTION("a different particle count") {
    sim::DynamicParticles bigger;
    iotest::fillFluid(bigger, 51, 5);
    CHECK_THROWS_WITH(readCheckpoint(dir / "checkpoint.h5",
                                     {{"fluid", &bigger.fields}, {"wall", &otherWalls.fields}}),
                      Catch::Contains("/groups/fluid/position") &&
                          Catch::Contains("holds 50 particles") &&
                          Catch::Contains("this run has 51"));
  }
  SECTION("a group the checkpoint lacks, or one it has that the run lacks") {
    CHECK_THROWS_WITH(
        readCheckpoint(
            dir / "checkpoint.h5",
            {{"fluid", &other.fields}, {"wall", &otherWalls.fields}, {"tissue", &other.fields}}),
        Catch::Contains("/groups/tissue") && Catch::Contains("not in the checkpoint"));
    CHECK_THROWS_WITH(readCheckpoint(dir / "checkpoint.h5", {{"fluid", &other.fields}}),
                      Catch::Contains("'wall'") && Catch::Contains("does not have"));
  }
  SECTION("a file that is not a checkpoint") {
    CHECK_THROWS_WITH(readCheckpoint(dir / "nothing.h5", {}),
                      Catch::Contains("nothing.h5") && Catch::Contains("no checkpoint"));
    std::ofstream(dir / "junk.h5") << "junk";
    CHECK_THROWS_WITH(readCheckpoint(dir / "junk.h5", {}),
                      Catch::Contains("junk.h5") && Catch::Contains("cannot open checkpoint"));
  }
  CHECK(other.x == before);  // validation happens before anything is restored
}

TEST_CASE("a leftover checkpoint.h5.tmp does not affect the previous checkpoint", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid;
  sim::WallParticles walls;
  iotest::fillFluid(fluid, 200, 1);
  iotest::fillWall(walls, 30, 2);
  CheckpointState state = sampleState(fluid, walls);
  state.step = 100;
  writeCheckpoint(dir / "checkpoint.h5", state);

  // What a writer killed mid-write leaves: the first half of a newer checkpoint as .tmp.
  iotest::fillFluid(fluid, 200, 9);
  state.step = 200;
  writeCheckpoint(dir / "newer.h5", state);
  const std::string newer = iotest::readFile(dir / "newer.h5");
  std::ofstream(dir / "checkpoint.h5.tmp", std::ios::binary)
      .write(newer.data(), static_cast<std::streamsize>(newer.size() / 2));

  sim::DynamicParticles restored;
  sim::WallParticles restoredWalls;
  iotest::fillFluid(restored, 200, 5);
  iotest::fillWall(restoredWalls, 30, 6);
  const auto read = readCheckpoint(dir / "checkpoint.h5",
                                   {{"fluid", &restored.fields}, {"wall", &restoredWalls.fields}});
  CHECK(read.step == 100);
  iotest::fillFluid(fluid, 200, 1);
  CHECK(restored.x == fluid.x);

  // The next checkpoint simply replaces the stale .tmp.
  writeCheckpoint(dir / "checkpoint.h5", state);
  CHECK(readCheckpoint(dir / "checkpoint.h5",
                       {{"fluid", &restored.fields}, {"wall", &restoredWalls.fields}})
            .step == 200);
  CHECK_FALSE(std::filesystem::exists(dir / "checkpoint.h5.tmp"));
}

TEST_CASE("a writer killed while checkpointing leaves the last complete checkpoint", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  constexpr std::size_t kParticles = 20000;  // ~3 MB per checkpoint: the kill lands mid-write
  int pipeFds[2];
  REQUIRE(pipe(pipeFds) == 0);
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    close(pipeFds[0]);
    try {
      sim::DynamicParticles fluid;
      sim::WallParticles walls;
      iotest::fillWall(walls, 10, 0);
      for (std::int64_t step = 1;; ++step) {
        iotest::fillFluid(fluid, kParticles, static_cast<std::uint64_t>(step));
        CheckpointState state;
        state.step = step;
        state.groups = {{"fluid", &fluid.fields}, {"wall", &walls.fields}};
        writeCheckpoint(dir / "checkpoint.h5", state);
        if (write(pipeFds[1], &step, sizeof step) != sizeof step) _exit(3);
      }
    } catch (...) {
      _exit(2);
    }
  }
  close(pipeFds[1]);
  std::int64_t lastReported = 0;
  for (int k = 0; k < 3; ++k)
    REQUIRE(read(pipeFds[0], &lastReported, sizeof lastReported) == sizeof lastReported);
  usleep(7000);  // into the middle of a later checkpoint (one takes tens of ms here)
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  CHECK(WIFSIGNALED(status));
  std::int64_t step = 0;
  while (read(pipeFds[0], &step, sizeof step) == sizeof step) lastReported = step;
  close(pipeFds[0]);

  sim::DynamicParticles fluid, expected;
  sim::WallParticles walls;
  iotest::fillFluid(fluid, kParticles, 0);
  iotest::fillWall(walls, 10, 0);
  const auto read =
      readCheckpoint(dir / "checkpoint.h5", {{"fluid", &fluid.fields}, {"wall", &walls.fields}});
  // The checkpoint is the last one reported complete, or one the kill caught after its rename
  // but before it could report.
  CHECK(read.step >= lastReported);
  CHECK(read.step <= lastReported + 1);
  iotest::fillFluid(expected, kParticles, static_cast<std::uint64_t>(read.step));
  CHECK(fluid.x == expected.x);
  CHECK(fluid.fields.get<sim::Mat3>("stress") == expected.fields.get<sim::Mat3>("stress"));
}

TEST_CASE("a checkpoint with a flipped bit in its particle data is refused", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid, restored;
  sim::WallParticles walls, restoredWalls;
  iotest::fillFluid(fluid, 400, 21);
  iotest::fillWall(walls, 300, 22);
  const std::filesystem::path path = dir / "checkpoint.h5";
  writeCheckpoint(path, sampleState(fluid, walls));

  // HDF5 checksums its metadata only: flip one bit inside the stored positions (found by their
  // bytes; datasets are contiguous), as a damaged disk or a copy gone wrong would.
  std::string bytes = iotest::readFile(path);
  const sim::FieldBase& positions = *fluid.fields.find("position");
  const std::string first(static_cast<const char*>(positions.rawData()), 3 * sizeof(sim::Real));
  const std::size_t at = bytes.find(first);
  REQUIRE(at != std::string::npos);
  bytes[at + 5] = static_cast<char>(bytes[at + 5] ^ 0x10);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;

  iotest::fillFluid(restored, 400, 99);
  iotest::fillWall(restoredWalls, 300, 98);
  CHECK_THROWS_WITH(
      readCheckpoint(path, {{"fluid", &restored.fields}, {"wall", &restoredWalls.fields}}),
      Catch::Contains("checkpoint.h5") && Catch::Contains("do not match its checksum"));
}
