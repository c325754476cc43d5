#pragma once
// Lower bounds of the distances from a point to the wall triangles a cell of WallTriangleGrid
// lists (wall_density.h): for each, the larger of the squared distances to its box and to its
// plane, each less a slack, so that rounding never lifts a bound above the distance
// the closest point computes (a triangle whose nearest point is a corner of its box). One pass
// over the entries' contiguous copies, in SIMD with Highway's runtime dispatch where the build
// has it (wall_bounds_simd.cpp), else the scalar loop in wall_density.cpp. Both evaluate the same
// expression operation for operation (min, max, abs and unfused products and sums are exact in
// any lane width), so the bounds, and the walls found, are bitwise the same either way.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "pbd/core/types.h"

namespace hs::pbd {

// The entries [0, n) of a cell: box corners per axis, plane n . x = c per component; the slack
// of every bound.
struct WallBoundsJob {
  const Real* lo[3];
  const Real* hi[3];
  const Real* plane[4];
  Real slack;
  Real px, py, pz;
  std::size_t n;
};

// Extra entries every array of a WallBoundsJob can be read past its last (zeros), so that the
// SIMD pass runs whole vectors; `out` holds n plus as many.
inline constexpr std::size_t kWallBoundsPadding = 16;

// The bound of entry k, as the SIMD pass computes it.
HS_KERNEL Real wallCandidateBound(const WallBoundsJob& job, std::size_t k) {
  // Each distance less the slack: the box's per axis (the box grown by it), the plane's.
  const Real slack = job.slack;
  const auto axis = [&](Real p, Real lo, Real hi) {
    return std::max(std::abs(p - std::min(std::max(p, lo), hi)) - slack, Real(0));
  };
  const Real dx = axis(job.px, job.lo[0][k], job.hi[0][k]);
  const Real dy = axis(job.py, job.lo[1][k], job.hi[1][k]);
  const Real dz = axis(job.pz, job.lo[2][k], job.hi[2][k]);
  const Real side = job.plane[0][k] * job.px + job.plane[1][k] * job.py + job.plane[2][k] * job.pz - job.plane[3][k];
  const Real plane = std::max(std::abs(side) - slack, Real(0));
  return std::max(dx * dx + dy * dy + dz * dz, plane * plane);
}

// The smallest of a cell's bounds and the first entry that has it.
struct WallBoundsMinimum {
  Real bound;
  std::size_t first;
};

// out[k] = wallCandidateBound(job, k) for k in [0, n), +infinity for the padding after n (`out`
// holds n + kWallBoundsPadding), and their minimum.
WallBoundsMinimum wallCandidateBounds(const WallBoundsJob& job, Real* out);

// 64-bit words that hold a bit for each of n entries and their padding.
inline constexpr std::size_t wallCandidateWords(std::size_t n) { return (n + kWallBoundsPadding + 63) / 64; }

// Bit k % 64 of words[k / 64] set where bounds[k] <= threshold, for k in [0, n) (the padding's
// +infinity is never set): the candidates a query still has to try. `words` holds
// wallCandidateWords(n).
void wallCandidatesWithin(const Real* bounds, std::size_t n, Real threshold, std::uint64_t* words);

}  // namespace hs::pbd
