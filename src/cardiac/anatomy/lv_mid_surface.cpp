#include "cardiac/anatomy/lv_mid_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace hs::cardiac::detail {

namespace {

constexpr double kPi = std::numbers::pi;
// Row height of equilateral triangles with edge h: h sqrt(3) / 2.
constexpr double kRowHeight = 0.8660254037844386;
// Fewest vertices on a ring: a hexagon, so the apex fan has 60-degree corners.
constexpr long kMinRingVertices = 6;

// Vertices on a ring of circumference 2 pi r at edge length h (and at most maxChord apart on
// the inner radius rInner, for rings shared with the base plate).
long ringCount(double rMid, double h, double rInner = 0, double maxChord = 0) {
  long n = std::max(kMinRingVertices, std::lround(2 * kPi * rMid / h));
  if (maxChord > 0) n = std::max(n, static_cast<long>(std::ceil(2 * kPi * rInner / maxChord)));
  return n;
}

// Azimuths of ring `row`: alternate rows are rotated by half a step so the band between
// two rings of equal count is made of near-equilateral triangles.
std::vector<double> ringAngles(long n, int row) {
  std::vector<double> phi(static_cast<std::size_t>(n));
  const double offset = (row % 2) * 0.5;
  for (long k = 0; k < n; ++k) phi[static_cast<std::size_t>(k)] = 2 * kPi * (double(k) + offset) / double(n);
  return phi;
}

}  // namespace

Index MidSurface::addVertex(const Vec3d& in, const Vec3d& out, Region r, int vertexRank) {
  inner.push_back(in);
  outer.push_back(out);
  region.push_back(r);
  rank.push_back(vertexRank);
  return static_cast<Index>(inner.size() - 1);
}

void MidSurface::addTriangle(Index a, Index b, Index c, bool bindsCavity) {
  triangles.push_back({a, b, c});
  cavity.push_back(bindsCavity ? 1 : 0);
}

void zipRings(MidSurface& s, const Ring& lower, const Ring& upper, bool bindsCavity) {
  // Walk both rings once around, always advancing the ring whose next vertex has the smaller
  // (unwrapped) azimuth; every step emits one triangle, n_lower + n_upper in total.
  const std::size_t nl = lower.ids.size();
  const std::size_t nu = upper.ids.size();
  auto unwrapped = [](const Ring& r, std::size_t k) {
    const std::size_t n = r.ids.size();
    return r.angles[k % n] + 2 * kPi * double(k / n);
  };
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < nl || j < nu) {
    const bool advanceLower = j == nu || (i < nl && unwrapped(lower, i + 1) < unwrapped(upper, j + 1));
    if (advanceLower) {
      s.addTriangle(lower.ids[i % nl], lower.ids[(i + 1) % nl], upper.ids[j % nu], bindsCavity);
      ++i;
    } else {
      s.addTriangle(lower.ids[i % nl], upper.ids[(j + 1) % nu], upper.ids[j % nu], bindsCavity);
      ++j;
    }
  }
}

Ring addCup(MidSurface& s, const ShellDims& d) {
  // Endocardium (a sin th cos phi, -c cos th, a sin th sin phi), th in [0, pi/2]; the
  // epicardium uses semi-axes (a+t, c+t) and th_o = th * thMax / (pi/2), where
  // cos thMax = -baseThickness / (c+t) puts its rim on the top of the base plate.
  const double ao = d.a + d.t;
  const double co = d.c + d.t;
  const double thetaOuterMax = std::acos(-d.baseThickness / co);
  auto innerAt = [&](double th, double phi) {
    return Vec3d(d.a * std::sin(th) * std::cos(phi), -d.c * std::cos(th), d.a * std::sin(th) * std::sin(phi));
  };
  auto outerAt = [&](double th, double phi) {
    const double to = th * thetaOuterMax / (kPi / 2);
    return Vec3d(ao * std::sin(to) * std::cos(phi), -co * std::cos(to), ao * std::sin(to) * std::sin(phi));
  };
  // Arc length of the mid-surface meridian (average of the two layers), tabulated in th.
  constexpr int kSamples = 4096;
  std::vector<double> arc(kSamples + 1, 0.0);
  auto midAt = [&](double th) -> Vec3d { return 0.5 * (innerAt(th, 0) + outerAt(th, 0)); };
  for (int k = 1; k <= kSamples; ++k) {
    const double th0 = (kPi / 2) * double(k - 1) / kSamples;
    const double th1 = (kPi / 2) * double(k) / kSamples;
    arc[k] = arc[k - 1] + (midAt(th1) - midAt(th0)).norm();
  }
  const long rows = std::max(2L, std::lround(arc.back() / (kRowHeight * d.h)));

  const Index pole = s.addVertex(innerAt(0, 0), outerAt(0, 0), Region::Myocardium, kRankCup);
  Ring previous;
  for (long row = 1; row <= rows; ++row) {
    // th where the arc length reaches row/rows of the meridian (linear inverse of the table).
    const double target = arc.back() * double(row) / double(rows);
    const auto it = std::lower_bound(arc.begin(), arc.end(), target);
    const auto k = static_cast<int>(std::clamp<long>(it - arc.begin(), 1, kSamples));
    const double f = (target - arc[k - 1]) / std::max(arc[k] - arc[k - 1], 1e-300);
    const double th =
        row == rows ? kPi / 2 : (kPi / 2) * (double(k - 1) + std::clamp(f, 0.0, 1.0)) / kSamples;
    const double rMid = midAt(th).x();
    const long n = row == rows ? ringCount(rMid, d.h, d.a, d.plateH) : ringCount(rMid, d.h);
    Ring ring;
    ring.angles = ringAngles(n, static_cast<int>(row));
    for (double phi : ring.angles)
      ring.ids.push_back(s.addVertex(innerAt(th, phi), outerAt(th, phi), Region::Myocardium, kRankCup));
    if (row == 1) {
      for (std::size_t q = 0; q < ring.ids.size(); ++q) {
        s.addTriangle(pole, ring.ids[q], ring.ids[(q + 1) % ring.ids.size()], true);
      }
    } else {
      zipRings(s, previous, ring, true);
    }
    previous = std::move(ring);
  }
  return previous;
}

