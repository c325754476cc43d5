#include "mesh/planar_delaunay.h"

#include <algorithm>
#include <utility>

namespace hs::pbd {

double inCircle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                const Eigen::Vector2d& d) {
  // det | ax-dx  ay-dy  |a-d|^2 |
  //     | bx-dx  by-dy  |b-d|^2 |
  //     | cx-dx  cy-dy  |c-d|^2 |, positive when d is inside the circumcircle of ccw (a, b, c).
  const Eigen::Vector2d ad = a - d;
  const Eigen::Vector2d bd = b - d;
  const Eigen::Vector2d cd = c - d;
  const double ab = ad.x() * bd.y() - bd.x() * ad.y();
  const double bc = bd.x() * cd.y() - cd.x() * bd.y();
  const double ca = cd.x() * ad.y() - ad.x() * cd.y();
  return ad.squaredNorm() * bc + bd.squaredNorm() * ca + cd.squaredNorm() * ab;
}

std::vector<Triangle> delaunayTriangulation(const std::vector<Eigen::Vector2d>& points) {
  const auto n = static_cast<Index>(points.size());
  if (n < 3) return {};
  // A super-triangle far outside the points (1e3 times their extent) so that circles through
  // two hull points and a super vertex are nearly half-planes and the hull edges survive.
  Eigen::Vector2d lo = points[0];
  Eigen::Vector2d hi = points[0];
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector2d mid = 0.5 * (lo + hi);
  const double extent = std::max((hi - lo).maxCoeff(), 1e-12);
  constexpr double kSuperScale = 1e3;
  std::vector<Eigen::Vector2d> x = points;
  x.emplace_back(mid.x() - kSuperScale * extent, mid.y() - kSuperScale * extent);
  x.emplace_back(mid.x() + kSuperScale * extent, mid.y() - kSuperScale * extent);
  x.emplace_back(mid.x(), mid.y() + kSuperScale * extent);

  std::vector<Triangle> tris = {{n, n + 1, n + 2}};
  std::vector<std::pair<Edge, Edge>> edges;  // (sorted key, directed edge) of the cavity
  std::vector<Triangle> kept;
  for (Index p = 0; p < n; ++p) {
    // The cavity: every triangle whose circumcircle contains p. Its boundary edges (those not
    // shared by two cavity triangles) are joined to p, keeping their counter-clockwise order.
    edges.clear();
    kept.clear();
    for (const Triangle& t : tris) {
      if (inCircle(x[t[0]], x[t[1]], x[t[2]], x[p]) > 0) {
        for (int k = 0; k < 3; ++k) {
          const Index a = t[k];
          const Index b = t[(k + 1) % 3];
          edges.push_back({{std::min(a, b), std::max(a, b)}, {a, b}});
        }
      } else {
        kept.push_back(t);
      }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
      std::size_t j = i + 1;
      while (j < edges.size() && edges[j].first == edges[i].first) ++j;
      if (j - i == 1) kept.push_back({edges[i].second[0], edges[i].second[1], p});
      i = j;
    }
    std::swap(tris, kept);
  }
  std::vector<Triangle> result;
  result.reserve(tris.size());
  for (const Triangle& t : tris) {
    if (t[0] < n && t[1] < n && t[2] < n) result.push_back(t);
  }
  std::sort(result.begin(), result.end());
  return result;
}

}  // namespace hs::pbd
