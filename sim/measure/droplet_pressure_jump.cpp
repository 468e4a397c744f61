#include "sim/measure/droplet_pressure_jump.h"

#include <string>

namespace sim {

PressureJump measureDropletPressureJump(const World& world, const std::vector<Real>& pressure,
                                        const DropletRegion& region) {
  const auto& p = world.particles;
  require(pressure.size() == p.size(), "pressure field has the wrong length");
  const NeighborList& nw = world.wallNeighbors();
  PressureJump out;
  Real sumIn = 0, sumOut = 0;
  // Serial, index order: deterministic and cheap (called once per sample, not per step).
  for (Index i = 0; i < p.size(); ++i) {
    if (nw.count(i) > 0) continue;
    const Real r = (p.x[i] - region.centre).norm();
    if (p.material[i] == region.material && r < region.radius - region.margin) {
      sumIn += pressure[i];
      ++out.insideCount;
    } else if (p.material[i] != region.material && r > region.radius + region.margin &&
               r < region.outerRadius) {
      sumOut += pressure[i];
      ++out.outsideCount;
    }
  }
  require(out.insideCount > 0 && out.outsideCount > 0,
          "droplet pressure jump: no particle " +
              std::string(out.insideCount == 0 ? "inside R - margin" : "outside R + margin") +
              " away from walls; make the margin smaller or the box larger");
  out.inside = sumIn / out.insideCount;
  out.outside = sumOut / out.outsideCount;
  out.jump = out.inside - out.outside;
  return out;
}

Vec3 centreOfMaterial(const World& world, int material) {
  const auto& p = world.particles;
  Vec3 sum = Vec3::Zero();
  Real mass = 0;
  for (Index i = 0; i < p.size(); ++i)
    if (p.material[i] == material) {
      sum += p.mass[i] * p.x[i];
      mass += p.mass[i];
    }
  require(mass > 0, "no particle of material " + std::to_string(material));
  return sum / mass;
}

}  // namespace sim
