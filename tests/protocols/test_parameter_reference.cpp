// The parameter table is the single source of the docs' reference: docs/protocols.md must hold
// exactly what the code generates (regenerate with `tamponade validate --reference`).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

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

TEST_CASE("the protocol's solver and effect names are the engine registry's", "[unit][protocol]") {
  // The protocol format lists its choices as constants (the parameter table and the error
  // messages need them at compile time); the engine's registries are what runs. A solver or
  // effect added to one and not the other fails here instead of at a user's protocol.
  std::set<std::string_view> registered;
  for (const auto& entry : sim::solverRegistry()) registered.insert(entry.name);
  const std::set<std::string_view> offered(protocols::kSolverNames.begin(),
                                           protocols::kSolverNames.end());
  CHECK(offered == registered);
  std::set<std::string_view> effects;
  for (const auto& entry : sim::effectRegistry()) effects.insert(entry.name);
  for (std::string_view name : protocols::kEffectNames) {
    INFO("[effects] " << name);
    CHECK(effects.count(name) == 1);
  }
}
