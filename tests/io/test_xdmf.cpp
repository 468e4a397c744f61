// The XDMF sidecar: well-formed XML, a Temporal collection with one grid per group per frame,
// relative HDF5 references that all resolve to datasets of the stated shape, and replaced
// atomically (no .tmp left behind).
#include <catch2/catch.hpp>

#include <hdf5.h>

#include <cstdlib>

#include "io_test_support.h"
#include "protocols/io/frame_writer.h"
#include "protocols/io/xdmf_document.h"
#include "tests/support/scratch_directory.h"

TEST_CASE("the XML checker used below rejects malformed documents", "[unit][io]") {
  // The checker is the oracle of the next test, so it must be able to fail.
  CHECK(iotest::checkXml("<a><b x=\"1\"/></a>", nullptr).empty());
  CHECK_FALSE(iotest::checkXml("<a><b></a>", nullptr).empty());
  CHECK_FALSE(iotest::checkXml("<a x=1/>", nullptr).empty());
  CHECK_FALSE(iotest::checkXml("<a x=\"1\" x=\"2\"/>", nullptr).empty());
  CHECK_FALSE(iotest::checkXml("<a>&nbsp;</a>", nullptr).empty());
  CHECK_FALSE(iotest::checkXml("<a/><b/>", nullptr).empty());
  CHECK_FALSE(iotest::checkXml("<a>1 < 2</a>", nullptr).empty());
}

TEST_CASE("the XDMF sidecar is well-formed and references only existing datasets", "[unit][io]") {
  const tamponade_test::ScratchDirectory dir("tamponade-io");
  sim::DynamicParticles fluid;
  sim::WallParticles walls;
  iotest::fillWall(walls, 120, 1);
  // A per-frame wall field (as coverage will add) besides the static ones.
  auto& oil = walls.fields.add<sim::Real>({"wall_oil_fraction", "1", false, true});
  {
    protocols::FrameWriter writer(dir / "frames.h5", {});
    // Static wall data: positions, tags. The per-frame field is written every frame.
    sim::WallParticles staticPart;
    iotest::fillWall(staticPart, 120, 1);
    writer.writeStatic("wall", staticPart.fields);
    for (int f = 0; f < 3; ++f) {
      iotest::fillFluid(fluid, 200, f);
      for (std::size_t i = 0; i < oil.size(); ++i) oil[i] = 0.01 * f;
      writer.writeFrame(0.5 * f, 10 * f, {{"fluid", &fluid.fields}, {"wall", &walls.fields}});
      CHECK_FALSE(std::filesystem::exists(dir / "frames.xmf.tmp"));
    }
  }
  const std::string xml = iotest::readFile(dir / "frames.xmf");
  std::vector<iotest::XmlElement> elements;
  const std::string problem = iotest::checkXml(xml, &elements);
  INFO(problem);
  REQUIRE(problem.empty());

  // Also through xmllint (libxml2-utils) when it is installed: an independent parser.
  if (std::system("command -v xmllint >/dev/null 2>&1") == 0) {
    const std::string command = "xmllint --noout '" + (dir / "frames.xmf").string() + "' 2>&1";
    CHECK(std::system(command.c_str()) == 0);
  } else {
    WARN("xmllint not installed (package libxml2-utils): only the built-in checker ran");
  }

  // Structure: Xdmf/Domain/Grid(Temporal) with 3 Spatial collections, each with fluid + wall.
  int temporal = 0, spatial = 0, uniform = 0, times = 0;
  for (const auto& e : elements) {
    if (e.name != "Grid" && e.name != "Time") continue;
    if (e.name == "Time") {
      ++times;
      continue;
    }
    const std::string type = e.attributes.count("GridType") ? e.attributes.at("GridType") : "";
    const std::string collection =
        e.attributes.count("CollectionType") ? e.attributes.at("CollectionType") : "";
    if (collection == "Temporal") ++temporal;
    if (collection == "Spatial") ++spatial;
    if (type == "Uniform") ++uniform;
  }
  CHECK(temporal == 1);
  CHECK(spatial == 3);
  CHECK(uniform == 6);
  CHECK(times == 3);
  CHECK(elements.front().name == "Xdmf");

  hid_t file = H5Fopen((dir / "frames.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  int references = 0;
  bool sawStaticPosition = false, sawFrameWallField = false;
  for (const auto& e : elements) {
    if (e.name != "DataItem") continue;
    ++references;
    INFO(e.text);
    CHECK(e.attributes.at("Format") == "HDF");
    // Relative reference: "frames.h5:/path", no directory part, so the run folder can move.
    const auto colon = e.text.find(':');
    REQUIRE(colon != std::string::npos);
    CHECK(e.text.substr(0, colon) == "frames.h5");
    const std::string path = e.text.substr(colon + 1);
    sawStaticPosition |= path == "/static/wall/position";
    sawFrameWallField |= path.find("/wall/wall_oil_fraction") != std::string::npos;
    const iotest::DatasetCheck found = iotest::inspectDataset(file, path);
    REQUIRE(found.rows >= 0);  // the dataset exists
    // Dimensions are the dataset's exact shape, "rows components" (scalars are rows x 1).
    CHECK(e.attributes.at("Dimensions") ==
          std::to_string(found.rows) + " " + std::to_string(found.columns));
    CHECK(e.attributes.at("NumberType") == (found.isInteger ? "Int" : "Float"));
    CHECK(e.attributes.at("Precision") == std::to_string(found.bytes));
  }
  H5Fclose(file);
  CHECK(sawStaticPosition);
  CHECK(sawFrameWallField);
  // fluid: position + 6 other written fields; wall: static position/tag + wall_oil_fraction.
  CHECK(references == 3 * (7 + 3));
}

TEST_CASE("XDMF text escapes names and keeps times exact", "[unit][io]") {
  protocols::XdmfFrame frame;
  frame.time = 0.1 + 0.2;
  frame.step = 3;
  protocols::XdmfGrid grid;
  grid.name = "oil & <aqueous>";
  grid.position = {"position", "/frames/000000/x", 2, 3, sim::ScalarKind::kReal, 8};
  frame.grids.push_back(grid);
  const std::string xml =
      protocols::formatXdmfDocument({protocols::formatXdmfFrame(frame, "fr\"ames.h5")});
  std::vector<iotest::XmlElement> elements;
  REQUIRE(iotest::checkXml(xml, &elements).empty());
  bool sawTime = false;
  for (const auto& e : elements) {
    if (e.name == "Time") {
      sawTime = true;
      CHECK(std::strtod(e.attributes.at("Value").c_str(), nullptr) == 0.1 + 0.2);
    }
    if (e.name == "Grid" && e.attributes.at("GridType") == "Uniform")
      CHECK(e.attributes.at("Name") == "oil & <aqueous>");
    if (e.name == "DataItem") CHECK(e.text == "fr\"ames.h5:/frames/000000/x");
  }
  CHECK(sawTime);
}
