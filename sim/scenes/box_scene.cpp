#include "sim/scenes/box_scene.h"

#include <algorithm>
#include <cmath>

namespace sim {

Box tankDomain(const TankSpec& tank, Real spacing) {
  const Real margin = 3 * spacing;
  Vec3 hi = tank.innerMax + Vec3::Constant(margin);
  if (!tank.closedTop) hi.y() += (tank.innerMax.y() - tank.innerMin.y());  // room for splashes
  return Box(tank.innerMin - Vec3::Constant(margin), hi);
}

void addTankWalls(World& world, const TankSpec& tank, Real d, int tag) {
  require(d > 0, "wall spacing must be > 0 m");
  require((tank.innerMax - tank.innerMin).minCoeff() > 0, "tank must have a positive size");
  const Vec3 size = tank.innerMax - tank.innerMin;
  const Eigen::Vector3i cells = (size / d).array().round().cast<int>().max(1);
  const Vec3 step = size.cwiseQuotient(cells.cast<Real>());  // exactly fits the tank
  for (int kz = 0; kz <= cells.z(); ++kz)
    for (int ky = 0; ky <= cells.y(); ++ky)
      for (int kx = 0; kx <= cells.x(); ++kx) {
        const bool onX = kx == 0 || kx == cells.x();
        const bool onY = ky == 0 || (ky == cells.y() && tank.closedTop);
        const bool onZ = kz == 0 || kz == cells.z();
        if (!onX && !onY && !onZ) continue;
        Vec3 n = Vec3::Zero();
        if (kx == 0) n.x() -= 1;
        if (kx == cells.x()) n.x() += 1;
        if (ky == 0) n.y() -= 1;
        if (ky == cells.y() && tank.closedTop) n.y() += 1;
        if (kz == 0) n.z() -= 1;
        if (kz == cells.z()) n.z() += 1;
        world.walls.add(tank.innerMin + Vec3(kx, ky, kz).cwiseProduct(step), n.normalized(), tag);
      }
}

void addTankWalls(World& world, const TankSpec& tank, Real d, int tag, const WallLayers& layers) {
  require(d > 0, "wall spacing must be > 0 m");
  require(layers.count >= 1, "a layered tank wall needs at least one layer");
  require((tank.innerMax - tank.innerMin).minCoeff() > 0, "tank must have a positive size");
  const Vec3 size = tank.innerMax - tank.innerMin;
  const Eigen::Vector3i cells = (size / d).array().round().cast<int>().max(1);
  const Vec3 step = size.cwiseQuotient(cells.cast<Real>());
  const Real volume = step.prod();  // [m^3] one lattice cell
  const int n = layers.count;
  // Depth of lattice index k outside [0, c) along one axis: -1 inside, 0 for the first cell out.
  auto depth = [](int k, int c) { return k < 0 ? -k - 1 : (k >= c ? k - c : -1); };
  const int yEnd = tank.closedTop ? cells.y() + n : cells.y();  // open top: no lid cells
  for (int kz = -n; kz < cells.z() + n; ++kz)
    for (int ky = -n; ky < yEnd; ++ky)
      for (int kx = -n; kx < cells.x() + n; ++kx) {
        const int dx = depth(kx, cells.x()), dy = depth(ky, cells.y()), dz = depth(kz, cells.z());
        const int layer = std::max({dx, dy, dz});
        if (layer < 0) continue;  // inside the tank
        Vec3 normal(dx == layer ? (kx < 0 ? -1 : 1) : 0, dy == layer ? (ky < 0 ? -1 : 1) : 0,
                    dz == layer ? (kz < 0 ? -1 : 1) : 0);
        const Vec3 x = tank.innerMin + (Vec3(kx, ky, kz) + Vec3::Constant(0.5)).cwiseProduct(step);
        addLayeredWallParticle(world.walls, x, normal.normalized(), tag, volume, layer);
      }
}

std::size_t addFluidBlock(World& world, const Vec3& min, const Vec3& max, Real d, int materialIndex,
                          Real densityRatio) {
  require(d > 0, "fluid spacing must be > 0 m");
  require(densityRatio > 0, "fluid block: the initial density ratio must be > 0");
  require(materialIndex >= 0 && materialIndex < world.materials.size(),
          "fluid block refers to an undefined material");
  const Real mass = densityRatio * world.materials[materialIndex].restDensity * d * d * d;
  const Eigen::Vector3i cells = ((max - min) / d).array().round().cast<int>();
  std::size_t added = 0;
  for (int kz = 0; kz < cells.z(); ++kz)
    for (int ky = 0; ky < cells.y(); ++ky)
      for (int kx = 0; kx < cells.x(); ++kx) {
        world.particles.add(min + Vec3(kx + 0.5, ky + 0.5, kz + 0.5) * d, Vec3::Zero(), mass,
                            materialIndex);
        ++added;
      }
  return added;
}

}  // namespace sim
