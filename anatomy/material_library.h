// The material library: physical properties of the fluids (aqueous, tamponades) and tissues
// (sclera, orbital fat), each value with its provenance flag and source.
//
// Why a CSV file embedded at build time: data/materials/materials.csv is the one place the
// values and their sources live, readable and reviewable as data; CMake embeds its text into the
// library (material_table.cpp.in), so the library needs no file at run time and cannot disagree
// with the shipped file. anatomy/ may not use toml++ (layering), and a one-row-per-value CSV is
// simple enough to parse strictly here (every row checked: kind, property, unit, flag, source).
// MaterialLibrary::loadCsv reads an edited copy for sensitivity studies.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace anatomy {

enum class Provenance { kSourced, kDerived, kUnsourced };  // [S], [D], [U]

struct SourcedValue {
  double value = 0.0;  // SI, see the field's unit below
  Provenance flag = Provenance::kUnsourced;
  std::string source;
};

enum class MaterialKind { kFluid, kTissue };

struct MaterialRecord {
  std::string name;
  MaterialKind kind = MaterialKind::kFluid;
  std::optional<SourcedValue> density;             // [kg/m^3]            all
  std::optional<SourcedValue> dynamicViscosity;    // [Pa s]              fluids
  std::optional<SourcedValue> interfacialTension;  // [N/m] vs aqueous    tamponades
  std::optional<SourcedValue> contactAngle;        // [deg] on retina, through the aqueous phase
  std::optional<SourcedValue> youngsModulus;       // [Pa]                tissues
  std::optional<SourcedValue> poissonRatio;        // [1]                 tissues

  // [m^2/s] dynamic viscosity / density; throws AnatomyError when either is missing.
  double kinematicViscosity() const;
};

class MaterialLibrary {
 public:
  // The library shipped in data/materials/materials.csv (embedded at build time).
  static const MaterialLibrary& builtin();
  // Reads a library file; throws AnatomyError "path:line: what is wrong" for any bad row, and
  // "path: material 'x' ..." for a material missing a required property.
  static MaterialLibrary loadCsv(const std::string& path);
  // Parses library text; `origin` names it in messages.
  static MaterialLibrary parseCsv(std::string_view text, const std::string& origin);

  // Throws AnatomyError listing the known names when `name` is unknown.
  const MaterialRecord& find(std::string_view name) const;
  bool contains(std::string_view name) const;
  const std::vector<MaterialRecord>& materials() const { return materials_; }

 private:
  std::vector<MaterialRecord> materials_;
};

// Text of data/materials/materials.csv as embedded at build time.
std::string_view embeddedMaterialTable();

}  // namespace anatomy
