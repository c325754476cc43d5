// StaticMeshCollider: grid candidates against brute force, collide() against collideBruteForce(),
// resting on a floor, no tunnelling out of a closed box, concave corners and wedges, going
// around a free edge, degenerate triangles, thread independence, and clear errors.
#include <gtest/gtest.h>

#include "thrown_message.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "pbd/contact/mesh_collider.h"

namespace hs::pbd {
namespace {

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
};

// Appends quad p0 p1 p2 p3 (in order around it) as two triangles.
void addQuad(Mesh& m, const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const Index base = Index(m.vertices.size());
  m.vertices.insert(m.vertices.end(), {p0, p1, p2, p3});
  m.triangles.push_back({base, Index(base + 1), Index(base + 2)});
  m.triangles.push_back({base, Index(base + 2), Index(base + 3)});
}

// The unit cube [0, 1]^3 as 8 shared corners and 12 triangles, normals outward (or inward).
Mesh unitBox(bool outward) {
  Mesh m;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) m.vertices.emplace_back(Real(i), Real(j), Real(k));
  const Index quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                             {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  const Vec3 centre = Vec3::Constant(Real(0.5));
  for (const auto& q : quads)
    for (const Triangle t : {Triangle{q[0], q[1], q[2]}, Triangle{q[0], q[2], q[3]}}) {
      const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
      const bool out = (b - a).cross(c - a).dot(a - centre) > 0;
      m.triangles.push_back(out == outward ? t : Triangle{t[0], t[2], t[1]});
    }
  return m;
}

Real uniform(std::mt19937& rng, double lo, double hi) {
  return Real(std::uniform_real_distribution<double>(lo, hi)(rng));
}

Vec3 randomPoint(std::mt19937& rng, double lo, double hi) {
  return Vec3(uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi));
}

Vec3 randomDirection(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  Vec3 d(Real(n(rng)), Real(n(rng)), Real(n(rng)));
  return d.normalized();
}

// Triangles of mixed sizes in [0, 1]^3, a few large tilted ones, and a few degenerate ones.
Mesh randomSoup(std::size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  Mesh m;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 centre = randomPoint(rng, 0, 1);
    const double size = i % 20 == 0 ? 0.8 : 0.02 + 0.25 * double(uniform(rng, 0, 1));
    const Index base = Index(m.vertices.size());
    for (int k = 0; k < 3; ++k) m.vertices.push_back(centre + randomPoint(rng, -size, size));
    if (i % 37 == 5) m.vertices[base + 2] = m.vertices[base];  // zero area
    if (i % 41 == 7)
      m.vertices[base + 2] = Real(0.5) * (m.vertices[base] + m.vertices[base + 1]);  // collinear
    m.triangles.push_back({base, Index(base + 1), Index(base + 2)});
  }
  return m;
}

std::vector<Index> bruteForceCandidates(const StaticMeshCollider& c, const Vec3& lo, const Vec3& hi) {
  std::vector<Index> out;
  for (Index t = 0; t < Index(c.triangles().size()); ++t)
    if (c.triangleMayTouchBox(t, lo, hi)) out.push_back(t);
  return out;
}

// Distance from x to the walls of the unit cube (negative outside).
Real insideDistance(const Vec3& x) {
  return std::min({x[0], x[1], x[2], Real(1) - x[0], Real(1) - x[1], Real(1) - x[2]});
}

