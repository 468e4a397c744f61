#include "protocols/coverage/wall_oil_fraction.h"

#include <array>
#include <cmath>
#include <string>
#include <unordered_map>

#include "protocols/coverage/coverage_error.h"

namespace protocols {
namespace {

// Cell key of a point for a grid of cell size h; 21 bits per axis cover +-2^20 cells (+-1 km at
// h = 1 mm), far beyond any eye.
std::int64_t cellKey(std::int64_t ix, std::int64_t iy, std::int64_t iz) {
  constexpr std::int64_t kOffset = 1 << 20;
  return ((ix + kOffset) << 42) | ((iy + kOffset) << 21) | (iz + kOffset);
}

}  // namespace

WallOilFractions computeWallOilFractions(const std::vector<sim::Vec3>& walls,
                                         const FluidPhaseState& fluid, const sim::Kernel& kernel) {
  if (fluid.positions == nullptr || fluid.isOil == nullptr)
    throw CoverageError("computeWallOilFractions: fluid positions and phase flags are required");
  const auto& x = *fluid.positions;
  const auto& isOil = *fluid.isOil;
  if (isOil.size() != x.size())
    throw CoverageError("computeWallOilFractions: " + std::to_string(x.size()) +
                        " fluid positions but " + std::to_string(isOil.size()) +
                        " phase flags; pass one flag per fluid particle");
  if (fluid.volumes != nullptr && fluid.volumes->size() != x.size())
    throw CoverageError("computeWallOilFractions: " + std::to_string(x.size()) +
                        " fluid positions but " + std::to_string(fluid.volumes->size()) +
                        " volumes; pass one volume per fluid particle or none");

  const double h = kernel.supportRadius();  // [m]
  const double invH = 1.0 / h;              // [1/m]
  auto cellOf = [invH](const sim::Vec3& p) {
    return std::array<std::int64_t, 3>{static_cast<std::int64_t>(std::floor(p.x() * invH)),
                                       static_cast<std::int64_t>(std::floor(p.y() * invH)),
                                       static_cast<std::int64_t>(std::floor(p.z() * invH))};
  };
  // Counting sort of the fluid particles by cell: one contiguous range per occupied cell, in
  // particle order inside the cell, so the sums below run in a fixed order (deterministic).
  std::unordered_map<std::int64_t, std::pair<std::size_t, std::size_t>> cells;  // key -> [b, e)
  std::vector<std::int64_t> keys(x.size());
  for (std::size_t j = 0; j < x.size(); ++j) {
    const auto c = cellOf(x[j]);
    keys[j] = cellKey(c[0], c[1], c[2]);
    ++cells[keys[j]].second;
  }
  std::size_t offset = 0;
  for (auto& [key, range] : cells) {
    const std::size_t count = range.second;
    range = {offset, offset};
    offset += count;
  }
  std::vector<std::size_t> sorted(x.size());
  for (std::size_t j = 0; j < x.size(); ++j) sorted[cells[keys[j]].second++] = j;

  WallOilFractions out;
  out.oilFraction.assign(walls.size(), 0.0);
  out.wetting.assign(walls.size(), WallWetting::kDry);
  const long n = static_cast<long>(walls.size());
#pragma omp parallel for schedule(static)
  for (long w = 0; w < n; ++w) {
    const sim::Vec3& xw = walls[static_cast<std::size_t>(w)];
    const auto c = cellOf(xw);
    double weight = 0.0;     // [1] sum V_j W_wj (dimensionless: m^3 * 1/m^3)
    double oilWeight = 0.0;  // [1]
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find(cellKey(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == cells.end()) continue;
          for (std::size_t k = it->second.first; k < it->second.second; ++k) {
            const std::size_t j = sorted[k];
            const double r = (xw - x[j]).norm();  // [m]
            if (r >= h) continue;
            const double vj = fluid.volumes != nullptr ? (*fluid.volumes)[j] : 1.0;
            const double wj = vj * kernel.W(r);
            weight += wj;
            if (isOil[j] != 0) oilWeight += wj;
          }
        }
    // W > 0 strictly inside the support, so weight > 0 iff some fluid particle is within h.
    if (weight <= 0.0) continue;
    const double phi = oilWeight / weight;
    out.oilFraction[static_cast<std::size_t>(w)] = phi;
    out.wetting[static_cast<std::size_t>(w)] =
        phi >= kOilCoveredThreshold ? WallWetting::kOil : WallWetting::kAqueous;
  }
  return out;
}

}  // namespace protocols
