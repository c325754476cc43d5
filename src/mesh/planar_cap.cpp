#include "mesh/planar_cap.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "mesh/planar_delaunay.h"

namespace hs::pbd {

namespace {

using Vec2d = Eigen::Vector2d;

constexpr double kKeepAway = 0.6;
constexpr double kRowHeight = 0.8660254037844386;  // sqrt(3) / 2

double distanceToSegment(const Vec2d& p, const Vec2d& a, const Vec2d& b) {
  const Vec2d ab = b - a;
  const double s = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + s * ab - p).norm();
}

double distanceToPolygon(const std::vector<Vec2d>& polygon, const Vec2d& p) {
  double d = HUGE_VAL;
  for (std::size_t k = 0; k < polygon.size(); ++k)
    d = std::min(d, distanceToSegment(p, polygon[k], polygon[(k + 1) % polygon.size()]));
  return d;
}

}  // namespace

bool insidePolygon(const std::vector<Vec2d>& polygon, const Vec2d& p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2d& a = polygon[i];
    const Vec2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

PlanarCap capWithHoles(const std::vector<Vec2d>& rim, const std::vector<Index>& rimIds, Index firstNewId,
                       const std::vector<CircularHole>& holes, double spacing) {
  if (rim.size() < 3 || rim.size() != rimIds.size() || !(spacing > 0))
    throw std::invalid_argument("capWithHoles: needs a rim of 3 or more points with ids and spacing > 0");
  for (std::size_t h = 0; h < holes.size(); ++h) {
    if (!insidePolygon(rim, holes[h].centre) ||
        distanceToPolygon(rim, holes[h].centre) < holes[h].radius + 0.25 * spacing)
      throw std::invalid_argument("capWithHoles: hole " + std::to_string(h + 1) +
                                  " does not fit inside the rim");
    for (std::size_t g = 0; g < h; ++g)
      if ((holes[h].centre - holes[g].centre).norm() < holes[h].radius + holes[g].radius + 0.25 * spacing)
        throw std::invalid_argument("capWithHoles: holes " + std::to_string(g + 1) + " and " +
                                    std::to_string(h + 1) + " overlap");
  }
  const double keep = kKeepAway * spacing;
  // Points: guides (hole centres), lattice, rings, rim.
  std::vector<Vec2d> pts;
  for (const CircularHole& hole : holes) pts.push_back(hole.centre);
  const std::size_t guides = pts.size();
  Vec2d lo = rim[0], hi = rim[0];
  for (const Vec2d& p : rim) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double rowH = kRowHeight * spacing;
  for (int row = 0; lo.y() + row * rowH <= hi.y(); ++row) {
    const double y = lo.y() + row * rowH;
    for (double x = lo.x() + (row % 2 ? 0.5 * spacing : 0.0); x <= hi.x(); x += spacing) {
      const Vec2d p(x, y);
      if (!insidePolygon(rim, p) || distanceToPolygon(rim, p) < keep) continue;
      bool clear = true;
      for (const CircularHole& hole : holes) clear = clear && (p - hole.centre).norm() >= hole.radius + keep;
      if (clear) pts.push_back(p);
    }
  }
  PlanarCap cap;
  for (const CircularHole& hole : holes) {
    const int n = std::max(8, static_cast<int>(std::ceil(2 * std::numbers::pi * hole.radius / spacing)));
    std::vector<Index> ring;
    for (int k = 0; k < n; ++k) {
      const double phi = 2 * std::numbers::pi * k / n;
      ring.push_back(static_cast<Index>(pts.size()));
      pts.push_back(hole.centre + hole.radius * Vec2d(std::cos(phi), std::sin(phi)));
    }
    cap.holeRings.push_back(std::move(ring));
  }
  const std::size_t firstRim = pts.size();
  pts.insert(pts.end(), rim.begin(), rim.end());
  // Local index -> mesh id: guides none, lattice and rings new ids, rim its ids.
  std::vector<Index> id(pts.size());
  for (std::size_t k = guides; k < firstRim; ++k) {
    id[k] = firstNewId + static_cast<Index>(k - guides);
    cap.newPoints.push_back(pts[k]);
  }
  for (std::size_t k = 0; k < rim.size(); ++k) id[firstRim + k] = rimIds[k];
  for (const Triangle& t : delaunayTriangulation(pts)) {
    if (t[0] < guides || t[1] < guides || t[2] < guides) continue;
    const Vec2d centroid = (pts[t[0]] + pts[t[1]] + pts[t[2]]) / 3.0;
    bool keepIt = insidePolygon(rim, centroid);
    for (const CircularHole& hole : holes) keepIt = keepIt && (centroid - hole.centre).norm() > hole.radius;
    if (keepIt) cap.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});
  }
  for (auto& ring : cap.holeRings)
    for (Index& k : ring) k = id[k];
  return cap;
}

}  // namespace hs::pbd
