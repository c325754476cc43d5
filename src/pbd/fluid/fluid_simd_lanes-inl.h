// Per-instruction-set helpers of fluid_simd.cpp (Highway's -inl.h convention: included once per
// target by foreach_target.h, hence the toggling guard instead of #pragma once). A particle's
// neighbour list is walked in chunks of kFluidSimdLanes = 8 entries, held in kParts vectors of
// MaxLanes(D) lanes; entry k of the list always lands in lane (k - begin) mod 8 of its chunk, so
// the per-lane partial sums, and the fixed order in which they are added, are the same on every
// target. The pair kernels copy the expressions of fluid.cpp and sph_kernels.h operation for
// operation, including Eigen's order for 3-vectors (x0 y0 + (x1 y1 + x2 y2)).
#if defined(HS_PBD_FLUID_SIMD_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef HS_PBD_FLUID_SIMD_LANES_INL_H_
#undef HS_PBD_FLUID_SIMD_LANES_INL_H_
#else
#define HS_PBD_FLUID_SIMD_LANES_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "pbd/fluid/fluid_loops.h"
#include "pbd/fluid/fluid_simd.h"

HWY_BEFORE_NAMESPACE();
namespace hs::pbd::simd::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

// At most 8 lanes of Real: 256-bit vectors on AVX2 and AVX-512 (float), two 128-bit ones on SSE4.
using D = hn::CappedTag<Real, kFluidSimdLanes>;
using V = hn::Vec<D>;
using DI = hn::RebindToSigned<D>;
using VI = hn::Vec<DI>;
using SignedIndex = hn::TFromD<DI>;
inline constexpr std::size_t kLanesPerVector = hn::MaxLanes(D());
inline constexpr std::size_t kParts = kFluidSimdLanes / kLanesPerVector;
static_assert(kParts * kLanesPerVector == kFluidSimdLanes);

// The lanes of one vector of a chunk: list entries [first, first + count), count <= lanes;
// lanes beyond count read particle `pad` (the particle itself, a valid index) and are masked.
// Built in place and passed by reference (`lane` may point into `padded`).
template <class Desc>
struct NeighbourLanes {
  Index first;
  std::size_t count;
  const Index* lane;  // j of each lane
  Index padded[kLanesPerVector];
  VI index;   // j
  VI index3;  // 3 j: the first coordinate of x_j in an AoS Vec3 array
  hn::Mask<Desc> valid;
  bool quadLoads;  // every x_j may be read as 4 Reals (j + 1 < the number of points)
};

template <class Desc>
HWY_INLINE void fillNeighbourLanes(Desc d, NeighbourLanes<Desc>& n, const ListView& lists, Index first,
                                   std::size_t count, Index pad) {
  const DI di;
  n.first = first;
  n.count = count;
  if (count == kLanesPerVector) {
    n.lane = lists.indices + first;
  } else {
    for (std::size_t l = 0; l < kLanesPerVector; ++l) n.padded[l] = l < count ? lists.indices[first + l] : pad;
    n.lane = n.padded;
  }
  if constexpr (sizeof(SignedIndex) == sizeof(Index)) {
    // Index and its signed twin may alias.
    n.index = hn::LoadU(di, reinterpret_cast<const SignedIndex*>(n.lane));
  } else {
    alignas(64) SignedIndex wide[kLanesPerVector];
    for (std::size_t l = 0; l < kLanesPerVector; ++l) wide[l] = SignedIndex(n.lane[l]);
    n.index = hn::Load(di, wide);
  }
  n.index3 = hn::Add(hn::Add(n.index, n.index), n.index);
  n.valid = hn::FirstN(d, count);
  n.quadLoads = hn::AllTrue(di, hn::Lt(n.index, hn::Set(di, SignedIndex(lists.count) - 1)));
}

