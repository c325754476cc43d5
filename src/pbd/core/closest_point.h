#pragma once
// The point of triangle abc closest to p, for any Eigen 3-vector type (float for the solver's
// contacts, double for the mesher): by the Voronoi regions of the corners, then the edges, then
// the face (Ericson 2005, "Real-Time Collision Detection", 5.1.5, ClosestPtPointTriangle).
// A degenerate triangle (no face region: va + vb + vc <= 0, or NaN) gives the corner a.
namespace hs::pbd {

template <class V>
V closestPointOnTriangleOf(const V& p, const V& a, const V& b, const V& c) {
  using S = typename V::Scalar;
  const V ab = b - a, ac = c - a, ap = p - a;
  const S d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const V bp = p - b;
  const S d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const S vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const V cp = p - c;
  const S d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const S vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const S va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const S sum = va + vb + vc;
  if (!(sum > 0)) return a;
  const S denom = S(1) / sum;
  return a + (vb * denom) * ab + (vc * denom) * ac;
}

}  // namespace hs::pbd
