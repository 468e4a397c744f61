// Uniform cell-grid neighbour search with Z-order sorting and CSR neighbour lists.
//
// The grid covers a fixed axis-aligned domain with cells of the kernel support radius, so every
// neighbour of a particle lies in its own or one of the 26 adjacent cells. Each update counting-
// sorts particle indices into cells (serially, so the order is deterministic) together with a copy
// of their positions in cell order, so that the candidate scan reads the 9 contiguous cell ranges
// of the 27-cell stencil without an indirection; a range is trimmed to the cells that can hold a
// point within the search radius (a row or end cell wholly farther away is skipped, which changes
// no list). The compressed-sparse-row lists are built in ONE parallel region: each thread scans its
// contiguous block of query points and stores the accepted candidates' sorted slots branch-free;
// once the blocks' offsets are known, each thread writes its block's point indices into place
// and, when a kernel is given, computes the per-pair kernel gradients and values straight into the
// final lists. With a kernel, the slots are staged in the previous build's gradient storage (dead
// until the kernel pass rewrites it, and three slots per gradient), so a list holds 20 bytes per
// pair (index, gradient and value) and nothing else; a block that does not fit its share there (the
// first build, a list that grew past the room) is counted, and the blocks are scanned again into
// exact shares. Without a kernel each thread stages in a reusable buffer of its own. The result
// does not depend on the thread count (each point's neighbours come in stencil order, inside a cell
// in index order). Static wall particles are binned once. Dynamic particle data are periodically
// reordered by the Z-order (Morton) index of their cell (zOrder()), which keeps neighbours close
// in memory. Storage only grows (per-thread buffers to 1.5x when less than 1/16 headroom is left,
// lists by a quarter), so a running simulation whose pair count drifts slowly does not allocate.
//
// Variable support (VSLSPH, sim/fluid/vslsph_li2023.h): the grid is built for the largest support
// R any particle may take (cells R/2 wide, a 5 x 5 x 5 stencil), and update() may be given
// per-particle support radii h_i <= R. A dynamic pair is then kept when
// r < max(h, h_i, h_j) (h the kernel's support), a dynamic-wall pair when r < max(h, h_i): a
// superset of the fixed-h lists, so stages that use the kernel of support h see every pair they
// would without the radii, and the extra ones carry W = 0. The scan skips a cell that lies beyond
// both the query's radius and the largest radius of the points in it (CellBins::cellMaxR2), so a
// bulk particle at h among neighbours at h scans about the fixed-h volume, not the largest
// support's. Without radii the scan is the fixed-h one, branch for branch.
//
// Time: pairKernelSeconds() is the part of an update spent on the per-pair kernel gradients and
// values (the stages' kernel evaluations, done here once); the pipeline reports it as its own
// stage, "pair_kernels", beside the search proper, "neighbors".
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "sim/core/error.h"
#include "sim/core/types.h"
#include "sim/kernels/kernel.h"
#include "sim/neighbors/pair_precision.h"

namespace sim {

using Box = Eigen::AlignedBox<Real, 3>;

// Neighbour lists in CSR form: the neighbours of i are indices[offsets[i] .. offsets[i+1]).
struct NeighborList {
  std::vector<Index> offsets;
  std::vector<Index> indices;

