// Frames: what goes in comes back bit for bit, with units, attributes and metadata; the layout
// (gzip + shuffle, chunked) is what the header promises; series tables; resume truncation; and
// bad use gets an IoError naming the file and the object.
#include <catch2/catch.hpp>

#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include "io_test_support.h"
#include "protocols/io/frame_reader.h"
#include "protocols/io/frame_writer.h"
#include "protocols/io/io_error.h"
#include "tests/support/scratch_directory.h"

using protocols::FrameReader;
using protocols::FrameWriter;
using protocols::IoError;

namespace {

protocols::RunMetadata sampleMetadata() {
  protocols::RunMetadata meta;
  meta.protocolText = "format = 1\n[eye]\nkind = \"emmetropic\"  # <&> \"quoted\"\n";
  meta.strings["protocol_file"] = "data/protocols/emmetropic.toml";
  meta.numbers["particle_spacing [m]"] = 2.5e-4;
  return meta;
}

// Checks every written field of `registry` against frame `index`, group `group`, bit for bit.
void requireFrameMatches(const FrameReader& reader, std::size_t index, const std::string& group,
                         const sim::FieldRegistry& registry,
                         const std::vector<std::string>& skipped = {}) {
  std::vector<std::string> expected;
  for (const auto& field : registry) {
    const auto& info = field->info();
    if (!info.written || std::find(skipped.begin(), skipped.end(), info.name) != skipped.end())
      continue;
    expected.push_back(info.name);
    INFO("frame " << index << " " << group << "/" << info.name);
    const protocols::FieldData data = reader.readField(index, group, info.name);
    CHECK(data.unit == info.unit);
    CHECK(iotest::sameBits(data, *field));
  }
  std::sort(expected.begin(), expected.end());
  CHECK(reader.fieldNames(index, group) == expected);  // and nothing that is not `written`
}

}  // namespace

TEST_CASE("frames round trip bit-identically with units, times and metadata", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid;
  sim::WallParticles walls;
  iotest::fillWall(walls, 300, 7);

  std::vector<std::vector<std::uint8_t>> snapshots;
  {
    FrameWriter writer(dir / "frames.h5", sampleMetadata());
    writer.writeStatic("wall", walls.fields);
    for (int f = 0; f < 3; ++f) {
      iotest::fillFluid(fluid, 400, 100 + f);
      // A per-frame wall field next to the static ones: written into the frame, not /static.
      CHECK(writer.writeFrame(0.125 * f, 1000 * f,
                              {{"fluid", &fluid.fields}, {"wall", &walls.fields}}) ==
            static_cast<std::size_t>(f));
    }
    REQUIRE(writer.frames().size() == 3);
  }

  FrameReader reader(dir / "frames.h5");
  REQUIRE(reader.frames().size() == 3);
  CHECK(reader.unreadableFrames().empty());
  for (int f = 0; f < 3; ++f) {
    const auto& info = reader.frames()[f];
    CHECK(info.index == static_cast<std::size_t>(f));
    CHECK(info.time == 0.125 * f);  // exact: stored as float64
    CHECK(info.step == 1000 * f);
    CHECK(info.groups == std::vector<std::string>{"fluid", "wall"});
    iotest::fillFluid(fluid, 400, 100 + f);  // regenerate frame f's state
    requireFrameMatches(reader, f, "fluid", fluid.fields);
    // Every written wall field went to /static, so the frame's wall group holds none.
    CHECK(reader.fieldNames(f, "wall").empty());
  }
  CHECK(reader.staticGroups() == std::vector<std::string>{"wall"});
  for (const auto& field : walls.fields) {
    if (!field->info().written) continue;
    const auto data = reader.readStaticField("wall", field->info().name);
    CHECK(iotest::sameBits(data, *field));
    CHECK(data.unit == field->info().unit);
  }

  const protocols::RunInfo run = reader.runInfo();
  CHECK(run.protocolText == sampleMetadata().protocolText);
  CHECK(run.strings.at("protocol_file") == "data/protocols/emmetropic.toml");
  CHECK(run.numbers.at("particle_spacing [m]") == 2.5e-4);
  CHECK(run.toolkitVersion == TAMPONADE_TEST_VERSION);
  CHECK(run.hdf5Version.rfind("1.", 0) == 0);
  CHECK(run.createdUtc.size() == 20);  // 2026-11-22T01:50:14Z
  CHECK(run.units.at("fluid").at("velocity") == "m/s");
  CHECK(run.units.at("fluid").at("stress") == "Pa");
  CHECK(run.units.at("wall").at("position") == "m");
  CHECK(run.units.at("fluid").count("scratch") == 0);  // not written, so not listed
}

