#include "dam_break_validation.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace hs::app {

double surgeFront(std::span<const pbd::Vec3> positions, double radius, double wallX, double floorY,
                  double floorBand) {
  double front = 0;
  for (const pbd::Vec3& x : positions) {
    if (double(x.y()) - radius - floorY > floorBand) continue;
    front = std::max(front, double(x.x()) + radius - wallX);
  }
  return front;
}

double damBreakTime(double t, double g, double a, double n2) { return std::sqrt(n2) * t * std::sqrt(g / a); }

double interpolateFront(const FrontCurve& curve, double T) {
  assert(!curve.T.empty() && curve.T.size() == curve.Z.size());
  if (T <= curve.T.front()) return curve.Z.front();
  if (T >= curve.T.back()) return curve.Z.back();
  const auto upper = std::upper_bound(curve.T.begin(), curve.T.end(), T);
  const auto i = static_cast<std::size_t>(upper - curve.T.begin());
  const double t0 = curve.T[i - 1], t1 = curve.T[i];
  const double w = t1 > t0 ? (T - t0) / (t1 - t0) : 1.0;
  return curve.Z[i - 1] + w * (curve.Z[i] - curve.Z[i - 1]);
}

std::vector<PointComparison> compareFront(const FrontCurve& curve, std::span<const DamBreakPoint> experiment,
                                          double shift, double tMax) {
  std::vector<PointComparison> out;
  for (const DamBreakPoint& p : experiment) {
    if (p.t > tMax) continue;
    PointComparison c;
    c.zExp = p.z;
    c.tExp = p.t;
    c.tSim = std::max(0.0, p.t - shift);
    c.zSim = interpolateFront(curve, c.tSim);
    c.relativeError = std::abs(c.zSim - p.z) / p.z;
    out.push_back(c);
  }
  return out;
}

double maxRelativeError(std::span<const PointComparison> points) {
  double worst = 0;
  for (const PointComparison& p : points) worst = std::max(worst, p.relativeError);
  return worst;
}

}  // namespace hs::app
