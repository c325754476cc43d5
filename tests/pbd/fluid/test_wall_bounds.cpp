// The lower bounds that prune the nearest-wall search (wall_bounds.h): the dispatched pass gives
// bitwise the scalar expression's bounds, never more than the true distance, and its minimum and
// candidate bits; and on a curved cavity, where the planes prune most, the search still finds
// bitwise what brute force finds.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "pbd/core/closest_point.h"
#include "pbd/fluid/wall_bounds.h"
#include "pbd/fluid/wall_density.h"

namespace hs::pbd {
namespace {

constexpr Real kReach = Real(0.008);  // the 4 mm blood's kernel support

// A closed latitude-longitude sphere of `radius` (m) about `centre`: `rings` bands of `sectors`
// quads, two triangles each, fans at the poles; faces wound outward.
struct Sphere {
  std::vector<Vec3> x;
  std::vector<Triangle> faces;
};

Sphere sphere(const Vec3& centre, Real radius, int rings, int sectors) {
  Sphere s;
  const double pi = std::numbers::pi;
  s.x.push_back(centre + Vec3(0, 0, radius));
  for (int r = 1; r < rings; ++r)
    for (int k = 0; k < sectors; ++k) {
      const double theta = pi * r / rings, phi = 2 * pi * k / sectors;
      s.x.push_back(centre + radius * Vec3(Real(std::sin(theta) * std::cos(phi)), Real(std::sin(theta) * std::sin(phi)),
                                           Real(std::cos(theta))));
    }
  s.x.push_back(centre - Vec3(0, 0, radius));
  const auto at = [&](int r, int k) { return Index(1 + (r - 1) * sectors + (k % sectors)); };
  const Index south = Index(s.x.size() - 1);
  for (int k = 0; k < sectors; ++k) {
    s.faces.push_back({0, at(1, k), at(1, k + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
      s.faces.push_back({at(r, k), at(r + 1, k), at(r + 1, k + 1)});
      s.faces.push_back({at(r, k), at(r + 1, k + 1), at(r, k + 1)});
    }
    s.faces.push_back({at(rings - 1, k), south, at(rings - 1, k + 1)});
  }
  return s;
}

// Entries of random boxes and planes, as a grid cell lists them, plus the padding.
struct Entries {
  std::vector<Real> lo[3], hi[3], plane[4];
  std::vector<Triangle> triangles;
  std::vector<Vec3> x;
};

Entries randomEntries(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(Real(0.09), Real(0.11));
  Entries e;
  for (std::size_t t = 0; t < n; ++t) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    e.x.insert(e.x.end(), {a, b, c});
    e.triangles.push_back({Index(3 * t), Index(3 * t + 1), Index(3 * t + 2)});
    const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    const Vec3 normal = (b - a).cross(c - a).normalized();
    for (int k = 0; k < 3; ++k) {
      e.lo[k].push_back(lo[k]);
      e.hi[k].push_back(hi[k]);
      e.plane[k].push_back(normal[k]);
    }
    e.plane[3].push_back(normal.dot(a));
  }
  for (auto* array : {&e.lo[0], &e.lo[1], &e.lo[2], &e.hi[0], &e.hi[1], &e.hi[2], &e.plane[0], &e.plane[1],
                      &e.plane[2], &e.plane[3]})
    array->resize(n + kWallBoundsPadding, Real(0));
  return e;
}

WallBoundsJob jobOf(const Entries& e, std::size_t n, const Vec3& p) {
  WallBoundsJob job{};
  for (int k = 0; k < 3; ++k) {
    job.lo[k] = e.lo[k].data();
    job.hi[k] = e.hi[k].data();
  }
  for (int k = 0; k < 4; ++k) job.plane[k] = e.plane[k].data();
  job.slack = Real(1e-6);
  job.px = p.x(), job.py = p.y(), job.pz = p.z();
  job.n = n;
  return job;
}

TEST(WallBounds, TheVectorPassIsTheScalarExpressionAndABoundOfTheDistance) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> u(Real(0.085), Real(0.115));
  // Counts around every vector width and the padding's end.
  for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(16), std::size_t(17),
                        std::size_t(63), std::size_t(64), std::size_t(65), std::size_t(130)}) {
    const Entries e = randomEntries(n, rng);
    for (int trial = 0; trial < 20; ++trial) {
      const Vec3 p(u(rng), u(rng), u(rng));
      const WallBoundsJob job = jobOf(e, n, p);
      std::vector<Real> bounds(n + kWallBoundsPadding, Real(-1));
      const WallBoundsMinimum smallest = wallCandidateBounds(job, bounds.data());
      std::size_t first = n;
      for (std::size_t k = 0; k < n; ++k) {
        ASSERT_EQ(bounds[k], wallCandidateBound(job, k)) << "n " << n << ", entry " << k;
        const Triangle& t = e.triangles[k];
        const Real d2 = (p - closestPointOnTriangle(p, e.x[t[0]], e.x[t[1]], e.x[t[2]])).squaredNorm();
        EXPECT_LE(bounds[k], d2) << "a bound beyond the true distance: n " << n << ", entry " << k;
        if (first == n || bounds[k] < bounds[first]) first = k;
      }
      for (std::size_t k = n; k < n + kWallBoundsPadding; ++k) EXPECT_TRUE(std::isinf(bounds[k])) << k;
      ASSERT_EQ(smallest.first, first) << "n " << n;
      if (n > 0) {
        EXPECT_EQ(smallest.bound, bounds[first]);
      }
      // The bits: exactly the entries not beyond a threshold (here the median-ish bound).
      const Real threshold = n > 0 ? bounds[n / 2] : Real(0);
      std::vector<std::uint64_t> words(wallCandidateWords(n), ~std::uint64_t(0));
      wallCandidatesWithin(bounds.data(), n, threshold, words.data());
      for (std::size_t k = 0; k < 64 * words.size(); ++k) {
        const bool set = (words[k / 64] >> (k % 64)) & 1;
        EXPECT_EQ(set, k < n && bounds[k] <= threshold) << "n " << n << ", bit " << k;
      }
    }
  }
}

