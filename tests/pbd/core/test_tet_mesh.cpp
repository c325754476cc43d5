#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "pbd/core/tet_mesh.h"

namespace hs::pbd {
namespace {

constexpr Real kTol = Real(1e-5);

TetMesh unitTet() {
  TetMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.tets = {{0, 1, 2, 3}};
  return m;
}

// Unit cube corners, id = x + 2y + 4z.
std::vector<Vec3> cubeCorners(Real x0 = 0) {
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(x0 + Real(i & 1), Real((i >> 1) & 1), Real((i >> 2) & 1));
  return v;
}

// Swaps two vertices of every negative tet so all are positive.
void orientPositive(TetMesh& m) {
  for (Tet& t : m.tets) {
    const auto& x = m.vertices;
    if (signedTetVolume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]) < 0) std::swap(t[2], t[3]);
  }
}

// Six tets around the diagonal 0-7, one per monotone path 0 -> 7 along the axes (Kuhn).
TetMesh kuhnCube() {
  TetMesh m;
  m.vertices = cubeCorners();
  const Index axes[3] = {1, 2, 4};
  int perm[3] = {0, 1, 2};
  do {
    const Index a = axes[perm[0]];
    const Index b = a + axes[perm[1]];
    m.tets.push_back({0, a, b, 7});
  } while (std::next_permutation(perm, perm + 3));
  orientPositive(m);
  return m;
}

// A central tet on the odd corners 1, 2, 4, 7 plus one corner tet at each even corner.
TetMesh fiveTetCube() {
  TetMesh m;
  m.vertices = cubeCorners();
  m.tets = {{1, 2, 4, 7}, {0, 1, 2, 4}, {3, 1, 2, 7}, {5, 1, 4, 7}, {6, 2, 4, 7}};
  orientPositive(m);
  return m;
}

Real sumTetVolumes(const TetMesh& m) {
  Real sum = 0;
  for (const Tet& t : m.tets)
    sum += signedTetVolume(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]);
  return sum;
}

TEST(TetMesh, SignedVolumeOfKnownTet) {
  const TetMesh m = unitTet();
  const auto& x = m.vertices;
  EXPECT_NEAR(signedTetVolume(x[0], x[1], x[2], x[3]), Real(1.0 / 6.0), kTol);
  EXPECT_NEAR(signedTetVolume(x[0], x[2], x[1], x[3]), Real(-1.0 / 6.0), kTol);
  const Vec3 shift(3, -2, 5);
  EXPECT_NEAR(signedTetVolume(2 * x[0] + shift, 2 * x[1] + shift, 2 * x[2] + shift, 2 * x[3] + shift),
              Real(8.0 / 6.0), kTol);
}

TEST(TetMesh, BoundaryOfSingleTetIsClosedAndOutward) {
  const TetMesh m = unitTet();
  const auto faces = boundaryFaces(m.tets);
  ASSERT_EQ(faces.size(), 4u);
  const SurfaceCheck check = checkSurface(faces);
  EXPECT_TRUE(check.closed);
  EXPECT_TRUE(check.consistentlyOriented);
  EXPECT_NEAR(enclosedVolume(m.vertices, faces), Real(1.0 / 6.0), kTol);
  // The face on the plane z = 0 must point down (-z).
  for (const Triangle& f : faces) {
    const auto& x = m.vertices;
    const Vec3 n = (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]);
    const Vec3 centroid = (x[f[0]] + x[f[1]] + x[f[2]]) / 3;
    EXPECT_GT(n.dot(centroid - Vec3(Real(0.25), Real(0.25), Real(0.25))), 0);
  }
}

TEST(TetMesh, CubeSplitsHaveClosedOutwardBoundary) {
  for (const TetMesh& m : {kuhnCube(), fiveTetCube()}) {
    const auto faces = boundaryFaces(m.tets);
    EXPECT_EQ(faces.size(), 12u);  // two triangles per cube face, interior faces cancelled
    const SurfaceCheck check = checkSurface(faces);
    EXPECT_TRUE(check.closed);
    EXPECT_TRUE(check.consistentlyOriented);
    EXPECT_NEAR(sumTetVolumes(m), Real(1), kTol);
    EXPECT_NEAR(enclosedVolume(m.vertices, faces), sumTetVolumes(m), kTol);
    EXPECT_EQ(measureQuality(m).invertedTets, 0u);
  }
}