// Calls lane(part, lanes) for every vector of i's neighbour list, part in [0, kParts) its place
// in the chunk of 8.
template <class Desc, class Lane>
HWY_INLINE void forNeighbourLanes(Desc d, const ListView& lists, Index i, const Lane& lane) {
  const Index begin = lists.offsets[i], end = lists.offsets[i + 1];
  NeighbourLanes<Desc> n;
  for (Index chunk = begin; chunk < end; chunk += Index(kFluidSimdLanes)) {
    for (std::size_t part = 0; part < kParts; ++part) {
      const Index first = chunk + Index(part * kLanesPerVector);
      if (first >= end) break;  // no entries: the lane sums stay as they are (adding zero)
      fillNeighbourLanes(d, n, lists, first, std::min<std::size_t>(kLanesPerVector, end - first), i);
      lane(part, n);
    }
  }
}

// Per-lane partial sums of a chunk of 8, added in a fixed tree at the end.
template <class Desc>
struct Accumulator {
  V part[kParts];
  explicit Accumulator(Desc d) {
    for (V& v : part) v = hn::Zero(d);
  }
  HWY_INLINE void add(std::size_t p, V v) { part[p] = hn::Add(part[p], v); }
  HWY_INLINE void subtract(std::size_t p, V v) { part[p] = hn::Sub(part[p], v); }
  // s_k = l_k + l_{k+4}, t_k = s_k + s_{k+2}, sum = t_0 + t_1: the order of a vector reduction
  // (halves, then pairs), done in registers where the vectors are 8 or 4 floats.
  HWY_INLINE Real sum(Desc d) const {
#if HWY_TARGET != HWY_SCALAR  // which has no shuffles
    constexpr std::size_t lanes = hn::MaxLanes(Desc());  // dependent: discarded branches stay uncompiled
    if constexpr (std::is_same_v<hn::TFromD<Desc>, float> && (lanes == 8 || lanes == 4)) {
      using D4 = hn::Full128<hn::TFromD<Desc>>;
      const hn::Vec<Desc>* const v = part;
      hn::Vec<D4> s4;
      if constexpr (lanes == 8) {
        s4 = hn::Add(hn::LowerHalf(D4(), v[0]), hn::UpperHalf(D4(), v[0]));
      } else {
        s4 = hn::Add(v[0], v[1]);
      }
      const auto t = hn::Add(s4, hn::Shuffle1032(s4));  // s0 + s2, s1 + s3, ...
      return hn::GetLane(hn::Add(t, hn::Shuffle2301(t)));
    }
#endif
    alignas(64) Real l[kFluidSimdLanes];
    for (std::size_t p = 0; p < kParts; ++p) hn::Store(part[p], d, l + p * kLanesPerVector);
    return ((l[0] + l[4]) + (l[2] + l[6])) + ((l[1] + l[5]) + (l[3] + l[7]));
  }
};
static_assert(kFluidSimdLanes == 8, "Accumulator::sum adds exactly 8 lanes");

template <class Desc>
struct Triple {
  V x, y, z;
};

// x_j, y_j, z_j of an AoS Vec3 array by gathers.
template <class Desc>
HWY_INLINE Triple<Desc> gather3(Desc d, const Real* coords, VI index3) {
  return {hn::GatherIndex(d, coords, index3), hn::GatherIndex(d, coords + 1, index3),
          hn::GatherIndex(d, coords + 2, index3)};
}

template <class Desc>
struct Quad {
  V x, y, z, w;
};

#if HWY_TARGET != HWY_SCALAR  // which has no shuffles
// The four Reals at stride * j_l (l the lane) as four vectors: one 4-float load per lane and a
// 4x4 transpose per 128-bit block, faster than gathers. Only for 4 or 8 float lanes.
template <std::size_t kStride, class Desc>
HWY_INLINE Quad<Desc> loadTransposed(Desc d, const Real* base, const Index* lane) {
  constexpr std::size_t lanes = hn::MaxLanes(Desc());
  const hn::Full128<hn::TFromD<Desc>> d4;
  const auto at = [&](std::size_t l) { return hn::LoadU(d4, base + kStride * std::size_t(lane[l])); };
  hn::Vec<Desc> c0, c1, c2, c3;
  if constexpr (lanes == 8) {
    c0 = hn::Combine(d, at(4), at(0));
    c1 = hn::Combine(d, at(5), at(1));
    c2 = hn::Combine(d, at(6), at(2));
    c3 = hn::Combine(d, at(7), at(3));
  } else {
    c0 = at(0), c1 = at(1), c2 = at(2), c3 = at(3);
  }
  const V t0 = hn::InterleaveLower(d, c0, c1);  // x0 x1 y0 y1 (per block)
  const V t1 = hn::InterleaveLower(d, c2, c3);  // x2 x3 y2 y3
  const V t2 = hn::InterleaveUpper(d, c0, c1);  // z0 z1 w0 w1
  const V t3 = hn::InterleaveUpper(d, c2, c3);  // z2 z3 w2 w3
  const hn::Repartition<std::uint64_t, Desc> d64;
  const auto lo = [&](V a, V b) { return hn::BitCast(d, hn::InterleaveLower(d64, hn::BitCast(d64, a), hn::BitCast(d64, b))); };
  const auto hi = [&](V a, V b) { return hn::BitCast(d, hn::InterleaveUpper(d64, hn::BitCast(d64, a), hn::BitCast(d64, b))); };
  return {lo(t0, t1), hi(t0, t1), lo(t2, t3), hi(t2, t3)};
}
#endif

