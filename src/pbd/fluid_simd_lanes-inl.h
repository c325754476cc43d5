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

#include "pbd/fluid_loops.h"
#include "pbd/fluid_simd.h"

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
template <class Desc>
struct NeighbourLanes {
  Index first;
  std::size_t count;
  VI index;   // j
  VI index3;  // 3 j: the first coordinate of x_j in an AoS Vec3 array
  hn::Mask<Desc> valid;
};

template <class Desc>
HWY_INLINE NeighbourLanes<Desc> neighbourLanes(Desc d, const Index* indices, Index first, std::size_t count,
                                               Index pad) {
  const DI di;
  VI j;
  if constexpr (sizeof(SignedIndex) == sizeof(Index)) {
    // Index and its signed twin may alias; a full vector is read in place.
    if (count == kLanesPerVector) {
      j = hn::LoadU(di, reinterpret_cast<const SignedIndex*>(indices + first));
    } else {
      alignas(64) SignedIndex buffer[kLanesPerVector];
      for (std::size_t l = 0; l < kLanesPerVector; ++l)
        buffer[l] = SignedIndex(l < count ? indices[first + l] : pad);
      j = hn::Load(di, buffer);
    }
  } else {
    alignas(64) SignedIndex buffer[kLanesPerVector];
    for (std::size_t l = 0; l < kLanesPerVector; ++l) buffer[l] = SignedIndex(l < count ? indices[first + l] : pad);
    j = hn::Load(di, buffer);
  }
  return {first, count, j, hn::Add(hn::Add(j, j), j), hn::FirstN(d, count)};
}

// Calls lane(part, lanes) for every vector of i's neighbour list, part in [0, kParts) its place
// in the chunk of 8.
template <class Desc, class Lane>
HWY_INLINE void forNeighbourLanes(Desc d, const ListView& lists, Index i, const Lane& lane) {
  const Index begin = lists.offsets[i], end = lists.offsets[i + 1];
  for (Index chunk = begin; chunk < end; chunk += Index(kFluidSimdLanes)) {
    for (std::size_t part = 0; part < kParts; ++part) {
      const Index first = chunk + Index(part * kLanesPerVector);
      if (first >= end) break;  // no entries: the lane sums stay as they are (adding zero)
      const std::size_t count = std::min<std::size_t>(kLanesPerVector, end - first);
      lane(part, neighbourLanes(d, lists.indices, first, count, i));
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
  // ((l0 + l1) + (l2 + l3)) + ((l4 + l5) + (l6 + l7)).
  HWY_INLINE Real sum(Desc d) const {
    alignas(64) Real l[kFluidSimdLanes];
    for (std::size_t p = 0; p < kParts; ++p) hn::Store(part[p], d, l + p * kLanesPerVector);
    return ((l[0] + l[1]) + (l[2] + l[3])) + ((l[4] + l[5]) + (l[6] + l[7]));
  }
};
static_assert(kFluidSimdLanes == 8, "Accumulator::sum adds exactly 8 lanes");

template <class Desc>
struct Triple {
  V x, y, z;
};

// x_j, y_j, z_j of an AoS Vec3 array.
template <class Desc>
HWY_INLINE Triple<Desc> gather3(Desc d, const Real* coords, VI index3) {
  return {hn::GatherIndex(d, coords, index3), hn::GatherIndex(d, coords + 1, index3),
          hn::GatherIndex(d, coords + 2, index3)};
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
  const Triple<Desc> xj = gather3(d, coords, n.index3);
  Pair<Desc> p{hn::Sub(xi, xj.x), hn::Sub(yi, xj.y), hn::Sub(zi, xj.z), hn::Zero(d)};
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
