#include "sim/equilibrium/wall_oil.h"

#include <algorithm>
#include <cmath>

namespace sim::equilibrium {
namespace {

constexpr double kReachVoxels = 4.0;  // D is resolved to 4 h, or delta + 2.5 h when delta is larger
constexpr double kWholeVoxel = 0.999;  // [1] fluid fraction of a voxel the wall does not cut

// Where between the centres of voxels a and b (0 at a, 1 at b) u crosses 1/2. When one of them
// is whole (u 0 or 1) and the other partly filled, the partial voxel holds a sharp interface with
// its oil on the side away from an aqueous neighbour (towards an oil one): it lies (u - 1/2) h
// from the partial voxel's centre, exact for a plane along the axis (a linear interpolation of the
// cell averages puts it up to h / 6 off, a layer the volume constraint fills partly). Linear
// between two partial voxels.
double crossingAlong(double ua, double ub) {
  const auto whole = [](double u) { return u == 0.0 || u == 1.0; };
  if (whole(ub) && !whole(ua)) return ub == 0.0 ? ua - 0.5 : 0.5 - ua;
  if (whole(ua) && !whole(ub)) return 1.0 - (ua == 0.0 ? ub - 0.5 : 0.5 - ub);
  return (0.5 - ua) / (ub - ua);
}

// Points where u crosses 1/2 between fluid voxels adjacent along an axis.
std::vector<Vec3> crossingPoints(const VoxelGrid& g, const std::vector<double>& u,
                                 const std::vector<double>& f) {
  std::vector<Vec3> points;
  const std::size_t stride[3] = {1, static_cast<std::size_t>(g.nx),
                                 static_cast<std::size_t>(g.nx) * g.ny};
  for (int k = 0; k + 1 < g.nz; ++k)
    for (int j = 0; j + 1 < g.ny; ++j)
      for (int i = 0; i + 1 < g.nx; ++i) {
        const std::size_t v = g.index(i, j, k);
        if (f[v] <= 0.0) continue;
        for (int a = 0; a < 3; ++a) {
          const std::size_t w = v + stride[a];
          if (f[w] <= 0.0 || (u[v] - 0.5) * (u[w] - 0.5) > 0.0 || u[v] == u[w]) continue;
          const double t = std::clamp(crossingAlong(u[v], u[w]), 0.0, 1.0);
          Vec3 p = g.centre(i, j, k);
          p[a] += t * g.spacing;
          points.push_back(p);
        }
      }
  return points;
}

}  // namespace

WallOilReader::WallOilReader(const EquilibriumSolution& s, double contactAngle, double offsetVoxels,
                             WallExtension extension)
    : grid_(s.grid), u_(s.oil), f_(s.fluidFraction), extension_(extension) {
  offset_ = offsetVoxels * grid_.spacing;
  turning_ = std::min(offset_, s.capillaryLength);
  reach_ = std::max(kReachVoxels, offsetVoxels + 2.5) * grid_.spacing;
  theta_ = contactAngle;
  cosTheta_ = std::cos(contactAngle);
  // Only whole fluid voxels: the voxels the wall cuts hold slivers of fluid that the scheme
  // assigns by the wall term alone (at 18 deg they read as an aqueous film over the oil's wall).
  for (double& fraction : f_) fraction = fraction >= kWholeVoxel ? 1.0 : 0.0;
  points_ = crossingPoints(grid_, u_, f_);
  // Each point's interface normal, from the gradient of u there (central differences of the
  // fluid-weighted interpolation, half a voxel apart).
  normals_.resize(points_.size());
  const double step = 0.5 * grid_.spacing;
  for (std::size_t q = 0; q < points_.size(); ++q) {
    Vec3 g;
    for (int a = 0; a < 3; ++a) {
      Vec3 e = Vec3::Zero();
      e[a] = step;
      g[a] = oilShare(points_[q] + e) - oilShare(points_[q] - e);
    }
    normals_[q] = g.norm() > 0.0 ? Vec3(g.normalized()) : Vec3::Zero();
  }
  // Bins of edge reach_ over the voxel grid's box: a query looks at its 27 neighbouring bins.
  bins_.origin = grid_.origin;
  bins_.spacing = reach_;
  bins_.nx = static_cast<int>(std::ceil(grid_.nx * grid_.spacing / reach_)) + 1;
  bins_.ny = static_cast<int>(std::ceil(grid_.ny * grid_.spacing / reach_)) + 1;
  bins_.nz = static_cast<int>(std::ceil(grid_.nz * grid_.spacing / reach_)) + 1;
  auto binOf = [&](const Vec3& p) {
    const Vec3 c = (p - bins_.origin) / reach_;
    return bins_.index(std::clamp(static_cast<int>(c.x()), 0, bins_.nx - 1),
                       std::clamp(static_cast<int>(c.y()), 0, bins_.ny - 1),
                       std::clamp(static_cast<int>(c.z()), 0, bins_.nz - 1));
  };
  cellStart_.assign(bins_.size() + 1, 0);
  for (const Vec3& p : points_) ++cellStart_[binOf(p) + 1];
  for (std::size_t b = 0; b < bins_.size(); ++b) cellStart_[b + 1] += cellStart_[b];
  cellPoints_.resize(points_.size());
  std::vector<std::size_t> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (std::size_t q = 0; q < points_.size(); ++q) cellPoints_[fill[binOf(points_[q])]++] = q;
}

double WallOilReader::oilShare(const Vec3& x) const {
  return weightedInterpolate(grid_, u_, f_, x);
}

std::size_t WallOilReader::nearestPoint(const Vec3& x) const {
  const Vec3 c = (x - bins_.origin) / reach_;
  const int ci = static_cast<int>(std::floor(c.x())), cj = static_cast<int>(std::floor(c.y())),
            ck = static_cast<int>(std::floor(c.z()));
  double best = reach_ * reach_;
  std::size_t nearest = points_.size();
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int i = ci + di, j = cj + dj, k = ck + dk;
        if (i < 0 || j < 0 || k < 0 || i >= bins_.nx || j >= bins_.ny || k >= bins_.nz) continue;
        const std::size_t b = bins_.index(i, j, k);
        for (std::size_t q = cellStart_[b]; q < cellStart_[b + 1]; ++q) {
          const double d2 = (points_[cellPoints_[q]] - x).squaredNorm();
          if (d2 < best) {
            best = d2;
            nearest = cellPoints_[q];
          }
        }
      }
  return nearest;
}