TEST(TetMesh, TwoCubesShareTheirInteriorFace) {
  TetMesh m = kuhnCube();
  const TetMesh right = kuhnCube();
  const std::vector<Vec3> corners = cubeCorners(1);
  // Corners of the second cube: x = 0 side reuses ids 1, 3, 5, 7 of the first.
  const Index map[8] = {1, 8, 3, 9, 5, 10, 7, 11};
  for (int i : {1, 3, 5, 7}) m.vertices.push_back(corners[i]);
  for (Tet t : right.tets) {
    for (Index& v : t) v = map[v];
    m.tets.push_back(t);
  }
  const auto faces = boundaryFaces(m.tets);
  EXPECT_EQ(faces.size(), 20u);
  EXPECT_TRUE(checkSurface(faces).closed);
  EXPECT_TRUE(checkSurface(faces).consistentlyOriented);
  EXPECT_NEAR(enclosedVolume(m.vertices, faces), Real(2), kTol);
  // Sorted, each face rotated to start at its smallest id.
  EXPECT_TRUE(std::is_sorted(faces.begin(), faces.end()));
  for (const Triangle& f : faces) EXPECT_LT(f[0], std::min(f[1], f[2]));
}

TEST(TetMesh, UniqueEdgeCounts) {
  EXPECT_EQ(uniqueEdges(unitTet().tets).size(), 6u);
  // 12 cube edges + 6 face diagonals + the main diagonal.
  EXPECT_EQ(uniqueEdges(kuhnCube().tets).size(), 19u);
  // 12 cube edges + 6 face diagonals (the central tet's edges).
  const auto edges = uniqueEdges(fiveTetCube().tets);
  EXPECT_EQ(edges.size(), 18u);
  EXPECT_TRUE(std::is_sorted(edges.begin(), edges.end()));
  for (const Edge& e : edges) EXPECT_LT(e[0], e[1]);
}

TEST(TetMesh, CheckSurfaceDetectsOpenAndFlippedFaces) {
  auto faces = boundaryFaces(kuhnCube().tets);
  std::vector<Triangle> open(faces.begin() + 1, faces.end());
  const SurfaceCheck openCheck = checkSurface(open);
  EXPECT_FALSE(openCheck.closed);
  EXPECT_EQ(openCheck.boundaryEdges, 3u);
  EXPECT_TRUE(openCheck.consistentlyOriented);

  std::vector<Triangle> flipped = faces;
  std::swap(flipped[4][1], flipped[4][2]);
  const SurfaceCheck flippedCheck = checkSurface(flipped);
  EXPECT_TRUE(flippedCheck.closed);
  EXPECT_FALSE(flippedCheck.consistentlyOriented);

  // Three triangles on one edge: non-manifold.
  const std::vector<Triangle> fin = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const SurfaceCheck finCheck = checkSurface(fin);
  EXPECT_EQ(finCheck.nonManifoldEdges, 1u);
  EXPECT_FALSE(finCheck.closed);
  EXPECT_FALSE(finCheck.consistentlyOriented);
}

TEST(TetMesh, QualityOfRegularAndBadTets) {
  TetMesh regular;
  regular.vertices = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  regular.tets = {{0, 1, 2, 3}};
  orientPositive(regular);
  const MeshQuality q = measureQuality(regular);
  const Real expected = Real(std::acos(1.0 / 3.0) * 180.0 / 3.14159265358979323846);  // 70.53 deg
  EXPECT_NEAR(q.minDihedralDeg, expected, Real(1e-3));
  EXPECT_NEAR(q.maxDihedralDeg, expected, Real(1e-3));
  EXPECT_NEAR(q.maxAspectRatio, Real(1), Real(1e-5));
  EXPECT_NEAR(q.meanAspectRatio, Real(1), Real(1e-5));
  EXPECT_EQ(q.invertedTets, 0u);
  EXPECT_GT(q.minVolume, 0);

  // The unit corner tet: dihedral angles 90 (at the axes) and acos(1/sqrt(3)) = 54.74 deg.
  const MeshQuality corner = measureQuality(unitTet());
  EXPECT_NEAR(corner.maxDihedralDeg, Real(90), Real(1e-3));
  EXPECT_NEAR(corner.minDihedralDeg, Real(54.7356), Real(1e-3));
  EXPECT_GT(corner.maxAspectRatio, Real(1.1));

  TetMesh inverted = unitTet();
  std::swap(inverted.tets[0][1], inverted.tets[0][2]);
  EXPECT_EQ(measureQuality(inverted).invertedTets, 1u);
  EXPECT_LT(measureQuality(inverted).minVolume, 0);

  TetMesh flat = unitTet();
  flat.vertices[3] = Vec3(Real(0.3), Real(0.3), Real(0.01));
  EXPECT_LT(measureQuality(flat).minDihedralDeg, Real(5));
}

}  // namespace
}  // namespace hs::pbd