// Whether loadTransposed serves this target: 4 or 8 float lanes (not doubles, not HWY_SCALAR).
template <class Desc>
inline constexpr bool kTransposedLoads =
    std::is_same_v<hn::TFromD<Desc>, float> && (hn::MaxLanes(Desc()) == 8 || hn::MaxLanes(Desc()) == 4);

// x_j, y_j, z_j of an AoS Vec3 array: 4-float loads (x, y, z and the next point's x) where no
// lane is the last point, whose fourth float would lie past the array; gathers otherwise.
template <class Desc>
HWY_INLINE Triple<Desc> loadPoints(Desc d, const Real* coords, const NeighbourLanes<Desc>& n) {
#if HWY_TARGET != HWY_SCALAR
  if constexpr (kTransposedLoads<Desc>) {
    if (n.quadLoads) {
      const Quad<Desc> q = loadTransposed<3>(d, coords, n.lane);
      return {q.x, q.y, q.z};
    }
  }
#endif
  return gather3(d, coords, n.index3);
}

// x_j, y_j, z_j, w_j of an array of 4 Reals per point.
template <class Desc>
HWY_INLINE Quad<Desc> loadQuads(Desc d, const Real* quads, const NeighbourLanes<Desc>& n) {
#if HWY_TARGET != HWY_SCALAR
  if constexpr (kTransposedLoads<Desc>) return loadTransposed<4>(d, quads, n.lane);
#endif
  const VI index4 = hn::Add(n.index, n.index3);
  return {hn::GatherIndex(d, quads, index4), hn::GatherIndex(d, quads + 1, index4),
          hn::GatherIndex(d, quads + 2, index4), hn::GatherIndex(d, quads + 3, index4)};
}

template <class Desc>
struct Pair {
  V dx, dy, dz;  // r_ij = x_i - x_j
  V r2;          // |r_ij|^2
};

HWY_INLINE V dot(V ax, V ay, V az, V bx, V by, V bz) {
  return hn::Add(hn::Mul(ax, bx), hn::Add(hn::Mul(ay, by), hn::Mul(az, bz)));
}
HWY_INLINE V squaredNorm(V x, V y, V z) { return dot(x, y, z, x, y, z); }

template <class Desc>
HWY_INLINE Pair<Desc> pairAt(Desc d, const Real* coords, const NeighbourLanes<Desc>& n, V xi, V yi, V zi) {
  const Triple<Desc> xj = loadPoints(d, coords, n);
  Pair<Desc> p{hn::Sub(xi, xj.x), hn::Sub(yi, xj.y), hn::Sub(zi, xj.z), hn::Zero(d)};
  p.r2 = squaredNorm(p.dx, p.dy, p.dz);
  return p;
}

// r_ij from an array of (x, y, z, w) per point; w_j comes back in `w`.
template <class Desc>
HWY_INLINE Pair<Desc> pairAtQuads(Desc d, const Real* quads, const NeighbourLanes<Desc>& n, V xi, V yi, V zi, V& w) {
  const Quad<Desc> q = loadQuads(d, quads, n);
  w = q.w;
  Pair<Desc> p{hn::Sub(xi, q.x), hn::Sub(yi, q.y), hn::Sub(zi, q.z), hn::Zero(d)};
  p.r2 = squaredNorm(p.dx, p.dy, p.dz);
  return p;
}

