// Continuous contact against a moving surface, see swept_contact.h.
#include "pbd/contact/swept_contact.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace hs::pbd {
namespace {

using Vec3d = Eigen::Vector3d;

// Below this many particles a fork-join costs more than the loop saves.
constexpr std::ptrdiff_t kParallelThreshold = 256;

// Bisection steps for an entry time: 2^-60 of the piece, below double's resolution of [0, 1].
constexpr int kBisections = 60;

// The BVH's margin, as a fraction of the particle radius: covers the rounding of the
// interpolated positions (the swept box holds the triangle exactly otherwise).
constexpr Real kMarginPerRadius = Real(0.01);

Vec3d toDouble(const Vec3& v) { return v.cast<double>(); }

// f(t) = k0 + k1 t + k2 t^2 + k3 t^3 (Horner).
double cubic(const std::array<double, 4>& k, double t) { return ((k[3] * t + k[2]) * t + k[1]) * t + k[0]; }

// Roots of f'(t) = 3 k3 t^2 + 2 k2 t + k1 strictly inside (0, 1), ascending: f's turning
// points. The quadratic formula in its cancellation-free form (q = -(B + sign(B) sqrt(D)) / 2,
// roots q / A and C / q), which also degrades gracefully when A is tiny (q / A leaves [0, 1]).
int turningPoints(const std::array<double, 4>& k, std::array<double, 2>& roots) {
  const double a = 3 * k[3], b = 2 * k[2], c = k[1];
  int n = 0;
  auto keep = [&](double r) {
    if (r > 0 && r < 1) roots[std::size_t(n++)] = r;
  };
  if (a == 0) {
    if (b != 0) keep(-c / b);
  } else {
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      keep(q / a);
      if (q != 0) keep(c / q);
    }
  }
  if (n == 2 && roots[0] > roots[1]) std::swap(roots[0], roots[1]);
  return n;
}

// The point p on the triangle (x0, x1, x2), projected along the normal: barycentric weights
// (sum 1), or nullopt when the triangle is degenerate or p projects outside it by more than
// the tolerance.
std::optional<std::array<double, 3>> weightsOnTriangle(const Vec3d& p, const Vec3d& x0, const Vec3d& x1,
                                                       const Vec3d& x2) {
  const Vec3d e1 = x1 - x0, e2 = x2 - x0, w = p - x0;
  const Vec3d n = e1.cross(e2);
  const double nn = n.squaredNorm();
  if (!(nn > 0)) return std::nullopt;
  const double b1 = w.cross(e2).dot(n) / nn, b2 = e1.cross(w).dot(n) / nn, b0 = 1 - b1 - b2;
  const double tol = -kBarycentricTolerance;
  if (!(b0 >= tol && b1 >= tol && b2 >= tol)) return std::nullopt;
  std::array<double, 3> b{std::max(b0, 0.0), std::max(b1, 0.0), std::max(b2, 0.0)};
  const double sum = b[0] + b[1] + b[2];
  for (double& x : b) x /= sum;
  return b;
}

}  // namespace

