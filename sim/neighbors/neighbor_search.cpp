#include "sim/neighbors/neighbor_search.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "sim/neighbors/morton.h"

namespace sim {

NeighborSearch::NeighborSearch(const Box& domain, Real supportRadius)
    : domain_(domain), radius_(supportRadius) {
  require(supportRadius > 0.0, "neighbour search: support radius must be > 0 m");
  require(!domain.isEmpty() && domain.volume() > 0.0, "neighbour search: empty domain");
  invCell_ = 1.0 / supportRadius;
  const Vec3 extent = domain.sizes() * invCell_;
  require(extent.maxCoeff() < 2.0e6, "neighbour search: domain is more than 2e6 cells across");
  dims_ = (extent.array().ceil().cast<int>().max(1)).matrix();
  cellCount_ = static_cast<std::int64_t>(dims_.x()) * dims_.y() * dims_.z();
  require(cellCount_ <= 400'000'000,
          "neighbour search: the domain has " + std::to_string(cellCount_) +
              " cells of the support radius; make it tighter or the spacing coarser");
}

bool NeighborSearch::contains(const Vec3& x) const {
  return x.allFinite() && (x.array() >= domain_.min().array()).all() &&
         (x.array() <= domain_.max().array()).all();
}

Eigen::Vector3i NeighborSearch::cellCoords(const Vec3& x) const {
  Eigen::Vector3i c;
  for (int d = 0; d < 3; ++d) {
    const int k = static_cast<int>(std::floor((x[d] - domain_.min()[d]) * invCell_));
    c[d] = std::clamp(k, 0, dims_[d] - 1);
  }
  return c;
}

void NeighborSearch::bin(const std::vector<Vec3>& x, CellBins& bins, bool dynamic) {
  const std::size_t n = x.size();
  bins.cellOf.resize(n);
  bool allInside = true;
#pragma omp parallel for schedule(static) reduction(&& : allInside)
  for (std::size_t i = 0; i < n; ++i) {
    allInside = allInside && contains(x[i]);
    bins.cellOf[i] = linear(cellCoords(x[i]));
  }
  if (!allInside) {
    for (std::size_t i = 0; i < n; ++i) {
      if (contains(x[i])) continue;
      std::ostringstream msg;
      msg << (dynamic ? "particle " : "wall particle ") << i << " at (" << x[i].transpose()
          << ") m is outside the simulation domain [" << domain_.min().transpose() << "] - ["
          << domain_.max().transpose() << "] m"
          << (x[i].allFinite() ? "" : " (non-finite: the simulation became unstable)");
      throw SimError(msg.str());
    }
  }
  // Counting sort, serial so that the order inside a cell is the index order (determinism).
  bins.cellStart.assign(static_cast<std::size_t>(cellCount_) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++bins.cellStart[static_cast<std::size_t>(bins.cellOf[i]) + 1];
  std::partial_sum(bins.cellStart.begin(), bins.cellStart.end(), bins.cellStart.begin());
  bins.sorted.resize(n);
  counts_.assign(bins.cellStart.begin(), bins.cellStart.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    bins.sorted[counts_[static_cast<std::size_t>(bins.cellOf[i])]++] = static_cast<Index>(i);
}

void NeighborSearch::buildList(const std::vector<Vec3>& qx, const CellBins& qbins,
                               const std::vector<Vec3>& px, const CellBins& pbins, bool skipSelf,
                               NeighborList& out) {
  const std::size_t n = qx.size();
  const Real r2 = radius_ * radius_;
  out.offsets.resize(n + 1);
  out.offsets[0] = 0;
  const std::int64_t dx = 1, dy = dims_.x(), dz = static_cast<std::int64_t>(dims_.x()) * dims_.y();

  // Visits the candidate points of the 27 cells around query i in a fixed order.
  auto forCandidates = [&](std::size_t i, auto&& visit) {
    const std::int64_t c = qbins.cellOf[i];
    const std::int64_t cz = c / dz, cy = (c % dz) / dy, cx = c % dy;
    for (int oz = -1; oz <= 1; ++oz) {
      if (cz + oz < 0 || cz + oz >= dims_.z()) continue;
      for (int oy = -1; oy <= 1; ++oy) {
        if (cy + oy < 0 || cy + oy >= dims_.y()) continue;
        // The three cells along x are contiguous in the linear index: one range.
        const std::int64_t lo = std::max<std::int64_t>(cx - 1, 0);
        const std::int64_t hi = std::min<std::int64_t>(cx + 1, dims_.x() - 1);
        const std::int64_t base = (cz + oz) * dz + (cy + oy) * dy;
        const Index b = pbins.cellStart[static_cast<std::size_t>(base + lo * dx)];
        const Index e = pbins.cellStart[static_cast<std::size_t>(base + hi * dx) + 1];
        for (Index k = b; k < e; ++k) {
          const Index j = pbins.sorted[k];
          if (skipSelf && j == i) continue;
          if ((qx[i] - px[j]).squaredNorm() < r2) visit(j);
        }
      }
    }
  };

#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Index count = 0;
    forCandidates(i, [&](Index) { ++count; });
    out.offsets[i + 1] = count;
  }
  for (std::size_t i = 0; i < n; ++i) out.offsets[i + 1] += out.offsets[i];
  out.indices.resize(out.offsets[n]);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Index k = out.offsets[i];
    forCandidates(i, [&](Index j) { out.indices[k++] = j; });
  }
}

void NeighborSearch::setStatic(const std::vector<Vec3>& staticX) {
  staticX_ = staticX;
  bin(staticX_, staticBins_, false);
  buildList(staticX_, staticBins_, staticX_, staticBins_, true, ss_);
}

void NeighborSearch::update(const std::vector<Vec3>& dynamicX) {
  bin(dynamicX, dynamicBins_, true);
  buildList(dynamicX, dynamicBins_, dynamicX, dynamicBins_, true, dd_);
  if (staticX_.empty()) {
    ds_.offsets.assign(dynamicX.size() + 1, 0);
    ds_.indices.clear();
  } else {
    buildList(dynamicX, dynamicBins_, staticX_, staticBins_, false, ds_);
  }
}

void NeighborSearch::zOrder(const std::vector<Vec3>& x, std::vector<Index>& newToOld) const {
  const std::size_t n = x.size();
  std::vector<std::uint64_t>& code = mortonScratch_;
  code.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3i c = cellCoords(x[i]);
    code[i] = mortonCode(static_cast<std::uint32_t>(c.x()), static_cast<std::uint32_t>(c.y()),
                         static_cast<std::uint32_t>(c.z()));
  }
  newToOld.resize(n);
  std::iota(newToOld.begin(), newToOld.end(), Index{0});
  std::stable_sort(newToOld.begin(), newToOld.end(),
                   [&](Index a, Index b) { return code[a] < code[b]; });
}

}  // namespace sim