  Index count(Index i) const { return offsets[i + 1] - offsets[i]; }
  const Index* begin(Index i) const { return indices.data() + offsets[i]; }
  const Index* end(Index i) const { return indices.data() + offsets[i + 1]; }
  template <class F>
  void forEach(Index i, F&& f) const {
    for (Index k = offsets[i]; k < offsets[i + 1]; ++k) f(indices[k]);
  }
  std::size_t totalPairs() const { return indices.size(); }
};

// A set of points binned into the grid's cells.
struct CellBins {
  std::vector<Index>
      cellStart;  // size cellCount+1; points of cell c: sorted[cellStart[c]..cellStart[c+1])
  std::vector<Index> sorted;  // point indices grouped by cell
  std::vector<Index> slotOf;  // per point: its place in `sorted`
  std::vector<Index> cellOf;  // per point (cellCount() <= 4e8 fits)
  std::vector<Vec3> sortedX;  // [m] positions in `sorted` order (contiguous candidate scan)
  // [m^2] squared search radii max(h, h_i)^2 in `sorted` order; filled only for dynamic points
  // binned with per-particle support radii (empty otherwise).
  std::vector<Real> sortedR2;
  // [m^2] per cell, the largest of its points' sortedR2 (0 when empty); filled with sortedR2.
  std::vector<Real> cellMaxR2;
};

class NeighborSearch {
 public:
  // `domain` must contain every particle for the whole run; a particle leaving it is an error
  // (it has escaped the walls). Memory is one Index per cell: keep the domain tight.
  NeighborSearch(const Box& domain, Real supportRadius);
  // For per-particle support radii up to largestSupport >= supportRadius (variable smoothing
  // length); equal to supportRadius: the fixed-h grid.
  NeighborSearch(const Box& domain, Real supportRadius, Real largestSupport);

  Real supportRadius() const { return radius_; }
  Real largestSupport() const { return largest_; }  // [m]
  const Box& domain() const { return domain_; }
  std::int64_t cellCount() const { return cellCount_; }

  // Bins static points (walls) once; builds the static-static list (wall volumes need it).
  void setStatic(const std::vector<Vec3>& staticX);
  // Bins dynamic points and rebuilds dynamic-dynamic and dynamic-static lists.
  // Throws SimError naming the first particle outside the domain.
  void update(const std::vector<Vec3>& dynamicX);
  // Lists only, with per-particle support radii (nullptr: fixed h); no kernel values or
  // gradients are kept (the pair-cache-free mode, WorldParameters::cachePairKernels).
  void update(const std::vector<Vec3>& dynamicX, const std::vector<Real>* supportRadii);
  // Same, and also fills the kernel gradients gradW(x_i - x_j) aligned with the dynamic-dynamic
  // and dynamic-static lists (entry k belongs to the pair (i, indices[k])), computed in the same
  // pass as the lists with exactly Kernel::gradW's arithmetic.
  void update(const std::vector<Vec3>& dynamicX, const Kernel& kernel);
  // Same with per-particle support radii h_i [m] (<= largestSupport(); nullptr: the fixed-h
  // update): a pair is kept when r < max(h, h_i, h_j) (see the file comment).
  void update(const std::vector<Vec3>& dynamicX, const Kernel& kernel,
              const std::vector<Real>* supportRadii);

  const NeighborList& dynamicDynamic() const { return dd_; }
  const NeighborList& dynamicStatic() const { return ds_; }
  const NeighborList& staticStatic() const { return ss_; }
  // [1/m^4] filled by update(x, kernel) only; single precision (pair_precision.h)
  const std::vector<PairGradient>& dynamicDynamicGradients() const { return ddGrad_; }
  const std::vector<PairGradient>& dynamicStaticGradients() const { return dsGrad_; }
  // [1/m^3] kernel values W(x_i - x_j), same alignment; filled by update(x, kernel), emptied by
  // update(x). They let density sums and XSPH skip a square root and a kernel evaluation per pair
  // (without them a 101k DFSPH step takes about 1.1x the time, docs/benchmarks.md "Memory").
  const std::vector<PairValue>& dynamicDynamicKernelValues() const { return ddW_; }
  const std::vector<PairValue>& dynamicStaticKernelValues() const { return dsW_; }

  // [s] wall time the last update spent on the per-pair kernel gradients and values (part of
  // update()'s time; the rest is the search proper: binning, candidate scan, list placement).
  double pairKernelSeconds() const { return pairKernelSeconds_; }

  // Permutation (new -> old) that orders points by the Morton index of their cell.
  void zOrder(const std::vector<Vec3>& x, std::vector<Index>& newToOld) const;

  // Cell coordinates of a point, clamped to the grid; `inside` reports whether it was in the
  // domain.
  Eigen::Vector3i cellCoords(const Vec3& x) const;
  bool contains(const Vec3& x) const;

