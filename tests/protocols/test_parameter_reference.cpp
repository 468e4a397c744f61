// The parameter table is the single source of the docs' reference: docs/protocols.md must hold
// exactly what the code generates (regenerate with `tamponade validate --reference`).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "protocols/format/parameter_table.h"
#include "protocols/format/protocol.h"
#include "sim/world/stage_registry.h"

namespace {

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The text between `<!-- begin NAME -->\n` and `<!-- end NAME -->` of the document.
std::string section(const std::string& doc, const std::string& name) {
  const std::string begin = "<!-- begin " + name + " -->\n";
  const std::size_t from = doc.find(begin);
  const std::size_t to = doc.find("<!-- end " + name + " -->");
  if (from == std::string::npos || to == std::string::npos || to < from) return "(markers missing)";
  return doc.substr(from + begin.size(), to - from - begin.size());
}

}  // namespace

TEST_CASE("docs/protocols.md holds the generated reference tables", "[unit][protocol][docs]") {
  const std::string doc =
      readFile(std::filesystem::path(TAMPONADE_SOURCE_DIR) / "docs" / "protocols.md");
  INFO("regenerate the tables with: tamponade validate --reference");
  CHECK(section(doc, "parameter-reference") == protocols::renderParameterReference());
  CHECK(section(doc, "unit-table") == protocols::renderUnitTable());
  CHECK(section(doc, "accuracy-presets") == protocols::renderAccuracyPresetTable());
}

TEST_CASE("the parameter table is complete and consistent", "[unit][protocol]") {
  std::set<std::string_view> keys;
  for (const protocols::ParameterSpec& spec : protocols::parameterTable()) {
    INFO(spec.key);
    CHECK(keys.insert(spec.key).second);  // unique
    CHECK_FALSE(spec.doc.empty());
    CHECK(spec.min <= spec.max);
    // Every key lives in a table that is itself described.
    const std::size_t dot = spec.key.rfind('.');
    if (dot != std::string_view::npos) {
      const auto& parent = protocols::parameterSpec(spec.key.substr(0, dot));
      CHECK((parent.kind == protocols::ValueKind::kTable ||
             parent.kind == protocols::ValueKind::kTableArray));
    }
    if (spec.kind == protocols::ValueKind::kChoice) CHECK_FALSE(spec.choices.empty());
    if (spec.requirement == protocols::Requirement::kConditional)
      CHECK_FALSE(spec.condition.empty());
    const bool isContainer =
        spec.kind == protocols::ValueKind::kTable || spec.kind == protocols::ValueKind::kTableArray;
    if (!isContainer) CHECK_FALSE(spec.example.empty());
  }
  CHECK_THROWS_AS(protocols::parameterSpec("no.such.key"), std::logic_error);
}

TEST_CASE("the protocol's solver choices and [effects] keys come from the engine's registries",
          "[unit][protocol]") {
  // The registries are the only list: the protocol's `solver` choices are every registered
  // solver, and its [effects] keys exactly the effects the registry lets a caller force, each
  // documented in the reference by the registry's own description.
  std::vector<std::string_view> solvers;
  for (const auto& entry : sim::solverRegistry()) solvers.push_back(entry.name);
  const std::span<const std::string_view> choices = protocols::parameterSpec("solver").choices;
  CHECK(std::vector<std::string_view>(choices.begin(), choices.end()) == solvers);
  std::vector<std::string_view> forceable;
  for (const auto& entry : sim::effectRegistry())
    if (entry.forceable()) {
      forceable.push_back(entry.name);
      const protocols::ParameterSpec& row = protocols::parameterSpec("effects." + entry.name);
      CHECK(row.kind == protocols::ValueKind::kEffectSwitch);
      CHECK(row.doc.find(entry.inferredWhen) != std::string_view::npos);
    }
  CHECK(protocols::childKeys("effects") == forceable);
  CHECK(forceable.size() >= 6);  // tension, background pressure, wetting, viscosities, elasticity
}