TEST(MeshCollider, GridCandidatesMatchBruteForce) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Mesh soup = randomSoup(300, seed);
    // 0.001 needs far more cells than the budget: the grid coarsens and must stay correct.
    for (Real cell : {Real(0.05), Real(0.13), Real(0.001)}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", cell " + std::to_string(cell));
      const StaticMeshCollider collider(soup.vertices, soup.triangles, cell);
      EXPECT_LT(collider.activeTriangleCount(), soup.triangles.size());  // degenerate ones skipped
      if (cell < Real(0.01)) {
        EXPECT_GT(collider.cellSize(), cell);
      }
      // Points on the triangles: a triangle with a point inside a box must be a candidate.
      std::mt19937 rng(seed + 100);
      std::vector<std::pair<Index, Vec3>> samples;
      for (Index t = 0; t < Index(soup.triangles.size()); ++t)
        for (int s = 0; s < 20; ++s) {
          Real u = uniform(rng, 0, 1), v = uniform(rng, 0, 1);
          if (u + v > 1) u = 1 - u, v = 1 - v;
          const auto& tri = soup.triangles[t];
          const Vec3& a = soup.vertices[tri[0]];
          samples.emplace_back(t,
                               Vec3(a + u * (soup.vertices[tri[1]] - a) + v * (soup.vertices[tri[2]] - a)));
        }
      std::vector<bool> kept;  // not skipped as degenerate
      for (Index t = 0; t < Index(soup.triangles.size()); ++t)
        kept.push_back(collider.triangleMayTouchBox(t, Vec3::Constant(-10), Vec3::Constant(10)));
      std::size_t nonEmpty = 0, witnessed = 0;
      std::vector<Index> grid;
      for (int q = 0; q < 400; ++q) {
        const Vec3 centre = randomPoint(rng, -0.2, 1.2);
        const Vec3 half = q % 10 == 0 ? Vec3::Zero() : randomPoint(rng, 0, 0.15);
        const Vec3 lo = centre - half, hi = centre + half;
        collider.candidateTriangles(lo, hi, grid);
        const std::vector<Index> brute = bruteForceCandidates(collider, lo, hi);
        ASSERT_EQ(grid, brute) << "box " << q;
        nonEmpty += !grid.empty();
        for (const auto& [t, p] : samples)
          if (kept[t] && (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all()) {
            ++witnessed;
            ASSERT_TRUE(std::binary_search(grid.begin(), grid.end(), t))
                << "triangle " << t << " has a point in box " << q;
          }
      }
      EXPECT_GT(nonEmpty, 200u) << "boxes too small to test anything";
      EXPECT_GT(witnessed, 200u);
    }
  }
}

TEST(MeshCollider, CollideMatchesBruteForce) {
  const Mesh soup = randomSoup(150, 9);
  std::mt19937 rng(4);
  // Cells of 2 and 4 radii: a particle's box then spans one to three cells per axis.
  for (const auto& [radius, cellInRadii] : {std::pair{Real(0.01), Real(4)}, std::pair{Real(0.03), Real(2)}}) {
    const StaticMeshCollider collider(soup.vertices, soup.triangles, cellInRadii * radius);
    std::size_t moved = 0;
    for (int i = 0; i < 5000; ++i) {
      const Vec3 previous = randomPoint(rng, -0.1, 1.1);
      const Real length = i % 10 == 0 ? uniform(rng, 0.5, 3) : uniform(rng, 0, 3 * double(radius));
      const Vec3 predicted = previous + length * randomDirection(rng);
      const Vec3 grid = collider.collide(previous, predicted, radius);
      const Vec3 brute = collideBruteForce(soup.vertices, soup.triangles, previous, predicted, radius);
      ASSERT_LE((grid - brute).cwiseAbs().maxCoeff(), Real(1e-5)) << "move " << i << ", radius " << radius;
      moved += grid != predicted;
    }
    EXPECT_GT(moved, 300u) << "too few contacts to test anything";
  }
}

