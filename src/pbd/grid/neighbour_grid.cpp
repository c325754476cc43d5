#include "pbd/grid/neighbour_grid.h"

#include <omp.h>

#include <bit>
#include <limits>
#include <stdexcept>
#include <utility>

namespace hs::pbd {
namespace {

// Below this the dense grid is always allowed (tiny inputs would otherwise always hash).
constexpr double kMinDenseCells = 64;
// Cell and bucket counts must fit an Index with room for the end sentinel.
constexpr double kMaxCells = 2147483648.0;  // 2^31
// Morton input coordinates are clamped to 2^40 before coarsening to 21 bits.
constexpr double kMortonMaxCoord = 1099511627776.0;

struct Bounds {
  std::array<double, 3> lo{0, 0, 0};
  std::array<double, 3> hi{0, 0, 0};
};

// Bounding box of the finite positions (non-finite ones cannot be anyone's neighbour).
Bounds finiteBounds(const std::vector<Vec3>& positions) {
  Bounds b;
  constexpr double inf = std::numeric_limits<double>::infinity();
  b.lo = {inf, inf, inf};
  b.hi = {-inf, -inf, -inf};
  for (const Vec3& p : positions) {
    if (!p.allFinite()) continue;
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = std::min(b.lo[a], double(p[a]));
      b.hi[a] = std::max(b.hi[a], double(p[a]));
    }
  }
  if (!(b.lo[0] <= b.hi[0])) b.lo = b.hi = {0, 0, 0};  // no finite position at all
  return b;
}

std::size_t hashBucketCount(std::size_t n, Real perParticle) {
  const double want = std::clamp(double(perParticle) * double(n), 1.0, kMaxCells);
  return std::bit_ceil(std::size_t(want));
}

std::size_t denseCellLimit(std::size_t n, Real perParticle) {
  return std::size_t(std::min(double(perParticle) * double(n) + kMinDenseCells, kMaxCells));
}

}  // namespace

void NeighbourGrid::build(const std::vector<Vec3>& positions, Real cellSize) {
  assert(cellSize > 0 && std::isfinite(double(cellSize)));
  if (positions.size() >= std::size_t(kNoParticle)) throw std::length_error("NeighbourGrid: too many particles");
  const std::size_t n = positions.size();
  m_count = Index(n);
  m_cellSize = cellSize;

  const Bounds b = finiteBounds(positions);

  // Cells are made very slightly larger than cellSize. The caller's distance test runs in Real
  // and may accept a pair whose exact distance exceeds the radius by a few ulps, and the cell
  // coordinates are rounded in double; the margin covers both, so every accepted pair is at
  // most one cell apart on each axis.
  double maxT = 0;
  for (int a = 0; a < 3; ++a) maxT = std::max(maxT, (b.hi[a] - b.lo[a]) / double(cellSize));
  const double margin = 64.0 * double(std::numeric_limits<Real>::epsilon()) +
                        8.0 * std::numeric_limits<double>::epsilon() * (1.0 + std::min(maxT, kMaxCoord));
  m_cells.setCellSize(double(cellSize) * (1.0 + margin));

  // Choose the layout: dense if the box needs few enough cells, else hashed.
  const double cells = m_cells.cover(b.lo, b.hi, kMaxCoord);
  const std::size_t denseLimit = denseCellLimit(n, m_settings.denseCellsPerParticle);
  const std::size_t buckets = hashBucketCount(n, m_settings.hashBucketsPerParticle);
  m_hashed = m_settings.forceHashing || cells > double(denseLimit);
  const std::size_t cellCount = m_hashed ? buckets : std::size_t(cells);
  m_bucketMask = m_hashed ? std::uint64_t(buckets - 1) : 0;

  // Reserve for the largest layout this particle count can choose, so that rebuilding with the
  // same count never reallocates, whichever layout the new positions need.
  if (n != m_reservedFor || m_grid.offsets().capacity() == 0) {
    m_grid.reserve(std::max(denseLimit, buckets), n);
    m_cellOf.reserve(n);
    m_sortedPositions.reserve(n);
    m_reservedFor = n;
  }
  m_cellOf.resize(n);
  m_sortedPositions.resize(n);

  // 1. Cell of each particle. The build stays on one thread: with the keys, the sort and the
  //    gather below in parallel, 100k particles on 2 threads of this shared machine took
  //    85-88 ms CPU against 67-78 ms serial (hs_micro_bench), the barriers costing more than
  //    the O(N) work they split.
  for (std::size_t i = 0; i < n; ++i) m_cellOf[i] = keyOf(positions[i]);
  // 2. Counting sort: each cell lists its particles in increasing index order.
  [[maybe_unused]] const bool fits =
      m_grid.bin(n, cellCount, 1, [this](std::size_t i, auto&& emit) { emit(m_cellOf[i]); });
  assert(fits);  // n < kNoParticle entries
  // 3. Positions in cell order, so that queries stream through memory.
  for (std::size_t k = 0; k < n; ++k) m_sortedPositions[k] = positions[m_grid.item(Index(k))];
}

