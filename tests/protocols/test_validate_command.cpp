// `tamponade validate`: exit 0 and the normalised protocol for a good file; exit 2 and every
// problem as file:line:column for a bad one, creating nothing.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/scratch_directory.h"
#include "tests/support/tamponade_command.h"

namespace fs = std::filesystem;

using tamponade_test::runTamponade;

TEST_CASE("tamponade validate: bad protocol exits 2 with file:line:column",
          "[unit][protocol][cli]") {
  const tamponade_test::ScratchDirectory scratch("tamponade_validate_cli_test");
  const std::filesystem::path& dir = scratch.path();
  std::ofstream(dir / "bad.toml") << "format_version = 1\n"
                                     "[eye]\n"
                                     "kind = \"emmetropic\"\n"
                                     "side = \"OD\"\n"
                                     "[tamponade]\n"
                                     "agent = \"silicone_oil_1000\"\n"
                                     "fill = 1.2\n"
                                     "[schedule]\n"
                                     "[[schedule.postures]]\n"
                                     "name = \"supine\"\n"
                                     "duration = \"10 min\"\n"
                                     "[outputs]\n"
                                     "folder = \"out\"\n";
  const auto r = runTamponade("validate bad.toml", dir);
  INFO(r.output);
  CHECK(r.exitCode == 2);
  CHECK(r.output.find("bad.toml:7:8: tamponade.fill = 1.2 is outside the allowed range (0, 1]") !=
        std::string::npos);
  CHECK(r.output.find("1 problem found; nothing was run.") != std::string::npos);
  // Nothing was created: the directory still holds only the protocol.
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
}

TEST_CASE("tamponade validate: good protocol exits 0 and prints SI values",
          "[unit][protocol][cli]") {
  const fs::path dir = fs::path(TAMPONADE_SOURCE_DIR) / "data" / "protocols";
  const auto r = runTamponade("validate emmetropic_superior_break.toml", dir);
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK(r.output.find("tamponade.fill = 0.9") != std::string::npos);
  CHECK(r.output.find("eye.breaks[1].posterior_to_limbus = 0.014 m") != std::string::npos);
  CHECK(r.output.find("schedule.postures[1].duration = 600 s") != std::string::npos);
}

TEST_CASE("tamponade validate: usage errors exit 2", "[unit][protocol][cli]") {
  const fs::path dir = fs::temp_directory_path();
  CHECK(runTamponade("validate", dir).exitCode == 2);
  CHECK(runTamponade("validate a.toml b.toml", dir).exitCode == 2);
  CHECK(runTamponade("validate --help", dir).exitCode == 0);
  const auto missing = runTamponade("validate /no/such/file.toml", dir);
  CHECK(missing.exitCode == 2);
  CHECK(missing.output.find("/no/such/file.toml: cannot open the protocol file") !=
        std::string::npos);
}
