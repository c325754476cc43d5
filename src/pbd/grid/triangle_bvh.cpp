// Bounding volume hierarchy over a moving triangle mesh, see triangle_bvh.h.
#include "pbd/grid/triangle_bvh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace hs::pbd {
namespace {

// Below this many triangles a fork-join costs more than the refit saves.
constexpr std::ptrdiff_t kParallelThreshold = 2048;

}  // namespace

SegmentQuery::SegmentQuery(const Vec3& a, const Vec3& b, Real pad) : m_pad(double(pad)) {
  m_finite = a.allFinite() && b.allFinite();
  for (std::size_t k = 0; k < 3; ++k) {
    m_a[k] = double(a[int(k)]);
    const double end = double(b[int(k)]), d = end - m_a[k];
    m_lo[k] = std::min(m_a[k], end);
    m_hi[k] = std::max(m_a[k], end);
    m_flat[k] = d == 0;
    m_inverse[k] = m_flat[k] ? 0 : 1 / d;
  }
}

Box3 sweptTriangleBox(const std::vector<Vec3>& start, const std::vector<Vec3>& end, const Triangle& t, Real margin) {
  Box3 box;
  for (Index v : t) {
    if (!start[v].allFinite() || !end[v].allFinite()) return Box3{};
    box.grow(start[v]);
    box.grow(end[v]);
  }
  box.lo -= Vec3::Constant(margin);
  box.hi += Vec3::Constant(margin);
  return box;
}

TriangleBvh::TriangleBvh(std::vector<Triangle> triangles, const std::vector<Vec3>& positions)
    : m_triangles(std::move(triangles)), m_boxes(m_triangles.size()) {
  m_order.resize(m_triangles.size());
  std::vector<Vec3> centroids(m_triangles.size());
  for (std::size_t t = 0; t < m_triangles.size(); ++t) {
    m_order[t] = t;
    const Triangle& f = m_triangles[t];
    centroids[t] = (positions[f[0]] + positions[f[1]] + positions[f[2]]) / Real(3);
    if (!centroids[t].allFinite()) centroids[t] = Vec3::Zero();
  }
  m_nodes.reserve(2 * (m_triangles.size() / std::size_t(kLeafSize) + 1));
  if (!m_triangles.empty()) buildNode(centroids, 0, m_triangles.size(), 1);
  for (std::size_t n = 0; n < m_nodes.size(); ++n)
    if (m_nodes[n].count > 0) m_leaves.push_back(n);
}

// Median split of [begin, end) of m_order along the longest axis of its centroids' box; ties
// by triangle index, so the tree does not depend on the sort's internals.
std::size_t TriangleBvh::buildNode(std::vector<Vec3>& centroids, std::size_t begin, std::size_t end,
                                   std::size_t depth) {
  const std::size_t index = m_nodes.size();
  m_nodes.emplace_back();
  m_depth = std::max(m_depth, depth);
  if (end - begin <= std::size_t(kLeafSize)) {
    m_nodes[index].first = begin;
    m_nodes[index].count = end - begin;
    return index;
  }
  Box3 bounds;
  for (std::size_t k = begin; k < end; ++k) bounds.grow(centroids[m_order[k]]);
  int axis = 0;
  const Vec3 extent = bounds.hi - bounds.lo;
  if (extent[1] > extent[axis]) axis = 1;
  if (extent[2] > extent[axis]) axis = 2;
  const std::size_t middle = begin + (end - begin) / 2;
  const auto first = m_order.begin() + std::ptrdiff_t(begin);
  std::nth_element(first, m_order.begin() + std::ptrdiff_t(middle), m_order.begin() + std::ptrdiff_t(end),
                   [&](std::size_t x, std::size_t y) {
                     const Real cx = centroids[x][axis], cy = centroids[y][axis];
                     return cx != cy ? cx < cy : x < y;
                   });
  buildNode(centroids, begin, middle, depth + 1);  // the left child is index + 1
  const std::size_t right = buildNode(centroids, middle, end, depth + 1);
  m_nodes[index].first = right;
  // Median splits halve the count: depth ~ log2(n / kLeafSize) + 1, far below the query stack.
  assert(m_depth < 60);
  return index;
}

void TriangleBvh::refit(const std::vector<Vec3>& start, const std::vector<Vec3>& end, Real margin, int threads) {
  const auto triangles = std::ptrdiff_t(m_triangles.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (triangles >= kParallelThreshold)
  for (std::ptrdiff_t t = 0; t < triangles; ++t)
    m_boxes[std::size_t(t)] = sweptTriangleBox(start, end, m_triangles[std::size_t(t)], margin);
  const auto leaves = std::ptrdiff_t(m_leaves.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (triangles >= kParallelThreshold)
  for (std::ptrdiff_t l = 0; l < leaves; ++l) {
    Node& leaf = m_nodes[m_leaves[std::size_t(l)]];
    leaf.box = Box3{};
    for (std::size_t k = leaf.first; k < leaf.first + leaf.count; ++k) leaf.box.grow(m_boxes[m_order[k]]);
  }
  // Inner nodes, children first: in preorder both children come after their parent.
  for (std::size_t n = m_nodes.size(); n-- > 0;) {
    Node& node = m_nodes[n];
    if (node.count > 0) continue;
    node.box = m_nodes[n + 1].box;
    node.box.grow(m_nodes[node.first].box);
  }
  m_grid.build(m_boxes, threads);
}

}  // namespace hs::pbd
