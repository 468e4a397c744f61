// Every protocol shipped in data/protocols is assembled and run, not only parsed: a change that
// breaks one example's assembly (a mesh eye, elastic tissue, a custom agent, equilibrium
// postures) fails here instead of in a user's first command. At a 1.5 mm trial spacing, so that
// each takes seconds; the physics at the presets' spacings is checked by the validation label.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "protocols/assembly/assemble_scenario.h"
#include "protocols/equilibrium/posture_equilibrium.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/run/run_equilibrium.h"
#include "protocols/run/run_scenario.h"
#include "tests/support/scratch_directory.h"

namespace fs = std::filesystem;
using namespace protocols;

namespace {

const fs::path kProtocolDir = fs::path(TAMPONADE_SOURCE_DIR) / "data" / "protocols";
// [m] a trial spacing (the draft preset's is 0.8 mm): a few thousand particles per eye.
constexpr double kTrialSpacing = 1.5e-3;
// Steps run: a stop takes effect at a checkpointable step, every 16 steps (the Z-sort interval).
constexpr long kSteps = 16;

std::vector<fs::path> exampleProtocols() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kProtocolDir))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("every shipped example protocol assembles and runs", "[unit][examples]") {
  const std::vector<fs::path> files = exampleProtocols();
  REQUIRE(files.size() >= 10);
  const tamponade_test::ScratchDirectory scratch("tamponade_test_example_runs");
  int count = 0;
  for (const fs::path& file : files) {
    INFO(file.filename().string());
    Protocol protocol = parseProtocol(file);
    protocol.accuracy.particleSpacing.value = kTrialSpacing;
    Scenario scenario = assembleScenario(protocol);
    CHECK(scenario.world->particles.size() > 100);
    // A fresh output folder for each example: a run refuses one holding another protocol's files.
    const fs::path out = scratch / std::to_string(count++);
    fs::create_directories(out);
    RunOptions run;
    run.outputFolder = out;
    if (isEquilibriumSchedule(scenario)) {
      const RunSummary summary = runEquilibriumSchedule(protocol, scenario, run, {});
      CHECK(summary.retinaCoverage > 0.0);
      CHECK(summary.retinaCoverage <= 1.0);
    } else {
      run.stopAfterSteps = kSteps;
      const RunSummary summary = runScenario(protocol, scenario, run);
      CHECK(summary.stopped);
      CHECK(summary.steps == kSteps);
      CHECK(std::isfinite(summary.simulatedTime));
      CHECK(summary.simulatedTime > 0.0);
      for (const sim::Vec3& v : scenario.world->particles.v) REQUIRE(v.allFinite());
    }
  }
}