std::optional<SweptHit> firstEntry(const Vec3& a0, const Vec3& a1, const std::array<Vec3, 3>& x0,
                                   const std::array<Vec3, 3>& x1) {
  if (!a0.allFinite() || !a1.allFinite()) return std::nullopt;
  for (std::size_t i = 0; i < 3; ++i)
    if (!x0[i].allFinite() || !x1[i].allFinite()) return std::nullopt;
  // Everything relative to x_0 (cancellation-free differences of the float inputs).
  const Vec3d u0 = toDouble(x0[1]) - toDouble(x0[0]), v0 = toDouble(x0[2]) - toDouble(x0[0]);
  const Vec3d w0 = toDouble(a0) - toDouble(x0[0]);
  const Vec3d du = (toDouble(x1[1]) - toDouble(x1[0])) - u0, dv = (toDouble(x1[2]) - toDouble(x1[0])) - v0;
  const Vec3d dw = (toDouble(a1) - toDouble(x1[0])) - w0;
  // n(t) = (u0 + t du) x (v0 + t dv) = c0 + c1 t + c2 t^2; f(t) = (w0 + t dw) . n(t).
  const Vec3d c0 = u0.cross(v0), c1 = u0.cross(dv) + du.cross(v0), c2 = du.cross(dv);
  std::array<double, 4> k{w0.dot(c0), w0.dot(c1) + dw.dot(c0), w0.dot(c2) + dw.dot(c1), dw.dot(c2)};
  // The entry level delta = kPlaneSlack x the longest edge behind the face, in f's units
  // (f = distance x |n|), with the larger of the start and end normals.
  double edge2 = 0;
  for (const auto* x : {&x0, &x1})
    for (std::size_t i = 0; i < 3; ++i)
      edge2 = std::max(edge2, (toDouble((*x)[(i + 1) % 3]) - toDouble((*x)[i])).squaredNorm());
  const double normal = std::max(c0.norm(), (c0 + c1 + c2).norm());
  if (!(normal > 0)) return std::nullopt;  // degenerate at both ends of the step
  k[0] += kPlaneSlack * std::sqrt(edge2) * normal;

  // [0, 1] in pieces between turning points; f is monotone on each.
  std::array<double, 2> roots{};
  const int turns = turningPoints(k, roots);
  std::array<double, 4> cuts{0, 1, 1, 1};
  for (int r = 0; r < turns; ++r) cuts[std::size_t(r + 1)] = roots[std::size_t(r)];
  cuts[std::size_t(turns + 1)] = 1;
  for (int piece = 0; piece <= turns; ++piece) {
    double lo = cuts[std::size_t(piece)], hi = cuts[std::size_t(piece + 1)];
    if (!(cubic(k, lo) > 0 && cubic(k, hi) <= 0)) continue;  // no entry in this piece
    // Bisection keeps f(lo) > 0 >= f(hi); hi ends at the first time at or past the level.
    for (int step = 0; step < kBisections; ++step) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (cubic(k, mid) > 0 ? lo : hi) = mid;
    }
    const double t = hi;
    auto at = [t](const Vec3& from, const Vec3& to) -> Vec3d { return toDouble(from) + t * (toDouble(to) - toDouble(from)); };
    const std::optional<std::array<double, 3>> b =
        weightsOnTriangle(at(a0, a1), at(x0[0], x1[0]), at(x0[1], x1[1]), at(x0[2], x1[2]));
    if (b) return SweptHit{t, *b};
  }
  return std::nullopt;
}

SweptContact::SweptContact(std::vector<Triangle> surface, const std::vector<Vec3>& positions)
    : m_bvh(std::move(surface), positions) {}

void SweptContact::update(const std::vector<Vec3>& start, const std::vector<Vec3>& end, Real margin, int threads) {
  m_margin = margin;
  m_bvh.refit(start, end, margin, threads);
}

std::optional<SurfaceHit> SweptContact::firstSurfaceEntry(const std::vector<Vec3>& start, const std::vector<Vec3>& end,
                                                          const Vec3& a0, const Vec3& a1) const {
  std::optional<SurfaceHit> best;
  const std::vector<Triangle>& surface = m_bvh.triangles();
  m_bvh.forEachTouching(a0, a1, Real(0), [&](std::size_t t) {
    const Triangle& f = surface[t];
    const std::optional<SweptHit> hit =
        firstEntry(a0, a1, {start[f[0]], start[f[1]], start[f[2]]}, {end[f[0]], end[f[1]], end[f[2]]});
    if (hit && (!best || hit->t < best->hit.t || (hit->t == best->hit.t && t < best->triangle))) best = {t, *hit};
  });
  return best;
}

