#include "anatomy/material_library.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "anatomy/anatomy_error.h"

namespace anatomy {

namespace {

struct PropertySpec {
  std::string_view name;
  std::string_view unit;
  std::optional<SourcedValue> MaterialRecord::*field;
  double min, max;  // valid range, inclusive
};

constexpr double kHuge = 1e300;
const std::array<PropertySpec, 6> kProperties = {{
    {"density", "kg/m^3", &MaterialRecord::density, 1e-3, 1e5},
    {"dynamic_viscosity", "Pa*s", &MaterialRecord::dynamicViscosity, 1e-7, 1e6},
    {"interfacial_tension", "N/m", &MaterialRecord::interfacialTension, 0.0, 1.0},
    {"contact_angle", "deg", &MaterialRecord::contactAngle, 0.0, 180.0},
    {"youngs_modulus", "Pa", &MaterialRecord::youngsModulus, 1e-3, kHuge},
    {"poisson_ratio", "1", &MaterialRecord::poissonRatio, 0.0, 0.4999},
}};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

bool isValidName(std::string_view name) {
  if (name.empty()) return false;
  for (char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

}  // namespace

double MaterialRecord::kinematicViscosity() const {
  require(density.has_value() && dynamicViscosity.has_value(),
          "material '" + name + "' has no density or viscosity, so no kinematic viscosity");
  return dynamicViscosity->value / density->value;
}

namespace {

using Columns = std::array<std::string_view, 7>;

// Six separators; the source is the rest of the line and may contain commas.
Columns splitColumns(std::string_view line, const std::string& where) {
  Columns column;
  std::string_view rest = line;
  for (size_t k = 0; k < 6; ++k) {
    const size_t comma = rest.find(',');
    require(comma != std::string_view::npos,
            where +
                "expected 7 columns (material,kind,property,value,unit,flag,source), "
                "found " +
                std::to_string(k + 1));
    column[k] = trim(rest.substr(0, comma));
    rest = rest.substr(comma + 1);
  }
  column[6] = trim(rest);
  return column;
}

MaterialKind parseKind(std::string_view text, const std::string& where) {
  if (text == "fluid") return MaterialKind::kFluid;
  if (text == "tissue") return MaterialKind::kTissue;
  throw AnatomyError(where + "kind '" + std::string(text) + "' must be fluid or tissue");
}

const PropertySpec& parseProperty(std::string_view text, const std::string& where) {
  const PropertySpec* spec = nullptr;
  for (const auto& p : kProperties)
    if (p.name == text) spec = &p;
  if (spec == nullptr)
    throw AnatomyError(where + "unknown property '" + std::string(text) +
                       "' (density, dynamic_viscosity, interfacial_tension, contact_angle, "
                       "youngs_modulus, poisson_ratio)");
  return *spec;
}

// The value, unit, flag and source columns of one line.
SourcedValue parseValue(const Columns& column, const PropertySpec& spec, const std::string& where) {
  require(column[4] == spec.unit, where + std::string(spec.name) + " must be given in " +
                                      std::string(spec.unit) + ", not '" + std::string(column[4]) +
                                      "'");
  const std::string valueText(column[3]);
  char* parsedEnd = nullptr;
  const double value = std::strtod(valueText.c_str(), &parsedEnd);
  require(!valueText.empty() && parsedEnd == valueText.c_str() + valueText.size() &&
              std::isfinite(value),
          where + "value '" + valueText + "' is not a number");
  require(value >= spec.min && value <= spec.max, where + std::string(spec.name) + " " + valueText +
                                                      " " + std::string(spec.unit) +
                                                      " is out of the physical range");
  SourcedValue sourced;
  sourced.value = value;
  if (column[5] == "S")
    sourced.flag = Provenance::kSourced;
  else if (column[5] == "D")
    sourced.flag = Provenance::kDerived;
  else if (column[5] == "U")
    sourced.flag = Provenance::kUnsourced;
  else
    throw AnatomyError(where + "flag '" + std::string(column[5]) + "' must be S, D or U");
  require(!column[6].empty(), where + "every value needs a source (or a reason it has none)");
  sourced.source = std::string(column[6]);
  return sourced;
}

// Every material has the properties its kind needs, and a fluid no elastic constants.
void requireComplete(const std::vector<MaterialRecord>& materials, const std::string& origin) {
  for (const auto& m : materials) {
    const auto missing = [&](const char* what) {
      return origin + ": material '" + m.name + "' has no " + what;
    };
    require(m.density.has_value(), missing("density"));
    if (m.kind == MaterialKind::kFluid) {
      require(m.dynamicViscosity.has_value(), missing("dynamic_viscosity"));
      require(!m.youngsModulus && !m.poissonRatio,
              origin + ": fluid '" + m.name + "' must not have elastic constants");
    } else {
      require(m.youngsModulus.has_value(), missing("youngs_modulus"));
      require(m.poissonRatio.has_value(), missing("poisson_ratio"));
    }
  }
  require(!materials.empty(), origin + ": no materials");
}

}  // namespace

MaterialLibrary MaterialLibrary::parseCsv(std::string_view text, const std::string& origin) {
  MaterialLibrary library;
  size_t lineNumber = 0;
  while (!text.empty()) {
    const size_t end = text.find('\n');
    const std::string_view line = trim(text.substr(0, end));
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    ++lineNumber;
    if (line.empty() || line.front() == '#') continue;
    const std::string where = origin + ":" + std::to_string(lineNumber) + ": ";

    const Columns column = splitColumns(line, where);
    const std::string name(column[0]);
    require(isValidName(name),
            where + "material name '" + name + "' must be lower_snake_case (a-z, 0-9, _)");
    const MaterialKind kind = parseKind(column[1], where);
    const PropertySpec& spec = parseProperty(column[2], where);
    SourcedValue sourced = parseValue(column, spec, where);

    MaterialRecord* record = nullptr;
    for (auto& m : library.materials_)
      if (m.name == name) record = &m;
    if (record == nullptr) {
      library.materials_.push_back(MaterialRecord{});
      record = &library.materials_.back();
      record->name = name;
      record->kind = kind;
    }
    require(record->kind == kind, where + "material '" + name + "' was declared " +
                                      (record->kind == MaterialKind::kFluid ? "fluid" : "tissue") +
                                      " earlier");
    auto& slot = (*record).*(spec.field);
    require(!slot.has_value(),
            where + "material '" + name + "' gives " + std::string(spec.name) + " twice");
    slot = std::move(sourced);
  }
  requireComplete(library.materials_, origin);
  return library;
}

MaterialLibrary MaterialLibrary::loadCsv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  require(static_cast<bool>(in), path + ": cannot open the material library");
  std::ostringstream text;
  text << in.rdbuf();
  return parseCsv(text.str(), path);
}

const MaterialLibrary& MaterialLibrary::builtin() {
  static const MaterialLibrary library =
      parseCsv(embeddedMaterialTable(), "data/materials/materials.csv (built in)");
  return library;
}

bool MaterialLibrary::contains(std::string_view name) const {
  for (const auto& m : materials_)
    if (m.name == name) return true;
  return false;
}

const MaterialRecord& MaterialLibrary::find(std::string_view name) const {
  for (const auto& m : materials_)
    if (m.name == name) return m;
  std::string known;
  for (const auto& m : materials_) known += (known.empty() ? "" : ", ") + m.name;
  throw AnatomyError("no material named '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace anatomy
