// Materials of dynamic particles. Each particle carries an index into the MaterialTable.
#pragma once

#include <string>
#include <vector>

#include "sim/core/error.h"
#include "sim/core/types.h"

namespace sim {

enum class MaterialKind { kFluid, kElastic };

// Fluid-only effects (viscosity, XSPH velocity smoothing) act on and between fluid particles only:
// an elastic particle's motion is the elastic stage's business (docs/methods/elasticity.md).
constexpr bool isFluid(MaterialKind kind) { return kind == MaterialKind::kFluid; }

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::kFluid;
  Real restDensity = 1000.0;    // [kg/m^3]
  Real dynamicViscosity = 0.0;  // [Pa s]
  Real youngsModulus = 0.0;     // [Pa], elastic only
  Real poissonRatio = 0.0;      // [1], elastic only

  Real kinematicViscosity() const { return dynamicViscosity / restDensity; }  // [m^2/s]
};

// Interfacial tension between two fluid materials.
struct InterfacialTension {
  int materialA = -1;
  int materialB = -1;
  Real sigma = 0.0;  // [N/m]
};

// Contact angle of a fluid on the wall particles of one tag, MEASURED THROUGH `fluidMaterial`
// (0 deg: that fluid spreads on the wall; 180 deg: it beads up). The toolkit's clinical convention
// (docs/conventions.md) gives theta through the aqueous phase; a caller holding the angle through
// the tamponade passes the tamponade as fluidMaterial, or 180 deg minus it for the aqueous.
struct ContactAngle {
  int fluidMaterial = -1;
  int wallTag = 0;
  Real angle = 90.0;  // [deg]
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
  bool isFluid(int index) const { return sim::isFluid((*this)[index].kind); }
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
  // Sets (or replaces) sigma [N/m] between fluid materials a and b (sigma 0 removes it).
  void setInterfacialTension(int a, int b, Real sigma) {
    require(a != b && a >= 0 && b >= 0 && a < size() && b < size(),
            "interfacial tension needs two different existing materials");
    require(sigma >= 0.0, "interfacial tension must be >= 0 N/m");
    std::erase_if(tensions_, [&](const InterfacialTension& t) {
      return (t.materialA == a && t.materialB == b) || (t.materialA == b && t.materialB == a);
    });
    if (sigma > 0.0) tensions_.push_back({a, b, sigma});
  }
  Real interfacialTension(int a, int b) const {  // [N/m], 0 when none is set
    for (const auto& t : tensions_)
      if ((t.materialA == a && t.materialB == b) || (t.materialA == b && t.materialB == a))
        return t.sigma;
    return 0.0;
  }
  const std::vector<InterfacialTension>& interfacialTensions() const { return tensions_; }
  // Sets (or replaces) the contact angle [deg], measured through `fluid`, on walls of `wallTag`.
  void setContactAngle(int fluid, int wallTag, Real degrees) {
    require(fluid >= 0 && fluid < size(), "contact angle for a material that does not exist");
    require(degrees > 0.0 && degrees < 180.0,
            "contact angle must be in (0, 180) deg, measured through material '" +
                materials_[static_cast<size_t>(fluid)].name + "'");
    std::erase_if(angles_, [&](const ContactAngle& c) { return c.wallTag == wallTag; });
    angles_.push_back({fluid, wallTag, degrees});
  }
  const std::vector<ContactAngle>& contactAngles() const { return angles_; }
  auto begin() const { return materials_.begin(); }
  auto end() const { return materials_.end(); }

 private:
  std::vector<Material> materials_;
  std::vector<InterfacialTension> tensions_;
  std::vector<ContactAngle> angles_;
};

}  // namespace sim