namespace {

// The response to an entry of the path a0 -> a1 (swept_contact.h): the contact point carried
// to the end of the step plus radius along the end normal, plus the tangential part of the
// remaining relative motion with slip. nullopt if the triangle is degenerate at its end and
// at the contact.
std::optional<Vec3> respond(const std::vector<Vec3>& start, const std::vector<Vec3>& end, const Triangle& f,
                            const SweptHit& hit, const Vec3& a0, const Vec3& a1, Real radius, bool slip) {
  const double t = hit.t;
  Vec3d q1 = Vec3d::Zero(), qt = Vec3d::Zero();
  std::array<Vec3d, 3> xt{}, x1{};
  for (std::size_t i = 0; i < 3; ++i) {
    x1[i] = toDouble(end[f[i]]);
    xt[i] = toDouble(start[f[i]]) + t * (x1[i] - toDouble(start[f[i]]));
    q1 += hit.weights[i] * x1[i];
    qt += hit.weights[i] * xt[i];
  }
  Vec3d n = (x1[1] - x1[0]).cross(x1[2] - x1[0]);
  if (!(n.squaredNorm() > 0)) n = (xt[1] - xt[0]).cross(xt[2] - xt[0]);
  if (!(n.squaredNorm() > 0)) return std::nullopt;
  n.normalize();
  Vec3d result = q1 + double(radius) * n;
  if (slip) {
    const Vec3d pt = toDouble(a0) + t * (toDouble(a1) - toDouble(a0));
    const Vec3d relative = (toDouble(a1) - pt) - (q1 - qt);
    result += relative - relative.dot(n) * n;
  }
  return result.cast<Real>();
}

// The last resort's end: the start carried with the wall point hit, a0 + q1 - q(0).
Vec3 carriedStart(const std::vector<Vec3>& start, const std::vector<Vec3>& end, const Triangle& f, const SweptHit& hit,
                  const Vec3& a0) {
  Vec3d carry = Vec3d::Zero();
  for (std::size_t i = 0; i < 3; ++i) carry += hit.weights[i] * (toDouble(end[f[i]]) - toDouble(start[f[i]]));
  return (toDouble(a0) + carry).cast<Real>();
}

}  // namespace

Vec3 SweptContact::resolvePath(const std::vector<Vec3>& start, const std::vector<Vec3>& end, const Vec3& a0,
                               const Vec3& a1, const SweptContactSettings& settings, bool* unresolved) const {
  const std::vector<Triangle>& surface = m_bvh.triangles();
  Vec3 target = a1;
  std::optional<SurfaceHit> first;
  for (int pass = 0; pass < settings.maxPasses; ++pass) {
    const std::optional<SurfaceHit> hit = firstSurfaceEntry(start, end, a0, target);
    if (!hit) return target;
    if (!first) first = hit;
    const std::optional<Vec3> next =
        respond(start, end, surface[hit->triangle], hit->hit, a0, target, settings.radius, settings.slip);
    if (!next) break;
    target = *next;
  }
  if (!first || !firstSurfaceEntry(start, end, a0, target)) return target;
  // Last resorts: stop at the first contact (no slip), else keep the place relative to the wall.
  const Triangle& f = surface[first->triangle];
  if (const std::optional<Vec3> stop = respond(start, end, f, first->hit, a0, a1, settings.radius, false))
    if (!firstSurfaceEntry(start, end, a0, *stop)) return *stop;
  target = carriedStart(start, end, f, first->hit, a0);
  if (unresolved && firstSurfaceEntry(start, end, a0, target)) *unresolved = true;
  return target;
}

std::size_t SweptContact::resolve(Particles& particles, Index first, Index end, const SweptContactSettings& settings) {
  const std::vector<Vec3>& x = particles.position;
  std::vector<Vec3>& p = particles.predicted;
  update(x, p, kMarginPerRadius * settings.radius, settings.threads);
  const std::ptrdiff_t count = std::ptrdiff_t(end) - std::ptrdiff_t(first);
  std::size_t moved = 0, unresolved = 0;
  // Each iteration reads the surface's vertices (never in [first, end)) and writes only p[i].
#pragma omp parallel for schedule(dynamic, 64) num_threads(settings.threads) reduction(+ : moved, unresolved) \
    if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = first + Index(s);
    if (!particles.dynamic(i)) continue;
    bool stuck = false;
    const Vec3 result = resolvePath(x, p, x[i], p[i], settings, &stuck);
    unresolved += stuck ? 1 : 0;
    if (result.x() == p[i].x() && result.y() == p[i].y() && result.z() == p[i].z()) continue;
    p[i] = result;
    ++moved;
  }
  m_lastUnresolved = unresolved;
  return moved;
}

}  // namespace hs::pbd
