// wallCandidateBounds (wall_bounds.h) in SIMD with Highway's runtime dispatch: this file is
// compiled once per instruction set (foreach_target.h) and the best one the machine has runs.
// Each lane evaluates wallCandidateBound's expression for one entry, operation for operation.
#include "pbd/fluid/wall_bounds.h"

#include <limits>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pbd/fluid/wall_bounds_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace hs::pbd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

WallBoundsMinimum WallBoundsRange(const WallBoundsJob& job, Real* out) {
  const hn::CappedTag<Real, kWallBoundsPadding> d;
  const std::size_t lanes = hn::Lanes(d);
  const auto px = hn::Set(d, job.px), py = hn::Set(d, job.py), pz = hn::Set(d, job.pz);
  const auto zero = hn::Zero(d), infinity = hn::Inf(d), slack = hn::Set(d, job.slack);
  auto minimum = infinity;
  // Whole vectors past n read the arrays' padding (kWallBoundsPadding); their lanes beyond n
  // are stored as +infinity.
  for (std::size_t k = 0; k < job.n; k += lanes) {
    const auto axis = [&](auto p, const Real* lo, const Real* hi) {
      const auto outside = hn::Sub(p, hn::Min(hn::Max(p, hn::LoadU(d, lo + k)), hn::LoadU(d, hi + k)));
      return hn::Max(hn::Sub(hn::Abs(outside), slack), zero);
    };
    const auto dx = axis(px, job.lo[0], job.hi[0]);
    const auto dy = axis(py, job.lo[1], job.hi[1]);
    const auto dz = axis(pz, job.lo[2], job.hi[2]);
    const auto side = hn::Sub(hn::Add(hn::Add(hn::Mul(hn::LoadU(d, job.plane[0] + k), px),
                                              hn::Mul(hn::LoadU(d, job.plane[1] + k), py)),
                                      hn::Mul(hn::LoadU(d, job.plane[2] + k), pz)),
                              hn::LoadU(d, job.plane[3] + k));
    const auto plane = hn::Max(hn::Sub(hn::Abs(side), slack), zero);
    const auto box = hn::Add(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)), hn::Mul(dz, dz));
    const auto bound = hn::IfThenElse(hn::FirstN(d, job.n - k), hn::Max(box, hn::Mul(plane, plane)), infinity);
    minimum = hn::Min(minimum, bound);
    hn::StoreU(bound, d, out + k);
  }
  const std::size_t whole = (job.n + lanes - 1) / lanes * lanes;
  for (std::size_t k = whole; k < job.n + kWallBoundsPadding; ++k) out[k] = std::numeric_limits<Real>::infinity();
  const Real smallest = hn::GetLane(hn::MinOfLanes(d, minimum));
  const auto target = hn::Set(d, smallest);
  for (std::size_t k = 0; k < job.n; k += lanes) {
    const intptr_t lane = hn::FindFirstTrue(d, hn::Eq(hn::LoadU(d, out + k), target));
    if (lane >= 0) return {smallest, k + std::size_t(lane)};
  }
  return {smallest, job.n};
}

void CandidatesWithin(const Real* bounds, std::size_t n, Real threshold, std::uint64_t* words) {
  const hn::CappedTag<Real, kWallBoundsPadding> d;
  const std::size_t lanes = hn::Lanes(d);  // 2, 4, 8 or 16: a vector's bits never straddle two words
  const auto limit = hn::Set(d, threshold);
  for (std::size_t w = 0; w < wallCandidateWords(n); ++w) words[w] = 0;
  for (std::size_t k = 0; k < n; k += lanes) {
    std::uint8_t bits[8] = {};
    hn::StoreMaskBits(d, hn::Le(hn::LoadU(d, bounds + k), limit), bits);
    const std::uint64_t mask = std::uint64_t(bits[0]) | std::uint64_t(bits[1]) << 8;
    words[k / 64] |= mask << (k % 64);
  }
}

}  // namespace hs::pbd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace hs::pbd {

HWY_EXPORT(WallBoundsRange);
HWY_EXPORT(CandidatesWithin);

WallBoundsMinimum wallCandidateBounds(const WallBoundsJob& job, Real* out) {
  return HWY_DYNAMIC_DISPATCH(WallBoundsRange)(job, out);
}

void wallCandidatesWithin(const Real* bounds, std::size_t n, Real threshold, std::uint64_t* words) {
  HWY_DYNAMIC_DISPATCH(CandidatesWithin)(bounds, n, threshold, words);
}

}  // namespace hs::pbd
#endif  // HWY_ONCE