 private:
  void bin(const std::vector<Vec3>& x, CellBins& bins, bool dynamic);
  // Fills qR2_ (query order) and bins.sortedR2 from the support radii; throws if one exceeds the
  // cell size.
  void binRadii(const std::vector<Real>& radii, CellBins& bins);
  // The query side of one list being built (see buildList).
  struct ListQuery;
  // One row of the stencil (fixed y and z cells): the contiguous x-range of cells that can hold a
  // point within the pruning radius, as a range of sorted slots.
  struct StencilRow {
    Index begin, end;
  };
  // One thread's share of a list being built: the accepted neighbours of its block of query
  // points, as slots in the points' sorted order, stored during the scan in `area` (a range of
  // the pair gradients' storage, or `own`) and read back when the block is placed. A cache line
  // of its own, so that the threads' bookkeeping does not share one.
  struct alignas(64) ThreadBuffer {
    std::vector<Index> own;     // the thread's own slot storage (lists built without kernel)
    std::byte* area = nullptr;  // where the slots go (Index-sized cells, see buildList)
    std::size_t room = 0;       // [slots] the area's size (own: grows as needed)
    std::size_t count = 0;      // accepted pairs of the block
    std::size_t slack = 0;      // the most candidates of one point of the block
    bool fits = true;           // every slot was stored (false: counted only)
    bool grows = false;         // the area is `own`, grown as needed
    std::size_t offset = 0;     // where the block starts in the final list
  };
  // CSR list from query points `qx` (binned in `qbins`) to the points `px` binned in `pbins`;
  // `skipSelf` drops the pair (i, i) when both sets are the same. `kernel` non-null: also fill
  // `grad` and `values` (aligned with out.indices); null: both are emptied. `qR2` non-null:
  // per-query squared radii (variable support), with pbins.sortedR2 the points' ones when that is
  // filled (else the fixed radius for the points).
  void buildList(const std::vector<Vec3>& qx, const CellBins& qbins, const std::vector<Vec3>& px,
                 const CellBins& pbins, bool skipSelf, const Kernel* kernel, NeighborList& out,
                 std::vector<PairGradient>& grad, std::vector<PairValue>& values,
                 const Real* qR2 = nullptr);
  // The stencil rows of query point i that can hold a neighbour (rows[0..returned)); adds the
  // number of candidates in them to `candidates`.
  std::size_t stencilRows(const ListQuery& q, std::size_t i, StencilRow* rows,
                          std::size_t& candidates) const;
  // Scans query points [lo, hi) (see buildList); returns the accepted pairs.
  std::size_t scanBlock(const ListQuery& q, std::size_t lo, std::size_t hi,
                        ThreadBuffer& buf) const;
  void updateImpl(const std::vector<Vec3>& dynamicX, const Kernel* kernel,
                  const std::vector<Real>* supportRadii = nullptr);

  std::int64_t linear(const Eigen::Vector3i& c) const {
    return c.x() + dims_.x() * (static_cast<std::int64_t>(c.y()) +
                                static_cast<std::int64_t>(dims_.y()) * c.z());
  }

  Box domain_;
  Real radius_;
  Real largest_;   // [m] largest per-particle support the grid serves
  int reach_ = 1;  // [cells] stencil half-width: 1 for the fixed support, 2 for variable support
  Real invCell_;
  Eigen::Vector3i dims_;
  std::int64_t cellCount_;
  CellBins staticBins_, dynamicBins_;
  std::vector<Vec3> staticX_;
  NeighborList dd_, ds_, ss_;
  std::vector<PairGradient> ddGrad_, dsGrad_, noGrad_;
  std::vector<PairValue> ddW_, dsW_, noW_;
  std::vector<ThreadBuffer> threadBuffers_;
  std::vector<Real> qR2_;  // [m^2] max(h, h_i)^2 per dynamic point (variable support only)
  mutable std::vector<std::uint64_t> mortonScratch_;
  double pairKernelSeconds_ = 0.0;  // [s] see pairKernelSeconds()
};

}  // namespace sim
