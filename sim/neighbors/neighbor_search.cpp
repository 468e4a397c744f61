#include "sim/neighbors/neighbor_search.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <sstream>

#include "sim/neighbors/morton.h"

namespace sim {

NeighborSearch::NeighborSearch(const Box& domain, Real supportRadius)
    : NeighborSearch(domain, supportRadius, supportRadius) {}

NeighborSearch::NeighborSearch(const Box& domain, Real supportRadius, Real largestSupport)
    : domain_(domain), radius_(supportRadius), largest_(largestSupport) {
  require(supportRadius > 0.0, "neighbour search: support radius must be > 0 m");
  require(largestSupport >= supportRadius,
          "neighbour search: the largest support must be at least the support radius");
  require(!domain.isEmpty() && domain.volume() > 0.0, "neighbour search: empty domain");
  // Variable support: half-width cells, two cells each way. The 5^3 stencil scans (2.5 R)^3 of
  // candidates against (3 R)^3 for the 3^3 stencil of R-wide cells (42 % fewer at R = 1.25 h).
  reach_ = largestSupport > supportRadius ? 2 : 1;
  invCell_ = reach_ / largestSupport;
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
    bins.cellOf[i] = static_cast<Index>(linear(cellCoords(x[i])));
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
  // Counting sort, serial so that the order inside a cell is the index order (determinism):
  // cellStart[c] counts cell c, then holds the end of c (prefix sums), and placing the points from
  // the last to the first moves it back to the start of c (no second array of cell counters).
  const auto cells = static_cast<std::size_t>(cellCount_);
  bins.cellStart.assign(cells + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++bins.cellStart[bins.cellOf[i]];
  std::partial_sum(bins.cellStart.begin(), bins.cellStart.end() - 1, bins.cellStart.begin());
  bins.cellStart[cells] = static_cast<Index>(n);
  bins.sorted.resize(n);
  bins.sortedX.resize(n);
  bins.slotOf.resize(n);
  for (std::size_t i = n; i-- > 0;) {
    const Index k = --bins.cellStart[bins.cellOf[i]];
    bins.sorted[k] = static_cast<Index>(i);
    bins.slotOf[i] = k;
    bins.sortedX[k] = x[i];
  }
  bins.sortedR2.clear();  // refilled by binRadii for a variable-support update
}

void NeighborSearch::binRadii(const std::vector<Real>& radii, CellBins& bins) {
  const std::size_t n = bins.sorted.size();
  if (radii.size() != n) throw SimError("neighbour search: one support radius per particle needed");
  const Real cell = largest_;
  qR2_.resize(n);
  bins.sortedR2.resize(n);
  bool fits = true;
#pragma omp parallel for schedule(static) reduction(&& : fits)
  for (std::size_t i = 0; i < n; ++i) {
    fits = fits && radii[i] <= cell;
    const Real r = std::max(radius_, radii[i]);
    qR2_[i] = r * r;
  }
  if (!fits)  // (not require(): its message would be built, and allocated, every step)
    throw SimError(
        "neighbour search: a support radius exceeds the largest the grid was built for, " +
        std::to_string(cell) + " m");
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k)
    bins.sortedR2[k] = qR2_[static_cast<std::size_t>(bins.sorted[k])];
  // Per cell, the largest squared radius of its points (0 when empty): the candidate scan skips
  // a cell that lies beyond both the query's radius and every radius inside it, so the bulk,
  // where h_i = h, scans like the fixed-h grid instead of out to the largest support.
  bins.cellMaxR2.resize(static_cast<std::size_t>(cellCount_));
  const std::int64_t cells = cellCount_;
#pragma omp parallel for schedule(static)
  for (std::int64_t c = 0; c < cells; ++c) {
    Real largest = 0.0;
    for (Index k = bins.cellStart[c]; k < bins.cellStart[c + 1]; ++k)
      largest = std::max(largest, bins.sortedR2[k]);
    bins.cellMaxR2[static_cast<std::size_t>(c)] = largest;
  }
}

namespace {

// The capacity reserved for n elements: 25 % headroom, so that a list whose size drifts from step
// to step stops reallocating after the first few steps (reserved, untouched pages are not
// resident memory).
std::size_t withHeadroom(std::size_t n) { return n + n / 4; }

// Grows `v` to at least `n` elements, keeping its contents, with withHeadroom capacity.
template <class T>
void growTo(std::vector<T>& v, std::size_t n) {
  if (v.size() >= n) return;
  if (v.capacity() < n) v.reserve(withHeadroom(n));
  v.resize(n);
}

// Sizes `v` to `n` elements whose old contents are not needed (the final lists, rewritten whole
// after it): when it must grow, the old buffer is released before the larger one is reserved, so
// the peak memory never holds both and nothing is copied.
template <class T>
void sizeDiscarding(std::vector<T>& v, std::size_t n) {
  if (v.capacity() < n) {
    std::vector<T>().swap(v);
    v.reserve(withHeadroom(n));
  }
  v.resize(n);
}

// Slot m of a slot area: Index-sized cells in raw storage, which may be the pair gradients'
// (buildList), so they are written and read as bytes.
inline void putSlot(std::byte* area, std::size_t m, Index k) {
  std::memcpy(area + m * sizeof(Index), &k, sizeof(Index));
}
inline Index getSlot(const std::byte* area, std::size_t m) {
  Index k;
  std::memcpy(&k, area + m * sizeof(Index), sizeof(Index));
  return k;
}

// Stores every slot k of [b, e) at slot m of `area` and advances m when |xi - x_k|^2 < cut(k)
// and k is not `selfSlot` (the query point's own slot, compared without loading its index): no
// unpredictable branch per candidate. kStore false: counts only. `cut` inlines to a constant on
// the fixed-h path.
template <bool kStore, class Cut>
std::size_t scanRange(Index b, Index e, const Vec3& xi, const Vec3* sortedX, Index selfSlot,
                      Cut cut, std::byte* area, std::size_t m) {
  for (Index k = b; k < e; ++k) {
    if constexpr (kStore) putSlot(area, m, k);
    m += static_cast<std::size_t>((xi - sortedX[k]).squaredNorm() < cut(k)) &
         static_cast<std::size_t>(k != selfSlot);
  }
  return m;
}

// Distance [m] from coordinate x to the cell interval [lo, lo + size] along one axis (0 inside).
inline Real gapTo(Real x, Real lo, Real size) { return std::max({lo - x, x - (lo + size), 0.0}); }

// Kernel gradient and value of each pair of query point xi with the points `index[0..count)` of
// px, one square root and one kernel branch per pair; K is the kernel itself, so the choice of
// kernel is made once per list, not per pair. Kernel::gradW's and Kernel::W's arithmetic, stored
// in the pair cache's single precision (pair_precision.h).
template <class K>
void pairKernels(const K& k, Real gradientCutoff, const Vec3& xi, const Vec3* px,
                 const Index* index, std::size_t count, PairGradient* grad, PairValue* values) {
  for (std::size_t a = 0; a < count; ++a) {
    const Vec3 xij = xi - px[index[a]];
    const Real r = xij.norm();
    Real w, dwdr;
    k.evaluate(r, w, dwdr);
    values[a] = static_cast<PairValue>(w);
    grad[a] = r <= gradientCutoff ? PairGradient::Zero().eval()
                                  : (xij * (dwdr / r)).cast<PairGradient::Scalar>().eval();
  }
}

constexpr int kMaxReach = 2;  // [cells] the variable-support stencil's half-width
constexpr int kMaxRows = (2 * kMaxReach + 1) * (2 * kMaxReach + 1);
// Pruning keeps a cell whose distance is within 1e-9 of the radius: rounding in the cell bounds
// must never drop a cell that holds a neighbour.
constexpr Real kPruneSlack = 1.0 + 1e-9;

}  // namespace

struct NeighborSearch::ListQuery {
  const std::vector<Vec3>& qx;
  const CellBins& qbins;
  const CellBins& pbins;
  bool skipSelf;
  const Real* qR2;        // per-query squared radii (variable support), or null
  const Real* pR2;        // the points' squared radii (variable support, dynamic pairs), or null
  const Real* cellMaxR2;  // per cell, the largest of pR2 (with pR2)
  Index* counts;          // per query point i: counts[i] = its accepted pairs (out.offsets + 1)
};

std::size_t NeighborSearch::stencilRows(const ListQuery& q, std::size_t i, StencilRow* rows,
                                        std::size_t& candidates) const {
  const std::int64_t dy = dims_.x(), dz = static_cast<std::int64_t>(dims_.x()) * dims_.y();
  const Vec3 origin = domain_.min();
  const Real cell = 1.0 / invCell_;  // [m]
  auto sq = [](Real v) { return v * v; };
  const std::int64_t c = q.qbins.cellOf[i];
  const std::int64_t cz = c / dz, cy = (c % dz) / dy, cx = c % dy;
  const std::int64_t xlo = std::max<std::int64_t>(cx - reach_, 0);
  const std::int64_t xhi = std::min<std::int64_t>(cx + reach_, dims_.x() - 1);
  const std::int64_t zlo = std::max<std::int64_t>(cz - reach_, 0);
  const std::int64_t zhi = std::min<std::int64_t>(cz + reach_, dims_.z() - 1);
  const std::int64_t ylo = std::max<std::int64_t>(cy - reach_, 0);
  const std::int64_t yhi = std::min<std::int64_t>(cy + reach_, dims_.y() - 1);
  // The stencil's rows, each trimmed to the cells that can hold a point within `prune` of xi
  // (rows and end cells wholly farther away are skipped: every candidate in them would fail the
  // distance test, so the lists are the same, in the same order).
  const Vec3 xi = q.qx[i];
  const Real r2 = radius_ * radius_, maxR2 = largest_ * largest_;
  const Real prune2 = (q.qR2 == nullptr ? r2 : q.pR2 == nullptr ? q.qR2[i] : maxR2) * kPruneSlack;
  Real gx2[kMaxReach * 2 + 1], gy2[kMaxReach * 2 + 1];  // [m^2] squared gaps per column
  for (std::int64_t x = xlo; x <= xhi; ++x)
    gx2[x - xlo] = sq(gapTo(xi.x(), origin.x() + static_cast<Real>(x) * cell, cell));
  for (std::int64_t y = ylo; y <= yhi; ++y)
    gy2[y - ylo] = sq(gapTo(xi.y(), origin.y() + static_cast<Real>(y) * cell, cell));
  const std::int64_t last = xhi - xlo;
  const Index* cellStart = q.pbins.cellStart.data();
  std::size_t count = 0;
  for (std::int64_t z = zlo; z <= zhi; ++z) {
    const Real gz2 = sq(gapTo(xi.z(), origin.z() + static_cast<Real>(z) * cell, cell));
    for (std::int64_t y = ylo; y <= yhi; ++y) {
      const Real left = prune2 - gy2[y - ylo] - gz2;  // [m^2] room left along x
      if (left < 0.0) continue;
      const std::int64_t base = z * dz + y * dy + xlo;
      std::int64_t a = 0, b = last;
      if (q.cellMaxR2 == nullptr) {
        while (a < b && gx2[a] > left) ++a;
        while (b > a && gx2[b] > left) --b;
      } else {  // variable support: a cell is needed within max(h_i, its largest h_j)
        const Real gyz2 = gy2[y - ylo] + gz2;
        auto beyond = [&](std::int64_t x) {
          return gx2[x] + gyz2 > std::max(q.qR2[i], q.cellMaxR2[base + x]) * kPruneSlack;
        };
        while (a < b && beyond(a)) ++a;
        while (b > a && beyond(b)) --b;
        if (a == b && beyond(a)) continue;
      }
      const StencilRow row{cellStart[base + a], cellStart[base + b + 1]};
      if (row.end == row.begin) continue;
      rows[count++] = row;
      candidates += row.end - row.begin;
    }
  }
  return count;
}

namespace {

// One stencil row's candidates of query point i, with the cut of the list's kind.
template <bool kStore>
std::size_t scanRow(Index b, Index e, std::size_t i, const Vec3& xi, const Vec3* sortedX,
                    Index selfSlot, Real r2, const Real* qR2, const Real* pR2, std::byte* area,
                    std::size_t m) {
  if (qR2 == nullptr)  // fixed support
    return scanRange<kStore>(
        b, e, xi, sortedX, selfSlot, [r2](Index) { return r2; }, area, m);
  const Real ri2 = qR2[i];
  if (pR2 == nullptr)  // variable support against walls (support h <= h_i)
    return scanRange<kStore>(
        b, e, xi, sortedX, selfSlot, [ri2](Index) { return ri2; }, area, m);
  return scanRange<kStore>(  // variable support, dynamic pairs: max(h_i, h_j)
      b, e, xi, sortedX, selfSlot, [ri2, pR2](Index k) { return std::max(ri2, pR2[k]); }, area, m);
}

}  // namespace

std::size_t NeighborSearch::scanBlock(const ListQuery& q, std::size_t lo, std::size_t hi,
                                      ThreadBuffer& buf) const {
  const Vec3* sortedX = q.pbins.sortedX.data();
  const Real r2 = radius_ * radius_;
  // Kept in locals, not in `buf`: a slot store through a byte pointer may alias anything, and the
  // threads' buffers are neighbours in memory.
  std::byte* area = buf.area;
  std::size_t room = buf.room, slack = 0, m = 0;
  bool store = true, fits = true;
  StencilRow rows[kMaxRows];
  for (std::size_t i = lo; i < hi; ++i) {
    std::size_t candidates = 0;
    const std::size_t rowCount = stencilRows(q, i, rows, candidates);
    slack = std::max(slack, candidates);
    // Room for every candidate, so that the scan can store each one and advance only on a hit.
    if (store && m + candidates > room) {
      if (buf.grows) {
        growTo(buf.own, m + candidates);
        area = reinterpret_cast<std::byte*>(buf.own.data());
        room = buf.own.size();
      } else {  // a fixed area is full: count the rest (buildList scans again)
        store = false;
        fits = false;
      }
    }
    const Index selfSlot = q.skipSelf ? q.pbins.slotOf[i] : ~Index{0};
    const Vec3 xi = q.qx[i];
    const std::size_t first = m;
    // Stencil order: z, then y, then the x-adjacent cells, one contiguous range.
    for (std::size_t k = 0; k < rowCount; ++k)
      m = store ? scanRow<true>(rows[k].begin, rows[k].end, i, xi, sortedX, selfSlot, r2, q.qR2,
                                q.pR2, area, m)
                : scanRow<false>(rows[k].begin, rows[k].end, i, xi, sortedX, selfSlot, r2, q.qR2,
                                 q.pR2, area, m);
    q.counts[i] = static_cast<Index>(m - first);
  }
  buf.area = area;
  buf.room = room;
  buf.slack = slack;
  buf.fits = fits;
  return m;
}

void NeighborSearch::buildList(const std::vector<Vec3>& qx, const CellBins& qbins,
                               const std::vector<Vec3>& px, const CellBins& pbins, bool skipSelf,
                               const Kernel* kernel, NeighborList& out,
                               std::vector<PairGradient>& grad, std::vector<PairValue>& values,
                               const Real* qR2) {
  const std::size_t n = qx.size();
  out.offsets.resize(n + 1);
  out.offsets[0] = 0;
  const int maxThreads = omp_get_max_threads();
  if (static_cast<int>(threadBuffers_.size()) < maxThreads)
    threadBuffers_.resize(static_cast<std::size_t>(maxThreads));
  const Real* pR2 = qR2 != nullptr && !pbins.sortedR2.empty() ? pbins.sortedR2.data() : nullptr;
  const ListQuery q{qx,
                    qbins,
                    pbins,
                    skipSelf,
                    qR2,
                    pR2,
                    pR2 != nullptr ? pbins.cellMaxR2.data() : nullptr,
                    out.offsets.data() + 1};
  // With a kernel, the scan stages each block's slots in the pair gradients' storage, whose old
  // values are dead until the kernel pass rewrites them: three slots per gradient, so a search
  // holds 20 bytes per pair (index, gradient and value) instead of 24 with a buffer of its own
  // (docs/benchmarks.md, "Memory"). A block whose share of that storage is too small (the first
  // build, or a list grown past the room) is counted instead, and the blocks are scanned again
  // into exact shares.
  static_assert(sizeof(PairGradient) % sizeof(Index) == 0);
  constexpr std::size_t kSlotsPerGradient = sizeof(PairGradient) / sizeof(Index);
  const bool staged = kernel != nullptr;
  bool rescan = false;
  std::size_t total = 0;     // pairs in the list, set once the blocks are scanned
  double kernelStart = 0.0;  // [s] set by the master thread

#pragma omp parallel
  {
    const std::size_t threads = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
    ThreadBuffer& buf = threadBuffers_[t];
    // A contiguous block of query points per thread (as schedule(static)).
    const std::size_t lo = n * t / threads, hi = n * (t + 1) / threads;
    if (staged) {
      const std::size_t slots = grad.size() * kSlotsPerGradient;
      const std::size_t begin = slots * t / threads;
      buf.area = reinterpret_cast<std::byte*>(grad.data()) + begin * sizeof(Index);
      buf.room = slots * (t + 1) / threads - begin;
      buf.grows = false;
    } else {
      buf.grows = true;
      buf.area = reinterpret_cast<std::byte*>(buf.own.data());
      buf.room = buf.own.size();
    }
    buf.count = scanBlock(q, lo, hi, buf);
    // Hysteresis: when less than 1/16 headroom is left, grow to 1.5x this build's size, so that
    // lists that drift from step to step (a fluid settling, a splash) reuse the buffers instead
    // of reallocating at every small growth.
    const std::size_t m = buf.count;
    if (!staged && buf.own.capacity() < m + m / 16 + 1024) {
      buf.own.reserve(m + m / 2 + 1024);
      buf.area = reinterpret_cast<std::byte*>(buf.own.data());
    }
#pragma omp barrier
#pragma omp single
    {
      std::size_t staging = 0;
      for (std::size_t k = 0; k < threads; ++k) {
        threadBuffers_[k].offset = total;
        total += threadBuffers_[k].count;
        staging += threadBuffers_[k].count + threadBuffers_[k].slack;
        rescan = rescan || !threadBuffers_[k].fits;
      }
      if (rescan) {  // exact shares: each block's pairs plus its largest point's candidates
        sizeDiscarding(grad,
                       std::max(total, (staging + kSlotsPerGradient - 1) / kSlotsPerGradient));
        std::byte* area = reinterpret_cast<std::byte*>(grad.data());
        for (std::size_t k = 0; k < threads; ++k) {
          ThreadBuffer& b = threadBuffers_[k];
          b.area = area;
          b.room = b.count + b.slack;
          area += b.room * sizeof(Index);
        }
      }
      sizeDiscarding(out.indices, total);
    }                                       // implicit barrier
    if (rescan) scanBlock(q, lo, hi, buf);  // fits: the same counts
    // Each thread places its block's point indices.
    const Index* sorted = pbins.sorted.data();
    Index* indices = out.indices.data();
    Index running = static_cast<Index>(buf.offset);
    std::size_t slot = 0;
    for (std::size_t i = lo; i < hi; ++i) {
      const Index begin = running;
      running += out.offsets[i + 1];
      out.offsets[i + 1] = running;
      for (Index a = begin; a < running; ++a) indices[a] = sorted[getSlot(buf.area, slot++)];
    }
    if (kernel) {
      // Then the kernel gradient and value of each pair, straight into the final list (the staged
      // slots are dead now). Timed apart from the search proper (pairKernelSeconds()): they are the
      // stages' kernel evaluations done here once, not part of finding neighbours.
#pragma omp barrier
#pragma omp single
      {
        sizeDiscarding(grad, total);
        sizeDiscarding(values, total);
        kernelStart = omp_get_wtime();
      }  // implicit barrier
      for (std::size_t i = lo; i < hi; ++i) {
        const Index begin = out.offsets[i];  // written by the previous block before the barrier
        const std::size_t count = static_cast<std::size_t>(out.offsets[i + 1] - begin);
        const Index* index = indices + begin;
        if (kernel->kind() == KernelKind::kCubicSpline)
          pairKernels(kernel->cubicSpline(), kernel->gradientCutoff(), qx[i], px.data(), index,
                      count, grad.data() + begin, values.data() + begin);
        else
          pairKernels(kernel->wendlandC2(), kernel->gradientCutoff(), qx[i], px.data(), index,
                      count, grad.data() + begin, values.data() + begin);
      }
#pragma omp barrier
#pragma omp master
      pairKernelSeconds_ += omp_get_wtime() - kernelStart;
    }
  }
  if (!kernel) {  // no stale kernel values or gradients for a list built without a kernel
    grad.clear();
    values.clear();
  }
}

void NeighborSearch::setStatic(const std::vector<Vec3>& staticX) {
  staticX_ = staticX;
  bin(staticX_, staticBins_, false);
  buildList(staticX_, staticBins_, staticX_, staticBins_, true, nullptr, ss_, noGrad_, noW_);
  // A one-off list: its scan buffers are not kept (the dynamic lists stage theirs in the pair
  // gradients' storage).
  for (ThreadBuffer& buf : threadBuffers_) std::vector<Index>().swap(buf.own);
}

void NeighborSearch::update(const std::vector<Vec3>& dynamicX) { updateImpl(dynamicX, nullptr); }

void NeighborSearch::update(const std::vector<Vec3>& dynamicX,
                            const std::vector<Real>* supportRadii) {
  updateImpl(dynamicX, nullptr, supportRadii);
}

void NeighborSearch::update(const std::vector<Vec3>& dynamicX, const Kernel& kernel) {
  updateImpl(dynamicX, &kernel);
}

void NeighborSearch::update(const std::vector<Vec3>& dynamicX, const Kernel& kernel,
                            const std::vector<Real>* supportRadii) {
  updateImpl(dynamicX, &kernel, supportRadii);
}

void NeighborSearch::updateImpl(const std::vector<Vec3>& dynamicX, const Kernel* kernel,
                                const std::vector<Real>* supportRadii) {
  pairKernelSeconds_ = 0.0;
  bin(dynamicX, dynamicBins_, true);
  if (supportRadii != nullptr) binRadii(*supportRadii, dynamicBins_);
  const Real* qR2 = supportRadii != nullptr ? qR2_.data() : nullptr;
  buildList(dynamicX, dynamicBins_, dynamicX, dynamicBins_, true, kernel, dd_, ddGrad_, ddW_, qR2);
  if (staticX_.empty()) {
    ds_.offsets.assign(dynamicX.size() + 1, 0);
    ds_.indices.clear();
    dsGrad_.clear();
    dsW_.clear();
  } else {
    buildList(dynamicX, dynamicBins_, staticX_, staticBins_, false, kernel, ds_, dsGrad_, dsW_,
              qR2);
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
  // Ties broken by index: the same order as a stable sort, without its temporary buffer (an
  // allocation every zSortInterval steps).
  std::sort(newToOld.begin(), newToOld.end(),
            [&](Index a, Index b) { return code[a] < code[b] || (code[a] == code[b] && a < b); });
}

}  // namespace sim