Index NeighbourGrid::keyOf(const Vec3& x) const {
  const Coord c = cellCoord(x);
  if (m_hashed) return bucketOf(c[0], c[1], c[2]);
  // Finite positions lie inside the box already; clamping only places non-finite ones.
  std::int64_t k[3];
  for (std::size_t a = 0; a < 3; ++a) k[a] = std::clamp<std::int64_t>(c[a], 0, m_cells.dims[a] - 1);
  return Index(m_cells.cellIndex(k[0], k[1], k[2]));
}

void NeighbourGrid::buildNeighbourLists(const std::vector<Vec3>& positions, Real radius, NeighbourLists& lists) const {
  assert(positions.size() == m_count);
  const std::int64_t n = std::int64_t(m_count);
  lists.offsets.assign(std::size_t(n) + 1, 0);
  Index* const offsets = lists.offsets.data();

  // Pass 1: count.
#pragma omp parallel for schedule(dynamic, 256) num_threads(m_settings.threads)
  for (std::int64_t i = 0; i < n; ++i) {
    Index count = 0;
    forEachNeighbour(Index(i), positions, radius, [&count](Index, const Vec3&, Real) { ++count; });
    offsets[i + 1] = count;
  }
  // Prefix sum (serial: O(N) and trivially cheap next to the queries).
  std::uint64_t total = 0;
  for (std::int64_t i = 1; i <= n; ++i) {
    total += offsets[i];
    if (total > std::numeric_limits<Index>::max()) throw std::length_error("NeighbourGrid: too many neighbour pairs");
    offsets[i] = Index(total);
  }
  lists.indices.resize(std::size_t(total));
  Index* const indices = lists.indices.data();

  // Pass 2: fill each particle's own range, then sort it so the order is by j.
#pragma omp parallel for schedule(dynamic, 256) num_threads(m_settings.threads)
  for (std::int64_t i = 0; i < n; ++i) {
    Index k = offsets[i];
    forEachNeighbour(Index(i), positions, radius, [&k, indices](Index j, const Vec3&, Real) { indices[k++] = j; });
    assert(k == offsets[i + 1]);
    std::sort(indices + offsets[i], indices + offsets[i + 1]);
  }
}