TEST(MeshCollider, FallingParticleRestsOnFloorAtRadius) {
  Mesh floor;
  addQuad(floor, Vec3(-1, 0, -1), Vec3(-1, 0, 1), Vec3(1, 0, 1), Vec3(1, 0, -1));
  const Real r = Real(0.05), dt = Real(1) / Real(60);
  const StaticMeshCollider collider(floor.vertices, floor.triangles, 3 * r);
  // Gravity, position-based: v from the corrected displacement, so the floor also stops it.
  Vec3 x(Real(0.3), Real(1), Real(-0.2)), v = Vec3::Zero();
  for (int step = 0; step < 300; ++step) {
    v[1] -= Real(9.81) * dt;
    const Vec3 next = collider.collide(x, x + dt * v, r);
    v = (next - x) / dt;
    x = next;
    ASSERT_GE(x[1], r - Real(1e-5)) << "step " << step;
  }
  EXPECT_NEAR(x[1], r, 1e-5);
  EXPECT_EQ(x[0], Real(0.3));
  EXPECT_EQ(x[2], Real(-0.2));
  // In one step from far above to far below: stopped and lifted to the radius.
  const Vec3 fast =
      collider.collide(Vec3(Real(0.1), Real(2), Real(0.1)), Vec3(Real(0.1), Real(-40), Real(0.1)), r);
  EXPECT_NEAR(fast[1], r, 1e-5);
  // Coming from below (the floor is two-sided): stays below.
  const Vec3 below =
      collider.collide(Vec3(Real(0.1), Real(-1), Real(0.1)), Vec3(Real(0.1), Real(3), Real(0.1)), r);
  EXPECT_NEAR(below[1], -r, 1e-5);
}

TEST(MeshCollider, FastParticleNeverTunnelsOutOfClosedBox) {
  const Real r = Real(0.05);
  for (bool outward : {true, false}) {
    const Mesh box = unitBox(outward);
    ASSERT_EQ(box.triangles.size(), 12u);
    const SurfaceCheck check = checkSurface(box.triangles);
    ASSERT_TRUE(check.closed && check.consistentlyOriented);
    const StaticMeshCollider collider(box.vertices, box.triangles, 3 * r);
    std::mt19937 rng(outward ? 21 : 22);
    std::size_t escaped = 0;
    for (int i = 0; i < 5000; ++i) {
      const Vec3 previous = randomPoint(rng, double(r), 1 - double(r));
      // Mostly long moves (up to 10 box sizes), some short; a few aimed exactly at a corner or edge.
      Vec3 predicted = previous + uniform(rng, 0, i % 4 == 0 ? 0.2 : 10) * randomDirection(rng);
      if (i % 4 == 1) {
        // Through a random point of an edge or a face diagonal, where neighbouring triangles
        // meet and rounding could leave a crack.
        const Triangle& t = box.triangles[std::uniform_int_distribution<std::size_t>(0, 11)(rng)];
        const Vec3& a = box.vertices[t[std::size_t(i / 4) % 3]];
        const Vec3& b = box.vertices[t[std::size_t(i / 4 + 1) % 3]];
        const Vec3 target = a + uniform(rng, 0, 1) * (b - a);
        predicted = target + uniform(rng, 0.001, 10) * (target - previous);
      }
      escaped += insideDistance(predicted) < 0;
      const Vec3 x = collider.collide(previous, predicted, r);
      ASSERT_GE(insideDistance(x), r - Real(1e-5))
          << "move " << i << " from " << previous.transpose() << " to " << predicted.transpose()
          << " ended at " << x.transpose();
      if (i % 10 == 0) {
        ASSERT_EQ(x, collideBruteForce(box.vertices, box.triangles, previous, predicted, r));
      }
    }
    EXPECT_GT(escaped, 3000u) << "too few moves would leave the box";
  }
}

