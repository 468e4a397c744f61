// Materials of dynamic particles. Each particle carries an index into the MaterialTable.
#pragma once

#include <string>
#include <vector>

#include "sim/core/error.h"
#include "sim/core/types.h"

namespace sim {

enum class MaterialKind { kFluid, kElastic };

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::kFluid;
  Real restDensity = 1000.0;     // [kg/m^3]
  Real dynamicViscosity = 0.0;   // [Pa s]
  Real youngsModulus = 0.0;      // [Pa], elastic only
  Real poissonRatio = 0.0;       // [1], elastic only

  Real kinematicViscosity() const { return dynamicViscosity / restDensity; }  // [m^2/s]
};

class MaterialTable {
 public:
  // Returns the new material's index. Validates the physical parameters.
  int add(const Material& m) {
    require(!m.name.empty(), "material needs a name");
    require(m.restDensity > 0.0, "material '" + m.name + "': rest density must be > 0 kg/m^3");
    require(m.dynamicViscosity >= 0.0, "material '" + m.name + "': viscosity must be >= 0");
    if (m.kind == MaterialKind::kElastic) {
      require(m.youngsModulus > 0.0, "material '" + m.name + "': Young's modulus must be > 0 Pa");
      require(m.poissonRatio >= 0.0 && m.poissonRatio < 0.5,
              "material '" + m.name + "': Poisson ratio must be in [0, 0.5)");
    }
    for (const auto& existing : materials_)
      require(existing.name != m.name, "material '" + m.name + "' defined twice");
    materials_.push_back(m);
    return static_cast<int>(materials_.size()) - 1;
  }
  const Material& operator[](int index) const { return materials_.at(static_cast<size_t>(index)); }
  int size() const { return static_cast<int>(materials_.size()); }
  int indexOf(const std::string& name) const {
    for (int k = 0; k < size(); ++k)
      if (materials_[static_cast<size_t>(k)].name == name) return k;
    throw SimError("no material named '" + name + "'");
  }
  int countOfKind(MaterialKind kind) const {
    int n = 0;
    for (const auto& m : materials_) n += (m.kind == kind);
    return n;
  }
  auto begin() const { return materials_.begin(); }
  auto end() const { return materials_.end(); }

 private:
  std::vector<Material> materials_;
};

}  // namespace sim