Ring addVessel(MidSurface& s, const ShellDims& d, const ShellDims::Orifice& o, Ring& top) {
  // Lumen radius R, outer radius R + w. The bottom ring is the orifice edge: inner layer in the
  // base plane y = 0, outer layer on the top of the plate (y = baseThickness). The other rings
  // have both layers at the same height y = baseThickness + length * row / rows, so only the
  // first row is sheared (a wall sheared along its length makes flat tets). A shaped vessel's
  // rings stay horizontal; their centres and radii follow its shape at u = y / (baseThickness +
  // length), the share of its height (vessel_shape.h).
  const double rIn = o.radius;
  const double rOut = o.radius + d.vesselWall;
  const long n = ringCount(0.5 * (rIn + rOut), d.h, rIn, d.plateH);
  // Rows near-equilateral with the ring's actual chord (finer than h when the orifice ring
  // was refined for the base plate).
  const double chord = std::min(d.h, 2 * kPi * 0.5 * (rIn + rOut) / double(n));
  const long rows = std::max(1L, std::lround((0.5 * d.baseThickness + o.length) / (kRowHeight * chord)));
  const double height = d.baseThickness + o.length;
  Ring bottom;
  Ring previous;
  for (long row = 0; row <= rows; ++row) {
    const double yOut = d.baseThickness + o.length * double(row) / double(rows);
    const double yIn = row == 0 ? 0.0 : yOut;
    const double u = row == 0 ? 0.0 : yOut / height;
    const double shift = o.shape.shift(u);
    const Vec2d centre = o.centre + shift * Vec2d(o.shape.awayX, o.shape.awayZ);
    Ring ring;
    ring.angles = ringAngles(n, static_cast<int>(row));
    for (double phi : ring.angles) {
      const double cx = std::cos(phi);
      const double sz = std::sin(phi);
      const double r = row == 0 ? rIn : o.shape.radius(u, phi, rIn);
      const Vec3d in(centre.x() + r * cx, yIn, centre.y() + r * sz);
      const Vec3d out(centre.x() + (r + d.vesselWall) * cx, yOut, centre.y() + (r + d.vesselWall) * sz);
      const int rank = kRankVesselTop + static_cast<int>(rows - row);
      ring.ids.push_back(s.addVertex(in, out, row == 0 ? Region::BasePlate : o.region, rank));
    }
    if (row == 0) {
      bottom = ring;
    } else {
      zipRings(s, previous, ring, false);
    }
    previous = std::move(ring);
  }
  top = std::move(previous);
  return bottom;
}

void orientTriangles(MidSurface& s) {
  for (pbd::Triangle& t : s.triangles) {
    const auto& in = s.inner;
    const auto& out = s.outer;
    const Vec3d normal = (in[t[1]] - in[t[0]]).cross(in[t[2]] - in[t[0]]) +
                         (out[t[1]] - out[t[0]]).cross(out[t[2]] - out[t[0]]);
    const Vec3d across = (out[t[0]] + out[t[1]] + out[t[2]]) - (in[t[0]] + in[t[1]] + in[t[2]]);
    if (normal.dot(across) < 0) std::swap(t[1], t[2]);
  }
}

}  // namespace hs::cardiac::detail