TEST(MeshCollider, ConcaveCornerPushesOutOfBothFaces) {
  const Real r = Real(0.05), tol = Real(1e-5);
  // L-shaped corner: floor y = 0 (x in [0, 1]) and wall x = 0 (y in [0, 1]).
  Mesh corner;
  addQuad(corner, Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 0, -1));
  addQuad(corner, Vec3(0, 0, -1), Vec3(0, 1, -1), Vec3(0, 1, 1), Vec3(0, 0, 1));
  const StaticMeshCollider collider(corner.vertices, corner.triangles, 3 * r);
  const Vec3 previous(2 * r, 2 * r, Real(0.1));
  // Into both faces, and beyond both planes (stopped on the floor first): ends at (r, r).
  for (const Vec3& predicted :
       {Vec3(Real(0.3) * r, Real(0.4) * r, Real(0.1)), Vec3(-r / 10, -r / 5, Real(0.1))}) {
    const Vec3 x = collider.collide(previous, predicted, r);
    EXPECT_NEAR(x[0], r, tol) << predicted.transpose();
    EXPECT_NEAR(x[1], r, tol) << predicted.transpose();
  }
  // Steeply down through the floor: stopped where it crossed, lifted to y = r.
  const Vec3 steep = collider.collide(previous, Vec3(Real(0.5) * r, Real(-0.3), Real(0.1)), r);
  EXPECT_NEAR(steep[0], Real(0.08125), tol);
  EXPECT_NEAR(steep[1], r, tol);
  // Three faces: the inside corner of the box.
  const Mesh box = unitBox(true);
  const StaticMeshCollider boxCollider(box.vertices, box.triangles, 3 * r);
  const Vec3 x = boxCollider.collide(Vec3::Constant(Real(0.2)), Vec3(Real(0.01), Real(0.02), Real(0.03)), r);
  EXPECT_TRUE((x.array() >= r - tol).all()) << x.transpose();
  // A 60 degree wedge between the floor and a tilted wall: alternating pushes converge.
  Mesh wedge;
  const Vec3 up(Real(0.5), std::sqrt(Real(3)) / 2, 0);  // wall direction from the apex
  addQuad(wedge, Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(2, 0, 1), Vec3(2, 0, -1));
  addQuad(wedge, Vec3(0, 0, -1), Vec3(Real(2) * up + Vec3(0, 0, -1)), Vec3(Real(2) * up + Vec3(0, 0, 1)),
          Vec3(0, 0, 1));
  const StaticMeshCollider wedgeCollider(wedge.vertices, wedge.triangles, 3 * r);
  const Vec3 wallNormal(up[1], -up[0], 0);  // into the wedge
  const Vec3 w =
      wedgeCollider.collide(Vec3(6 * r, r * Real(1.5), 0), Vec3(Real(0.5) * r, Real(0.1) * r, 0), r);
  EXPECT_GE(w[1], r - tol) << w.transpose();
  EXPECT_GE(wallNormal.dot(w), r - Real(1e-4) * r - tol) << w.transpose();
}

TEST(MeshCollider, ParticleGoesAroundFreeEdgeOfThinPlate) {
  // A plate y = 0, x in [0, 1]: a particle that passes beside its free edge x = 1 and ends over
  // the plate belongs above it, although `previous` was below the plate's plane.
  Mesh plate;
  addQuad(plate, Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 0, 0));
  const Real r = Real(0.05);
  const StaticMeshCollider collider(plate.vertices, plate.triangles, 3 * r);
  const Vec3 x =
      collider.collide(Vec3(Real(1.06), Real(-0.03), Real(0.5)), Vec3(Real(0.97), Real(0.03), Real(0.5)), r);
  EXPECT_NEAR(x[1], r, 1e-5) << x.transpose();
  EXPECT_EQ(x[0], Real(0.97));
  // Beside the edge within the radius: pushed straight away from the edge.
  const Vec3 beside =
      collider.collide(Vec3(Real(1.2), Real(-0.01), Real(0.5)), Vec3(Real(1.03), Real(-0.01), Real(0.5)), r);
  EXPECT_NEAR((beside - Vec3(1, 0, Real(0.5))).norm(), r, 1e-5);
  EXPECT_NEAR(beside[1] / (beside[0] - 1), Real(-0.01) / Real(0.03), 1e-3);
  // Straight through the plate from above: stopped above.
  const Vec3 through =
      collider.collide(Vec3(Real(0.5), Real(0.2), Real(0.5)), Vec3(Real(0.55), Real(-0.2), Real(0.5)), r);
  EXPECT_NEAR(through[1], r, 1e-5);
}

