#include "sim/effects/wall_adhesion_young.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "sim/effects/interfacial_tension_hu_adams2006.h"

namespace sim {

Real WallAdhesionYoung::wallColour(Real thetaThroughColourOne) {
  return 0.5 * (1.0 + std::cos(thetaThroughColourOne * std::numbers::pi / 180.0));
}

void WallAdhesionYoung::attach(World& world) {
  const auto& materials = world.materials;
  const auto& angles = materials.contactAngles();
  const auto& tensions = materials.interfacialTensions();
  require(!angles.empty(), "wall_adhesion is on but no contact angle is given");
  require(!tensions.empty(),
          "a contact angle needs an interfacial tension between the fluid that touches the wall "
          "and the other fluid: set sigma (MaterialTable::setInterfacialTension)");
  const InterfacialTension& pair = tensions.front();
  materialA_ = pair.materialA;
  materialB_ = pair.materialB;
  const std::size_t nWalls = world.walls.size();
  wallColour_.assign(nWalls, std::numeric_limits<Real>::quiet_NaN());
  for (const auto& angle : angles) {
    const std::string& fluid = materials[angle.fluidMaterial].name;
    require(angle.fluidMaterial == materialA_ || angle.fluidMaterial == materialB_,
            "contact angle given through '" + fluid + "', which is not in the first tension pair ('" +
                materials[materialA_].name + "', '" + materials[materialB_].name +
                "'): wall wetting supports one pair of liquids; list that pair first");
    // theta through B is 180 deg - theta through A.
    const Real thetaA = angle.fluidMaterial == materialA_ ? angle.angle : 180.0 - angle.angle;
    const Real cw = wallColour(thetaA);
    bool found = false;
    for (std::size_t b = 0; b < nWalls; ++b)
      if (world.walls.tag[b] == angle.wallTag) {
        wallColour_[b] = cw;
        found = true;
      }
    require(found, "contact angle for wall tag " + std::to_string(angle.wallTag) +
                       " (through '" + fluid + "') but no wall particle has that tag");
  }
  wallGradient_ =
      &world.particles.fields.addOrGet<Vec3>({field::kWallColourGradient, "1/m", false, false});
}

void WallAdhesionYoung::apply(World& world, const StepContext&) {
  auto& p = world.particles;
  const Index n = static_cast<Index>(p.size());
  const NeighborList& nw = world.wallNeighbors();
  const auto& gradB = world.wallGradients();
  const auto& volume = world.walls.volume;
  auto& out = *wallGradient_;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    const int m = p.material[i];
    Vec3 g = Vec3::Zero();
    if (m == materialA_ || m == materialB_) {
      const Real ci = m == materialA_ ? 1.0 : 0.0;
      for (Index k = nw.offsets[i]; k < nw.offsets[i + 1]; ++k) {
        const Real cw = wallColour_[nw.indices[k]];
        if (std::isnan(cw)) continue;
        g += volume[nw.indices[k]] * (cw - ci) * gradB[k];
      }
    }
    out[i] = g;
  }
}

}  // namespace sim