// Inside a curved cavity the neighbours' planes pass beyond the nearest triangle, so most
// candidates are pruned by their plane: the search must still agree with brute force bitwise, for
// points inside, outside and on the far side of the reach, on 1 and 2 threads.
TEST(WallBounds, TheSearchInACurvedCavityAgreesWithBruteForceBitwise) {
  const Sphere cavity = sphere(Vec3(Real(0.1), Real(0.05), Real(-0.02)), Real(0.03), 24, 40);
  std::mt19937 rng(13);
  std::normal_distribution<Real> g(0, 1);
  std::uniform_real_distribution<Real> depth(Real(-0.012), Real(0.004));
  std::vector<Vec3> points;
  for (int k = 0; k < 4000; ++k) {
    const Vec3 direction = Vec3(g(rng), g(rng), g(rng)).normalized();
    points.push_back(Vec3(Real(0.1), Real(0.05), Real(-0.02)) + (Real(0.03) + depth(rng)) * direction);
  }
  for (int threads : {1, 2}) {
    std::vector<WallProximity> found;
    findNearestWalls(cavity.x, cavity.faces, points, kReach, found, threads);
    int near = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const WallProximity brute = nearestWallBruteForce(cavity.x, cavity.faces, points[i], kReach);
      ASSERT_EQ(found[i].distance, brute.distance) << "point " << i;
      ASSERT_EQ(found[i].normal, brute.normal) << "point " << i;
      near += brute.normal.squaredNorm() > 0;
    }
    EXPECT_GT(near, 2500) << "most points must be within reach of the wall";
  }
}

}  // namespace
}  // namespace hs::pbd