TEST(MeshCollider, DegenerateTrianglesAreSkipped) {
  Mesh m;
  addQuad(m, Vec3(-1, 0, -1), Vec3(-1, 0, 1), Vec3(1, 0, 1), Vec3(1, 0, -1));
  m.vertices.insert(m.vertices.end(), {Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0)});
  m.triangles.push_back({4, 5, 6});  // collinear
  m.triangles.push_back({4, 4, 5});  // repeated vertex
  const StaticMeshCollider collider(m.vertices, m.triangles, Real(0.1));
  EXPECT_EQ(collider.activeTriangleCount(), 2u);
  EXPECT_FALSE(collider.triangleMayTouchBox(2, Vec3::Constant(-5), Vec3::Constant(5)));
  // Straight through the line the degenerate triangles lie on: nothing stops it.
  const Vec3 predicted(Real(0.5), Real(0.8), 0);
  EXPECT_EQ(collider.collide(Vec3(Real(0.5), Real(1.2), 0), predicted, Real(0.05)), predicted);
  EXPECT_EQ(collideBruteForce(m.vertices, m.triangles, Vec3(Real(0.5), Real(1.2), 0), predicted, Real(0.05)),
            predicted);
}

TEST(MeshCollider, SameResultOnAnyThreadCount) {
  const Mesh soup = randomSoup(200, 5);
  const Real r = Real(0.02);
  const StaticMeshCollider collider(soup.vertices, soup.triangles, 3 * r);
  std::mt19937 rng(8);
  const int n = 20000;
  std::vector<Vec3> previous(n), predicted(n), serial(n), parallel(n);
  for (int i = 0; i < n; ++i) {
    previous[std::size_t(i)] = randomPoint(rng, 0, 1);
    predicted[std::size_t(i)] = previous[std::size_t(i)] + uniform(rng, 0, 0.06) * randomDirection(rng);
  }
  for (int i = 0; i < n; ++i)
    serial[std::size_t(i)] = collider.collide(previous[std::size_t(i)], predicted[std::size_t(i)], r);
#pragma omp parallel for num_threads(2) schedule(dynamic, 64)
  for (int i = 0; i < n; ++i)
    parallel[std::size_t(i)] = collider.collide(previous[std::size_t(i)], predicted[std::size_t(i)], r);
  EXPECT_EQ(serial, parallel);
  EXPECT_NE(serial, predicted);
}

TEST(MeshCollider, BadInputThrowsNamingTriangleOrVertex) {
  const std::vector<Vec3> v{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  auto expectContains = [](const std::string& message, const std::vector<std::string>& parts) {
    for (const std::string& p : parts)
      EXPECT_NE(message.find(p), std::string::npos) << message << " lacks " << p;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
  };
  expectContains(hs::testing::thrownMessage<std::invalid_argument>([&] {
                   StaticMeshCollider(v, {{0, 1, 2}, {0, 5, 1}}, Real(0.1));
                 }),
                 {"triangle 1", "vertex 5", "< 3"});
  expectContains(hs::testing::thrownMessage<std::invalid_argument>([&] {
                   (void)collideBruteForce(v, {{3, 1, 2}}, Vec3::Zero(), Vec3::Ones(), 1);
                 }),
                 {"triangle 0", "vertex 3", "< 3"});
  std::vector<Vec3> bad = v;
  bad[2][1] = std::nanf("");
  expectContains(hs::testing::thrownMessage<std::invalid_argument>([&] {
                   StaticMeshCollider(bad, {{0, 1, 2}}, Real(0.1));
                 }),
                 {"triangle 0", "vertex 2", "nan", "finite"});
  bad = v;
  bad.push_back(Vec3(std::numeric_limits<Real>::infinity(), 0, 0));
  expectContains(hs::testing::thrownMessage<std::invalid_argument>([&] {
                   StaticMeshCollider(bad, {{0, 1, 2}}, Real(0.1));
                 }),
                 {"vertex 3", "finite"});
  for (Real cell :
       {Real(0), Real(-1), std::numeric_limits<Real>::quiet_NaN(), std::numeric_limits<Real>::infinity()})
    expectContains(hs::testing::thrownMessage<std::invalid_argument>([&] {
                     StaticMeshCollider(v, {{0, 1, 2}}, cell);
                   }),
                   {"cellSize", "> 0"});
  // Empty meshes are fine and collide with nothing.
  const StaticMeshCollider empty({}, {}, Real(0.1));
  EXPECT_EQ(empty.collide(Vec3::Zero(), Vec3::Ones(), Real(0.1)), Vec3::Ones());
}

}  // namespace
}  // namespace hs::pbd
