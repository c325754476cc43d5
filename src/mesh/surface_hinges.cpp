#include "mesh/surface_hinges.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace hs::pbd {

using Vec3d = Eigen::Vector3d;

std::vector<Hinge> surfaceHinges(const std::vector<Triangle>& triangles) {
  // Directed edge (a, b) -> the vertex opposite it in its triangle; a consistently wound
  // neighbour holds the same edge as (b, a).
  std::map<std::pair<Index, Index>, std::vector<Index>> opposite;
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) opposite[{t[k], t[(k + 1) % 3]}].push_back(t[(k + 2) % 3]);
  std::vector<Hinge> hinges;
  for (const auto& [edge, across] : opposite) {
    if (edge.first > edge.second || across.size() != 1) continue;  // each edge once, manifold only
    const auto other = opposite.find({edge.second, edge.first});
    if (other == opposite.end() || other->second.size() != 1) continue;
    hinges.push_back({edge.first, edge.second, across.front(), other->second.front()});
  }
  return hinges;
}

double hingeAngle(const Hinge& h, std::span<const Vec3> x) {
  const Vec3d a = x[h.a].cast<double>(), b = x[h.b].cast<double>();
  const Vec3d n1 = (b - a).cross(x[h.c].cast<double>() - a);
  const Vec3d n2 = (a - b).cross(x[h.d].cast<double>() - b);
  const double l1 = n1.norm(), l2 = n2.norm(), edge = (b - a).norm();
  if (!(l1 > 0 && l2 > 0 && edge > 0)) return 0;
  const Vec3d u1 = n1 / l1, u2 = n2 / l2;
  return std::atan2(u1.cross(u2).dot((b - a) / edge), u1.dot(u2));
}

double largestHingeTurn(const std::vector<Hinge>& hinges, const std::vector<double>& restAngles,
                        std::span<const Vec3> x) {
  double largest = 0;
  for (std::size_t i = 0; i < hinges.size(); ++i) {
    double turn = std::abs(hingeAngle(hinges[i], x) - restAngles[i]);
    if (turn > std::numbers::pi) turn = 2 * std::numbers::pi - turn;
    largest = std::max(largest, turn);
  }
  return largest;
}

}  // namespace hs::pbd
