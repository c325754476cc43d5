#pragma once
// A bounding volume hierarchy over a triangle mesh whose topology is fixed and whose vertices
// move: the broad phase of continuous (swept) contact (swept_contact.h).
//
// Why these choices:
//  * Built once, refitted every step. The tree's shape (which triangles share a node) comes
//    from the first positions, by median splits of the triangle centroids along the longest
//    axis. A wall that beats deforms smoothly, so neighbours stay neighbours and the refitted
//    boxes stay tight; a refit is O(triangles) with no sorting (van den Bergen 1997,
//    "Efficient collision detection of complex deformable models using AABB trees").
//  * Swept boxes. A triangle's box is the box of its three vertices at the start AND at the
//    end of the step, grown by a margin: a triangle moving linearly between the two stays in
//    it for the whole step (the box of a convex combination of points lies in the box of the
//    points), so a point that meets the triangle at any time of the step lies in its box.
//  * Exact against brute force. A query tests each triangle's own box at the leaves, so it
//    returns exactly the triangles whose box the padded segment touches; an inner node's box
//    is the min/max of its children's (exact in floating point) and the segment test is
//    monotone in the box (IEEE operations round monotonically), so no touching leaf is
//    pruned by a parent.
//  * Parallel refit, bitwise the same for any thread count: triangle boxes and leaf boxes are
//    written one per loop iteration (OpenMP), inner nodes by one thread children first; min
//    and max do not depend on the order anyway.
//  * Queries are const: safe from any number of threads at once.
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <algorithm>
#include <vector>

#include "pbd/core/tet_mesh.h"
#include "pbd/core/types.h"
#include "pbd/grid/box_grid.h"

namespace hs::pbd {

// A segment a -> b grown by pad, prepared for many box tests: its own box (a cheap first
// reject: most boxes a short step is tested against are nowhere near it) and, per axis, the
// reciprocal of its extent for the slab test (Kay & Kajiya 1986). In double.
class SegmentQuery {
 public:
  SegmentQuery(const Vec3& a, const Vec3& b, Real pad);
  // Whether the segment meets the box grown by pad on every side (boundary included). False
  // for a non-finite segment or an empty box. Monotone in the box: a box containing another
  // is touched whenever the other is (IEEE operations round monotonically).
  [[nodiscard]] bool touches(const Box3& box) const {
    if (!m_finite) return false;
    double enter = 0, leave = 1;
    for (int k = 0; k < 3; ++k) {
      const double lo = double(box.lo[k]) - m_pad, hi = double(box.hi[k]) + m_pad;
      if (!(lo <= m_hi[k] && m_lo[k] <= hi)) return false;  // boxes apart (or the box empty)
      if (m_flat[k]) continue;  // within the slab for all s: the box test above was exact
      // The segment a + s (b - a) is inside slab k for s between (lo - a_k) / d_k and
      // (hi - a_k) / d_k.
      double s0 = (lo - m_a[k]) * m_inverse[k], s1 = (hi - m_a[k]) * m_inverse[k];
      if (s0 > s1) std::swap(s0, s1);
      enter = std::max(enter, s0);
      leave = std::min(leave, s1);
      if (enter > leave) return false;
    }
    return true;
  }

  // The segment's box grown by pad, and by a relative hair more: a box that touches() accepts
  // overlaps it whatever the rounding of lo - pad against hi + pad. Not finite when the segment
  // is not.
  [[nodiscard]] std::array<double, 3> paddedLo() const { return padded(m_lo, -1); }
  [[nodiscard]] std::array<double, 3> paddedHi() const { return padded(m_hi, +1); }

 private:
  std::array<double, 3> padded(const std::array<double, 3>& v, double sign) const {
    std::array<double, 3> out{};
    for (std::size_t k = 0; k < 3; ++k) {
      const double grown = v[k] + sign * m_pad;
      out[k] = m_finite ? grown + sign * 1e-9 * (std::abs(grown) + m_pad) : std::numeric_limits<double>::quiet_NaN();
    }
    return out;
  }

  std::array<double, 3> m_a{}, m_lo{}, m_hi{}, m_inverse{};
  std::array<bool, 3> m_flat{};
  double m_pad = 0;
  bool m_finite = false;
};

// The same for one box.
inline bool segmentTouchesBox(const Vec3& a, const Vec3& b, const Box3& box, Real pad) {
  return SegmentQuery(a, b, pad).touches(box);
}

// The box of a triangle over a step: its vertices at the start and at the end, grown by margin.
// Empty if any of the six points is not finite (such a triangle is never a candidate).
Box3 sweptTriangleBox(const std::vector<Vec3>& start, const std::vector<Vec3>& end, const Triangle& t, Real margin);

class TriangleBvh {
 public:
  static constexpr int kLeafSize = 4;  // triangles per leaf at most

  TriangleBvh() = default;
  // The tree's topology over `triangles` (vertex ids into `positions`), from their centroids at
  // `positions`. The boxes are empty until the first refit().
  TriangleBvh(std::vector<Triangle> triangles, const std::vector<Vec3>& positions);

  // Every box from the vertices' positions at the start and the end of the step
  // (sweptTriangleBox); the topology stays.
  void refit(const std::vector<Vec3>& start, const std::vector<Vec3>& end, Real margin, int threads = 1);

  // Calls f(triangle index) once for every triangle whose swept box the segment a -> b, grown
  // by pad, touches (segmentTouchesBox). The order is the same on every call: the cells' for a
  // short segment (the grid of the same boxes, box_grid.h), the tree's for a long one.
  template <class F>
  void forEachTouching(const Vec3& a, const Vec3& b, Real pad, F&& f) const {
    if (m_nodes.empty()) return;
    const SegmentQuery segment(a, b, pad);
    if (m_grid.forEachCandidate(segment.paddedLo(), segment.paddedHi(), [&](std::size_t t) {
          if (segment.touches(m_boxes[t])) f(t);
        }))
      return;
    std::array<std::size_t, 64> stack{};
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const std::size_t index = stack[--top];
      const Node& node = m_nodes[index];
      if (!segment.touches(node.box)) continue;
      if (node.count > 0) {
        for (std::size_t k = node.first; k < node.first + node.count; ++k)
          if (segment.touches(m_boxes[m_order[k]])) f(m_order[k]);
        continue;
      }
      // Inner node: its left child follows it (preorder); the right one is at node.first.
      stack[top++] = node.first;
      stack[top++] = index + 1;
    }
  }

  [[nodiscard]] const std::vector<Triangle>& triangles() const { return m_triangles; }
  [[nodiscard]] const Box3& triangleBox(std::size_t t) const { return m_boxes[t]; }
  [[nodiscard]] std::size_t nodeCount() const { return m_nodes.size(); }
  [[nodiscard]] std::size_t depth() const { return m_depth; }

 private:
  struct Node {
    Box3 box;
    std::size_t first = 0;  // leaf: first slot in m_order; inner node: index of the right child
    std::size_t count = 0;  // triangles of a leaf; 0 for an inner node
  };
  std::size_t buildNode(std::vector<Vec3>& centroids, std::size_t begin, std::size_t end, std::size_t depth);

  std::vector<Triangle> m_triangles;
  std::vector<std::size_t> m_order;  // triangle indices, each leaf's a contiguous run
  std::vector<Node> m_nodes;         // preorder: a node's children come after it
  std::vector<std::size_t> m_leaves; // node indices of the leaves
  std::vector<Box3> m_boxes;         // per triangle, from the last refit
  BoxGrid m_grid;                    // the same boxes in cells, for short queries
  std::size_t m_depth = 0;
};

}  // namespace hs::pbd