void NeighbourGrid::buildSlotNeighbourLists(Real radius, NeighbourLists& lists) {
  assert(radius <= m_cellSize || m_count == 0);
  const std::size_t n = m_count;
  const Real r2 = radius * radius;
  lists.offsets.resize(n + 1);
  lists.offsets[0] = 0;
  const int threads = std::max(1, m_settings.threads);
  if (m_threadLists.size() < std::size_t(threads)) m_threadLists.resize(std::size_t(threads));
  // Below this a fork-join costs more than the queries. At 1,000 particles the lists take a
  // tenth of a PBF step: built by one thread, the other waited (perf), and the 1k dam break ran
  // at ~800 steps/s on 2 threads instead of ~1,000-1,300.
  const bool parallel = threads > 1 && n >= 256;
  std::uint64_t total = 0;
#pragma omp parallel num_threads(threads) if (parallel)
  {
    const std::size_t t = std::size_t(omp_get_thread_num());
    const std::size_t teams = std::size_t(omp_get_num_threads());
    const std::size_t begin = n * t / teams, end = n * (t + 1) / teams;
    std::vector<Index>& buffer = m_threadLists[t];
    std::size_t used = 0;  // entries of buffer in use; its size is only a capacity
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t first = used;
      const Vec3 x = m_sortedPositions[k];
      forEachCandidateRun(Index(k), [&](Index runBegin, Index runEnd) {
        if (buffer.size() < used + (runEnd - runBegin)) buffer.resize(std::max(2 * buffer.size(), used + 4096));
        Index* out = buffer.data();
        // Branch-free append: write every candidate, advance only past the accepted ones
        // (a neighbour test is a coin toss for the branch predictor).
        for (Index j = runBegin; j < runEnd; ++j) {
          out[used] = j;
          used += std::size_t(((x - m_sortedPositions[j]).squaredNorm() < r2) & (j != Index(k)));
        }
      });
      if (m_hashed) std::sort(buffer.begin() + std::ptrdiff_t(first), buffer.begin() + std::ptrdiff_t(used));
      lists.offsets[k + 1] = Index(used - first);
    }
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t k = 1; k <= n; ++k) {
        total += lists.offsets[k];
        lists.offsets[k] = Index(std::min<std::uint64_t>(total, std::numeric_limits<Index>::max()));
      }
      if (total <= std::numeric_limits<Index>::max()) lists.indices.resize(std::size_t(total));
    }
    // The implicit barrier of `single` makes offsets and indices visible to every thread.
    if (total <= std::numeric_limits<Index>::max() && used > 0)
      std::copy(buffer.begin(), buffer.begin() + std::ptrdiff_t(used),
                lists.indices.begin() + std::ptrdiff_t(lists.offsets[begin]));
  }
  if (total > std::numeric_limits<Index>::max()) throw std::length_error("NeighbourGrid: too many neighbour pairs");
}

namespace {

// Spreads the low 21 bits of v so that two zero bits separate consecutive bits.
std::uint64_t spreadBits3(std::uint64_t v) {
  v &= 0x1FFFFFull;
  v = (v | (v << 32)) & 0x1F00000000FFFFull;
  v = (v | (v << 16)) & 0x1F0000FF0000FFull;
  v = (v | (v << 8)) & 0x100F00F00F00F00Full;
  v = (v | (v << 4)) & 0x10C30C30C30C30C3ull;
  v = (v | (v << 2)) & 0x1249249249249249ull;
  return v;
}

}  // namespace

std::vector<Index> mortonOrder(const std::vector<Vec3>& positions, Real cellSize) {
  assert(cellSize > 0);
  const std::size_t n = positions.size();
  const Bounds b = finiteBounds(positions);
  const double inv = 1.0 / double(cellSize);

  // Integer cell coordinates from the box corner; non-finite positions go to the end.
  std::vector<std::array<std::uint64_t, 3>> cells(n);
  std::uint64_t maxCoord = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      double t = (double(positions[i][a]) - b.lo[a]) * inv;
      if (!(t >= 0)) t = 0;
      if (!(t <= kMortonMaxCoord)) t = kMortonMaxCoord;
      cells[i][a] = std::uint64_t(t);
    }
    if (!positions[i].allFinite()) cells[i] = {0, 0, 0};  // sorted last below
    maxCoord = std::max({maxCoord, cells[i][0], cells[i][1], cells[i][2]});
  }
  // A Morton code holds 21 bits per axis; coarsen uniformly if the extent is larger (far
  // outliers), which keeps the ordering a Z-curve of coarser cells.
  int shift = 0;
  while ((maxCoord >> shift) >= (1ull << 21)) ++shift;

  std::vector<std::pair<std::uint64_t, Index>> keys(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& c = cells[i];
    const std::uint64_t code =
        spreadBits3(c[0] >> shift) | (spreadBits3(c[1] >> shift) << 1) | (spreadBits3(c[2] >> shift) << 2);
    keys[i] = {positions[i].allFinite() ? code : ~std::uint64_t(0), Index(i)};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<Index> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = keys[k].second;
  return order;
}

}  // namespace hs::pbd