double WallOilReader::wallSignedDistance(const Vec3& w, const Vec3& n) const {
  const Vec3 p = w - offset_ * n;
  const double side = oilShare(p) >= 0.5 ? 1.0 : -1.0;
  const std::size_t q = nearestPoint(p);
  if (q == points_.size()) return side * reach_ - offset_ * cosTheta_;
  const Vec3& m = normals_[q];
  // The distance to the interface's tangent plane at the nearest point: the points stand about a
  // voxel apart, and the distance to the point itself would overstate D by up to h / 8 at D = h.
  if (m.squaredNorm() == 0.0) return side * (points_[q] - p).norm() - offset_ * cosTheta_;
  // Straight at its own angle psi (cos psi = -m . n) down to turning_ from the wall, then to theta:
  // at turning_ = offset_ (a capillary length longer than the offset: the clinical case) this is
  // the extension from the offset itself.
  const double cosPsi = std::clamp(-m.dot(n), -1.0, 1.0);
  const double atTurn = side * std::abs(m.dot(p - points_[q])) - (offset_ - turning_) * cosPsi;
  if (extension_ == WallExtension::kPlanar) return atTurn - turning_ * cosTheta_;
  const double psi = std::acos(cosPsi);
  return atTurn - turning_ * std::sin(psi) / std::tan(0.5 * (psi + theta_));
}

}  // namespace sim::equilibrium