template <class Desc>
struct KernelConstants {
  V zero, one, h, h2, invH, invH2, poly6Coeff, spikyGradCoeff, minRadius;
  KernelConstants(Desc d, const SphKernels& k)
      : zero(hn::Zero(d)), one(hn::Set(d, Real(1))), h(hn::Set(d, k.h)), h2(hn::Set(d, k.h2)),
        invH(hn::Set(d, k.invH)), invH2(hn::Set(d, k.invH2)), poly6Coeff(hn::Set(d, k.poly6Coeff)),
        spikyGradCoeff(hn::Set(d, k.spikyGradCoeff)), minRadius(hn::Set(d, Real(1e-6) * k.h)) {}
};

// poly6 of sph_kernels.h: W = c (1 - r^2/h^2)^3 for r^2 < h^2, else 0.
template <class Desc>
HWY_INLINE V poly6(const KernelConstants<Desc>& k, hn::Mask<Desc> valid, V r2) {
  const V t = hn::Sub(k.one, hn::Mul(r2, k.invH2));
  return hn::IfThenElseZero(hn::And(valid, hn::Lt(r2, k.h2)), hn::Mul(k.poly6Coeff, hn::Mul(hn::Mul(t, t), t)));
}

// poly6Clamped of fluid.cpp; `inside` = valid and r^2 < h^2.
template <class Desc>
HWY_INLINE V poly6Clamped(const KernelConstants<Desc>& k, hn::Mask<Desc> inside, V r2) {
  const V t = hn::Max(k.zero, hn::Sub(k.one, hn::Mul(r2, k.invH2)));
  return hn::IfThenElseZero(inside, hn::Mul(k.poly6Coeff, hn::Mul(hn::Mul(t, t), t)));
}

// spikyGradientScale of fluid.cpp: s with grad W_spiky(r_ij) = s r_ij; `inside` as above.
template <class Desc>
HWY_INLINE V spikyGradientScale(const KernelConstants<Desc>& k, hn::Mask<Desc> inside, V r2) {
  const V r = hn::Sqrt(r2);
  const V q = hn::Max(k.zero, hn::Sub(k.one, hn::Mul(r, k.invH)));
  const V s = hn::Div(hn::Mul(hn::Mul(k.spikyGradCoeff, q), q), hn::Max(r, k.minRadius));
  return hn::IfThenElseZero(inside, s);
}

// The factor of spikyGradient of sph_kernels.h: grad W = s r_ij for 0 < r < h, else 0.
template <class Desc>
HWY_INLINE V spikyGradientFactor(const KernelConstants<Desc>& k, hn::Mask<Desc> valid, V r2) {
  const V r = hn::Sqrt(r2);
  const V t = hn::Sub(k.one, hn::Mul(r, k.invH));
  const auto inside = hn::And(valid, hn::And(hn::Lt(r, k.h), hn::Gt(r, k.zero)));
  return hn::IfThenElseZero(inside, hn::Div(hn::Mul(hn::Mul(k.spikyGradCoeff, t), t), r));
}

// Per-pair values at list entries [first, first + count) (the pair-gradient cache).
template <class Desc>
HWY_INLINE void storeLanes(Desc d, V v, Real* out, const NeighbourLanes<Desc>& n) {
  if (n.count == kLanesPerVector) {
    hn::StoreU(v, d, out + n.first);
    return;
  }
  alignas(64) Real buffer[kLanesPerVector];
  hn::Store(v, d, buffer);
  std::copy_n(buffer, n.count, out + n.first);
}

template <class Desc>
HWY_INLINE V loadLanes(Desc d, const Real* in, const NeighbourLanes<Desc>& n) {
  if (n.count == kLanesPerVector) return hn::LoadU(d, in + n.first);
  alignas(64) Real buffer[kLanesPerVector] = {};
  std::copy_n(in + n.first, n.count, buffer);
  return hn::Load(d, buffer);
}

}  // namespace hs::pbd::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // HS_PBD_FLUID_SIMD_LANES_INL_H_ toggle
