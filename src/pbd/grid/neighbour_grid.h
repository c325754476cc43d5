#pragma once
// Fixed-radius neighbour search for particle fluids (Position Based Fluids, Macklin & Mueller
// 2013, "Position Based Fluids", ACM TOG 32(4)). The layout follows Green 2010, "Particle
// Simulation using CUDA" (NVIDIA whitepaper): a uniform grid whose cell edge equals the kernel
// support radius h, particles sorted by cell, and a per-cell [begin, end) range into the sorted
// array.
//
// Why these choices:
//  * Cell edge = support radius: any particle closer than h lies in the same cell or one of the
//    26 cells around it, so a query scans exactly 27 cells (3 contiguous rows of 3 cells in
//    the dense layout).
//  * Counting sort (histogram, prefix sum, scatter) instead of a comparison sort: the keys are
//    small integers, so the sort is O(N) and needs no per-step allocation once the buffers have
//    grown to their working size (they are reused between builds).
//  * Positions are copied in cell order during the scatter, so a query streams through
//    contiguous memory instead of gathering from the caller's array.
//  * Bounds are recomputed every build, so particles may go anywhere. When the bounding box
//    would need far more cells than particles (a few particles escaped far away), cells are
//    hashed into ~2N buckets instead; a bucket may then hold several real cells, which is
//    harmless because every candidate is filtered by distance anyway.
//  * mortonOrder() gives a Z-order permutation of the particles by cell: applying it now and
//    then to all particle arrays keeps spatial neighbours close in memory (cache locality).
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <vector>

#include "pbd/core/types.h"
#include "pbd/grid/cell_grid.h"

namespace hs::pbd {

struct NeighbourGridSettings {
  int threads = 1;                   // OpenMP threads for buildNeighbourLists
  Real denseCellsPerParticle = 4;    // dense grid allowed up to this many cells per particle
  Real hashBucketsPerParticle = 2;   // bucket count of the hashed fallback (rounded to 2^k)
  bool forceHashing = false;         // always use the hashed layout (tests, benchmarks)
};

// Compressed sparse rows: the neighbours of i are indices[offsets[i] .. offsets[i+1]), in
// increasing order.
struct NeighbourLists {
  std::vector<Index> offsets;  // particle count + 1 entries
  std::vector<Index> indices;
};

class NeighbourGrid {
 public:
  explicit NeighbourGrid(NeighbourGridSettings settings = {}) : m_settings(settings) {}

  const NeighbourGridSettings& settings() const { return m_settings; }
  void setSettings(const NeighbourGridSettings& s) { m_settings = s; }

  // Sorts the particles into cells of edge cellSize (normally the kernel support radius h).
  // The grid keeps a copy of the positions: queries see the positions as of this call.
  void build(const std::vector<Vec3>& positions, Real cellSize);

  // Calls f(j, r_ij, |r_ij|^2) with r_ij = x_i - x_j for every j != i with |r_ij| < radius
  // (strictly). Requires radius <= cellSize and `positions` unchanged since build().
  // Visiting order is by cell, not by j.
  template <class F>
  void forEachNeighbour(Index i, const std::vector<Vec3>& positions, Real radius, F&& f) const {
    assert(i < m_count && positions.size() == m_count);
    query(positions[i], radius, i, f);
  }

  // Same for an arbitrary point x (every particle j with |x - x_j| < radius; r = x - x_j).
  template <class F>
  void forEachNeighbourOfPoint(const Vec3& x, Real radius, F&& f) const {
    query(x, radius, kNoParticle, f);
  }

  // All neighbour lists at once, in parallel over particles (settings().threads). Each particle
  // writes only its own range: count, prefix sum, fill, then sort the range, so the result is
  // identical for any thread count. Buffers of `lists` are reused.
  void buildNeighbourLists(const std::vector<Vec3>& positions, Real radius, NeighbourLists& lists) const;

  // The same lists in cell order, the fast path of the fluid solver: slot k is the particle
  // sortedIndices()[k] at sortedPositions()[k], and lists name slots, not particle ids. In the
  // dense layout the 9 runs of a query come in increasing slot order, so every list is sorted
  // without sorting and neighbours are close in memory. One pass: each thread fills its own
  // buffer for a contiguous range of slots, then the buffers are concatenated in slot order,
  // so the result is identical for any thread count. Buffers are reused between builds.
  void buildSlotNeighbourLists(Real radius, NeighbourLists& lists);

  Index particleCount() const { return m_count; }
  Real cellSize() const { return m_cellSize; }
  bool hashed() const { return m_hashed; }
  Index cellCount() const { return Index(m_grid.cellCount()); }

  // Runtime buffers, exposed for tests (allocation reuse) and diagnostics.
  const std::vector<Index>& cellStarts() const { return m_grid.offsets(); }
  const std::vector<Index>& sortedIndices() const { return m_grid.items(); }
  const std::vector<Index>& particleCells() const { return m_cellOf; }
  const std::vector<Vec3>& sortedPositions() const { return m_sortedPositions; }

 private:
  using Coord = std::array<std::int64_t, 3>;
  static constexpr Index kNoParticle = ~Index(0);
  // Cell coordinates are clamped to +-2^40: clamping is monotone, so it only merges cells
  // (never separates two particles by more than one cell), which keeps queries correct.
  static constexpr double kMaxCoord = 1099511627776.0;  // 2^40