TEST_CASE("frame datasets are chunked, shuffled and gzip-4 compressed", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid;
  iotest::fillFluid(fluid, 500, 1);
  // Compressible positions (a lattice), as in a real run, to see that compression happens.
  for (std::size_t i = 0; i < fluid.size(); ++i)
    fluid.x[i] = sim::Vec3(i % 10, (i / 10) % 10, i / 100.0) * 1e-4;
  {
    FrameWriter writer(dir / "frames.h5", {});
    writer.writeFrame(0, 0, {{"fluid", &fluid.fields}});
  }
  hid_t file = H5Fopen((dir / "frames.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  hid_t dataset = H5Dopen2(file, "/frames/000000/fluid/position", H5P_DEFAULT);
  REQUIRE(dataset >= 0);
  hid_t creation = H5Dget_create_plist(dataset);
  CHECK(H5Pget_layout(creation) == H5D_CHUNKED);
  hsize_t chunk[2] = {0, 0};
  CHECK(H5Pget_chunk(creation, 2, chunk) == 2);
  CHECK(chunk[0] == 500);  // whole field in one chunk below 512 KiB
  CHECK(chunk[1] == 3);
  REQUIRE(H5Pget_nfilters(creation) == 2);
  unsigned flags = 0;
  std::size_t count = 1;
  unsigned level = 0;
  std::size_t none = 0;
  CHECK(H5Pget_filter2(creation, 0, &flags, &none, nullptr, 0, nullptr, nullptr) ==
        H5Z_FILTER_SHUFFLE);
  CHECK(H5Pget_filter2(creation, 1, &flags, &count, &level, 0, nullptr, nullptr) ==
        H5Z_FILTER_DEFLATE);
  CHECK(level == 4);
  hid_t type = H5Dget_type(dataset);
  CHECK(H5Tequal(type, H5T_IEEE_F64LE) > 0);
  // Lattice positions must compress (a stored size below the logical size proves the filter
  // ran; the exact ratio depends on zlib and is not asserted).
  CHECK(H5Dget_storage_size(dataset) < 500 * 3 * sizeof(double));
  H5Tclose(type);
  H5Pclose(creation);
  H5Dclose(dataset);
  H5Fclose(file);
}

TEST_CASE("float32 frames store each value rounded to float", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid;
  iotest::fillFluid(fluid, 200, 3);
  for (std::size_t i = 0; i < fluid.size(); ++i)
    fluid.x[i] = sim::Vec3(std::sin(i), std::cos(i), std::sqrt(i)) * 1e-3;
  protocols::FrameWriterOptions options;
  options.precision = protocols::FramePrecision::kFloat32;
  {
    FrameWriter writer(dir / "frames.h5", {}, options);
    writer.writeFrame(0, 0, {{"fluid", &fluid.fields}});
  }
  FrameReader reader(dir / "frames.h5");
  const auto x = reader.readField(0, "fluid", "position");
  REQUIRE(x.rows == fluid.size());
  bool allRounded = true;
  for (std::size_t i = 0; i < fluid.size(); ++i)
    for (int c = 0; c < 3; ++c)
      allRounded &= x.real(i, c) == static_cast<double>(static_cast<float>(fluid.x[i][c]));
  CHECK(allRounded);  // HDF5's conversion is IEEE round-to-nearest, the same as the cast
  const auto ids = reader.readField(0, "fluid", "id");
  CHECK(iotest::sameBits(ids, *fluid.fields.find("id")));  // integers stay exact
}

TEST_CASE("series tables append rows and keep their columns", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  {
    FrameWriter writer(dir / "frames.h5", {});
    for (int r = 0; r < 70; ++r)  // more than one 64-row chunk
      writer.appendSeries("coverage", 0.5 * r, {r / 70.0, 1.0 - r / 70.0}, {"retina", "break 1"},
                          {"1", "1"});
    writer.appendSeries("energy", 0.0, {1.5}, {"kinetic"});
    try {
      writer.appendSeries("coverage", 99.0, {1.0}, {"retina"});
      FAIL("a row with other columns was accepted");
    } catch (const IoError& e) {
      CHECK_THAT(e.what(),
                 Catch::Contains("/series/coverage") && Catch::Contains("columns differ"));
    }
  }
  FrameReader reader(dir / "frames.h5");
  CHECK(reader.seriesNames() == std::vector<std::string>{"coverage", "energy"});
  const auto coverage = reader.readSeries("coverage");
  CHECK(coverage.columns == std::vector<std::string>{"time", "retina", "break 1"});
  CHECK(coverage.units == std::vector<std::string>{"s", "1", "1"});
  REQUIRE(coverage.rows == 70);
  const auto retina = coverage.column("retina");
  const auto time = coverage.column("time");
  for (int r = 0; r < 70; ++r) {
    CHECK(time[r] == 0.5 * r);
    CHECK(retina[r] == r / 70.0);
  }
  CHECK(reader.readSeries("energy").units == std::vector<std::string>{"s", ""});
}

TEST_CASE("resuming drops frames and series rows after the checkpoint", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid;
  sim::WallParticles walls;
  iotest::fillWall(walls, 50, 2);
  {
    FrameWriter writer(dir / "frames.h5", {});
    writer.writeStatic("wall", walls.fields);
    for (int f = 0; f < 4; ++f) {
      iotest::fillFluid(fluid, 100, f);
      writer.writeFrame(0.1 * f, 10 * f, {{"fluid", &fluid.fields}});
      writer.appendSeries("coverage", 0.1 * f, {f * 1.0}, {"retina"});
    }
  }
  {
    // Checkpoint at step 10 (time 0.1): frames 0, 1 and rows 0, 1 stay.
    FrameWriter writer = FrameWriter::resume(dir / "frames.h5", 10, 0.1);
    REQUIRE(writer.frames().size() == 2);
    for (int f = 2; f < 4; ++f) {
      iotest::fillFluid(fluid, 100, 50 + f);
      CHECK(writer.writeFrame(0.1 * f, 10 * f, {{"fluid", &fluid.fields}}) ==
            static_cast<std::size_t>(f));
      writer.appendSeries("coverage", 0.1 * f, {f * 10.0}, {"retina"});
    }
  }
  FrameReader reader(dir / "frames.h5");
  REQUIRE(reader.frames().size() == 4);
  iotest::fillFluid(fluid, 100, 1);
  requireFrameMatches(reader, 1, "fluid", fluid.fields);
  iotest::fillFluid(fluid, 100, 53);
  requireFrameMatches(reader, 3, "fluid", fluid.fields);
  CHECK(reader.readSeries("coverage").column("retina") == std::vector<double>{0, 1, 20, 30});
  // The rebuilt sidecar lists all four frames, each with the static wall grid.
  const std::string xmf = iotest::readFile(dir / "frames.xmf");
  CHECK(xmf.find("/frames/000003/fluid/position") != std::string::npos);
  CHECK(xmf.find("frames.h5:/static/wall/position") != std::string::npos);
}

TEST_CASE("bad use of frame files is reported with file and object", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid;
  iotest::fillFluid(fluid, 10, 1);
  {
    FrameWriter writer(dir / "frames.h5", {});
    writer.writeFrame(0, 0, {{"fluid", &fluid.fields}});
  }

  SECTION("an existing file is not overwritten unless asked") {
    try {
      FrameWriter writer(dir / "frames.h5", {});
      FAIL("existing file replaced");
    } catch (const IoError& e) {
      CHECK_THAT(e.what(), Catch::Contains("frames.h5") && Catch::Contains("exists already"));
    }
    protocols::FrameWriterOptions options;
    options.overwrite = true;
    FrameWriter writer(dir / "frames.h5", {}, options);
    CHECK(FrameReader(dir / "frames.h5").frames().empty());
  }
  SECTION("a missing field names the dataset path") {
    FrameReader reader(dir / "frames.h5");
    try {
      reader.readField(0, "fluid", "pressure");
      FAIL("missing field read");
    } catch (const IoError& e) {
      CHECK(e.object() == "/frames/000000/fluid/pressure");
      CHECK_THAT(e.what(), Catch::Contains("no such field dataset"));
    }
    CHECK_THROWS_WITH(reader.readField(5, "fluid", "position"),
                      Catch::Contains("no complete frame 5") && Catch::Contains("numbered 0 to 0"));
  }
  SECTION("a file that is not HDF5 is rejected with HDF5's reason") {
    std::ofstream(dir / "junk.h5") << "not hdf5 at all";
    try {
      FrameReader reader(dir / "junk.h5");
      FAIL("junk opened");
    } catch (const IoError& e) {
      CHECK(e.file() == (dir / "junk.h5").string());
      CHECK_THAT(e.what(), Catch::Contains("cannot open as HDF5") && Catch::Contains("HDF5:"));
    }
  }
  SECTION("a metadata key given twice") {
    protocols::RunMetadata meta;
    meta.strings["fill"] = "90 %";
    meta.numbers["fill"] = 0.9;
    CHECK_THROWS_WITH(FrameWriter(dir / "meta.h5", meta),
                      Catch::Contains("'fill'") && Catch::Contains("both as text and as number"));
    CHECK_FALSE(std::filesystem::exists(dir / "meta.h5"));
  }
  SECTION("group names must be usable and unique") {
    FrameWriter writer(dir / "other.h5", {});
    CHECK_THROWS_WITH(writer.writeFrame(0, 0, {{"a/b", &fluid.fields}}),
                      Catch::Contains("'a/b' is not usable"));
    CHECK_THROWS_WITH(writer.writeFrame(0, 0, {{"fluid", &fluid.fields}, {"fluid", &fluid.fields}}),
                      Catch::Contains("given twice"));
    CHECK_THROWS_WITH(writer.writeFrame(NAN, 0, {{"fluid", &fluid.fields}}),
                      Catch::Contains("not finite"));
    // After the failures the next frame still gets index 0.
    CHECK(writer.writeFrame(0, 0, {{"fluid", &fluid.fields}}) == 0);
  }
}

TEST_CASE("empty particle groups are written and read back as zero rows", "[unit][io]") {
  // A scene without tissue still passes its (empty) tissue group: nothing may fail on zero rows.
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles tissue;
  {
    FrameWriter writer(dir / "frames.h5", {});
    writer.writeFrame(0, 0, {{"tissue", &tissue.fields}});
  }
  FrameReader reader(dir / "frames.h5");
  const auto x = reader.readField(0, "tissue", "position");
  CHECK(x.rows == 0);
  CHECK(x.components == 3);
  CHECK(x.reals.empty());
}

TEST_CASE("fields spanning several chunks (compressed on all threads) read back exactly",
          "[unit][io]") {
  // Above 512 KiB a field is split into chunks that are shuffled and deflated in parallel and
  // handed to HDF5 pre-filtered; reading goes through HDF5's own filters, so a byte wrong in
  // the shuffle or the zlib stream would fail here.
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid;
  iotest::fillFluid(fluid, 40000, 21);  // position 0.9 MiB = 2 chunks, stress 2.7 MiB = 6
  sim::FieldRegistry labels;
  auto& label = labels.add<std::int32_t>({"label", "1", false, true});
  labels.resize(300001);  // 1.1 MiB of int32 = 3 chunks, the last one nearly empty
  for (std::size_t i = 0; i < label.size(); ++i)
    label[i] = static_cast<std::int32_t>(i * 2654435761u);
  {
    FrameWriter writer(dir / "frames.h5", {});
    writer.writeFrame(0, 0, {{"fluid", &fluid.fields}, {"labels", &labels}});
  }
  {
    FrameReader reader(dir / "frames.h5");
    requireFrameMatches(reader, 0, "fluid", fluid.fields);
    requireFrameMatches(reader, 0, "labels", labels);
  }

  hid_t file = H5Fopen((dir / "frames.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  for (const auto& [path, chunks] :
       {std::pair{"/frames/000000/fluid/position", 2}, std::pair{"/frames/000000/fluid/stress", 6},
        std::pair{"/frames/000000/labels/label", 3}}) {
    hid_t dataset = H5Dopen2(file, path, H5P_DEFAULT);
    hid_t space = H5Dget_space(dataset);
    hsize_t count = 0;
    CHECK(H5Dget_num_chunks(dataset, space, &count) >= 0);
    H5Sclose(space);
    CHECK(count == static_cast<hsize_t>(chunks));
    H5Dclose(dataset);
  }
  H5Fclose(file);
}
