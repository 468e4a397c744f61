// The equilibrium interfaces as a ParaView time series: interfaces.h5 holds each posture's surface
// bit for bit, interfaces.xmf is well-formed XML whose Triangle grids reference existing datasets
// of the stated shape, postures without an interface are left out, and a failure names the file.
#include <catch2/catch.hpp>

#include <hdf5.h>

#include <filesystem>

#include "io_test_support.h"
#include "protocols/io/interface_series.h"
#include "protocols/io/io_error.h"
#include "tests/support/scratch_directory.h"

namespace {

protocols::PostureInterface tetrahedron(const std::string& name, double time, double scale) {
  protocols::PostureInterface p{name, time, {}, {}};
  p.vertices = {sim::Vec3(0, 0, 0), sim::Vec3(scale, 0, 0), sim::Vec3(0, scale, 0),
                sim::Vec3(0, 0, 1.0 / 3.0)};
  p.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return p;
}

template <class T>
std::vector<T> readAll(hid_t file, const std::string& path, hid_t memoryType, std::size_t count) {
  std::vector<T> out(count);
  const hid_t dataset = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  REQUIRE(dataset >= 0);
  REQUIRE(H5Dread(dataset, memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) >= 0);
  H5Dclose(dataset);
  return out;
}

}  // namespace

TEST_CASE("equilibrium interfaces: one Triangle grid per posture, bit for bit", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  const std::vector<protocols::PostureInterface> postures = {
      tetrahedron("supine", 0.0, 1e-3 / 7.0),
      {"full fill", 1.0, {}, {}},
      tetrahedron("upright", 2.0, 0.1 + 1e-17)};
  protocols::writeInterfaceSeries(dir.path(), postures);
  CHECK_FALSE(std::filesystem::exists(dir / "interfaces.h5.tmp"));
  CHECK_FALSE(std::filesystem::exists(dir / "interfaces.xmf.tmp"));

  const std::string xml = iotest::readFile(dir / "interfaces.xmf");
  std::vector<iotest::XmlElement> elements;
  const std::string problem = iotest::checkXml(xml, &elements);
  INFO(problem);
  REQUIRE(problem.empty());
  int times = 0, triangles = 0, uniform = 0;
  std::vector<std::string> names;
  for (const auto& e : elements) {
    times += e.name == "Time";
    if (e.name == "Topology") {
      CHECK(e.attributes.at("TopologyType") == "Triangle");
      CHECK(e.attributes.at("NumberOfElements") == "4");
      ++triangles;
    }
    if (e.name == "Grid" && e.attributes.at("GridType") == "Uniform") {
      ++uniform;
      names.push_back(e.attributes.at("Name"));
    }
  }
  // The full fill (no interface) is left out: two postures, each one surface at its own time.
  CHECK(times == 2);
  CHECK(triangles == 2);
  CHECK(uniform == 2);
  CHECK(names == std::vector<std::string>{"supine", "upright"});
  CHECK(xml.find("<Time Value=\"2\"/>") != std::string::npos);

  const hid_t file = H5Fopen((dir / "interfaces.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  for (const auto& e : elements) {
    if (e.name != "DataItem") continue;
    const auto colon = e.text.find(':');
    REQUIRE(colon != std::string::npos);
    CHECK(e.text.substr(0, colon) == "interfaces.h5");  // relative: the folder can move
    const iotest::DatasetCheck found = iotest::inspectDataset(file, e.text.substr(colon + 1));
    INFO(e.text);
    REQUIRE(found.rows >= 0);
    CHECK(e.attributes.at("Dimensions") ==
          std::to_string(found.rows) + " " + std::to_string(found.columns));
    CHECK(e.attributes.at("NumberType") == (found.isInteger ? "Int" : "Float"));
  }
  // The stored values are the given ones, bit for bit (posture index 2 keeps its number).
  const auto vertices = readAll<double>(file, "/postures/002/vertices", H5T_NATIVE_DOUBLE, 12);
  const auto faces = readAll<int>(file, "/postures/002/triangles", H5T_NATIVE_INT, 12);
  for (std::size_t v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) CHECK(vertices[3 * v + c] == postures[2].vertices[v][c]);
  for (std::size_t t = 0; t < 4; ++t)
    for (int c = 0; c < 3; ++c) CHECK(faces[3 * t + c] == postures[2].triangles[t][c]);
  H5Fclose(file);
}

TEST_CASE("equilibrium interfaces: nothing to write, or an unwritable folder", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  protocols::writeInterfaceSeries(dir.path(), {{"full fill", 0.0, {}, {}}});
  CHECK_FALSE(std::filesystem::exists(dir / "interfaces.h5"));
  CHECK_FALSE(std::filesystem::exists(dir / "interfaces.xmf"));
  const std::filesystem::path missing = dir / "no such folder";
  CHECK_THROWS_WITH(protocols::writeInterfaceSeries(missing, {tetrahedron("supine", 0.0, 1.0)}),
                    Catch::Contains("interfaces.h5") && Catch::Contains("writable"));
}