  Coord cellCoord(const Vec3& x) const {
    Coord c;
    for (int a = 0; a < 3; ++a) {
      double t = m_cells.axisCoord(double(x[a]), a);
      if (!(t >= -kMaxCoord)) t = -kMaxCoord;  // also NaN: such a particle has no neighbours
      if (t > kMaxCoord) t = kMaxCoord;
      c[a] = std::int64_t(std::floor(t));
    }
    return c;
  }

  Index bucketOf(std::int64_t x, std::int64_t y, std::int64_t z) const {
    std::uint64_t h = std::uint64_t(x) * 0x9E3779B97F4A7C15ull ^ std::uint64_t(y) * 0xC2B2AE3D27D4EB4Full ^
                      std::uint64_t(z) * 0x165667B19E3779F9ull;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return Index(h & m_bucketMask);
  }

  // The cell (dense layout) or bucket (hashed) of a particle at x.
  Index keyOf(const Vec3& x) const;

  template <class F>
  void scan(Index begin, Index end, const Vec3& x, Real r2, Index skip, F& f) const {
    for (Index k = begin; k < end; ++k) {
      const Index j = m_grid.item(k);
      if (j == skip) continue;
      const Vec3 r = x - m_sortedPositions[k];
      const Real d2 = r.squaredNorm();
      if (d2 < r2) f(j, r, d2);
    }
  }

  // Calls run(begin, end) for every run of slots [begin, end) that may hold neighbours of
  // slot k: 9 runs of 3 cells in the dense layout (in increasing slot order), the distinct
  // buckets around it in the hashed layout.
  template <class F>
  void forEachCandidateRun(Index k, F&& run) const {
    if (!m_hashed) {
      const auto key = std::int64_t(m_cellOf[m_grid.item(k)]);
      const Coord& d = m_cells.dims;
      const Coord c{key % d[0], (key / d[0]) % d[1], key / (d[0] * d[1])};
      forEachRunAround(c, run);
    } else {
      forEachRunAround(cellCoord(m_sortedPositions[k]), run);
    }
  }

  // The runs of slots in the 27 cells around cell c. Dense layout: cells (x-1..x+1, y, z) are
  // consecutive, so 9 ranges, not 27 (none when c lies outside the grid on the x axis).
  // Hashed: the 27 cells may share buckets; each bucket is visited once.
  template <class F>
  void forEachRunAround(const Coord& c, F& run) const {
    if (!m_hashed) {
      CellBox r;
      for (std::size_t a = 0; a < 3; ++a) {
        r.lo[a] = std::max<std::int64_t>(c[a] - 1, 0);
        r.hi[a] = std::min(c[a] + 1, m_cells.dims[a] - 1);
      }
      if (r.lo[0] > r.hi[0]) return;
      m_grid.forEachRun(m_cells, r, run);
      return;
    }
    std::array<Index, 27> buckets;
    int n = 0;
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) buckets[std::size_t(n++)] = bucketOf(c[0] + dx, c[1] + dy, c[2] + dz);
    std::sort(buckets.begin(), buckets.end());
    const auto last = std::unique(buckets.begin(), buckets.end());
    for (auto b = buckets.begin(); b != last; ++b) run(m_grid.begin(*b), m_grid.end(*b));
  }

  template <class F>
  void query(const Vec3& x, Real radius, Index skip, F& f) const {
    assert(radius <= m_cellSize || m_count == 0);
    if (m_count == 0) return;
    const Real r2 = radius * radius;
    auto scanRun = [&](Index begin, Index end) { scan(begin, end, x, r2, skip, f); };
    forEachRunAround(cellCoord(x), scanRun);
  }

  NeighbourGridSettings m_settings;

  // Runtime state of the last build.
  Index m_count = 0;
  Real m_cellSize = 0;
  CellIndexing m_cells;                 // edge cellSize * (1 + safety margin), see build(); dims: dense layout
  bool m_hashed = false;
  std::uint64_t m_bucketMask = 0;       // hashed layout only
  CellGrid m_grid;                      // particle indices by cell (or bucket); ascending within a cell
  std::vector<Index> m_cellOf;          // cell (or bucket) of each particle
  std::vector<Vec3> m_sortedPositions;  // positions in the order of m_grid.items()
  std::size_t m_reservedFor = 0;        // particle count the cell buffer was reserved for
  std::vector<std::vector<Index>> m_threadLists;  // per-thread buffers of buildSlotNeighbourLists
};

// Permutation sorting particles along a Z-order (Morton) curve of their grid cells (edge
// cellSize), ties broken by index. order[k] is the old index of the particle that goes to slot
// k; apply it with applyOrder to every particle array. Z-order keeps particles of nearby cells
// close in memory, so the 27-cell scans and the constraint loops hit the cache.
std::vector<Index> mortonOrder(const std::vector<Vec3>& positions, Real cellSize);

// out[k] = in[order[k]].
template <class T, class A>
void applyOrder(std::vector<T, A>& values, const std::vector<Index>& order) {
  assert(values.size() == order.size());
  std::vector<T, A> out;
  out.reserve(values.size());
  for (const Index o : order) out.push_back(values[o]);
  values.swap(out);
}

}  // namespace hs::pbd
