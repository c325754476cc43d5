// The surface-to-wall mesher: prism cuts, conformity, no inverted tets, thickness from a
// second surface, boundary loops, remeshing to a target edge length.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "mesh/planar_cap.h"
#include "mesh/surface_remesh.h"
#include "mesh/wall_extrusion.h"
#include "sphere_surface.h"

namespace hs::pbd {
namespace {

using testing::cupTriangles;
using testing::makeSphere;

double sixVolume(const std::vector<Vec3>& x, const Tet& t) {
  return 6.0 * double(signedTetVolume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
}

TEST(SplitPrism, EveryIdOrderGivesThreePositiveTetsFillingThePrism) {
  // The unit prism (0,0,0), (1,0,0), (0,1,0) lifted by z = 1; corner ids permuted in all 6 ways
  // (the winding is the corners', the ids only decide the cut).
  const std::array<Vec3, 3> corner = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  std::array<Index, 3> ids = {0, 1, 2};
  do {
    std::vector<Vec3> x(6);
    for (int k = 0; k < 3; ++k) {
      x[ids[k]] = corner[k];
      x[ids[k] + 3] = corner[k] + Vec3(0, 0, 1);
    }
    double total = 0;
    for (const Tet& t : splitPrism({ids[0], ids[1], ids[2]}, 3)) {
      EXPECT_NEAR(sixVolume(x, t), 1.0, 1e-6);
      total += sixVolume(x, t);
    }
    EXPECT_NEAR(total / 6.0, 0.5, 1e-6);
  } while (std::next_permutation(ids.begin(), ids.end()));
}

TEST(SplitPrism, AnyIdsOnEitherTriangleGiveThreePositiveTetsFillingThePrism) {
  // All 720 ways of numbering the unit prism's six corners, the smallest id on the bottom or
  // the top: three positive tets that fill it.
  const std::array<Vec3, 6> corner = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                                      Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)};
  std::array<Index, 6> ids = {0, 1, 2, 3, 4, 5};
  int prisms = 0;
  do {
    std::vector<Vec3> x(6);
    for (int k = 0; k < 6; ++k) x[ids[k]] = corner[k];
    double total = 0;
    for (const Tet& t : splitPrism({ids[0], ids[1], ids[2]}, {ids[3], ids[4], ids[5]})) {
      EXPECT_NEAR(sixVolume(x, t), 1.0, 1e-6);
      total += sixVolume(x, t);
    }
    EXPECT_NEAR(total / 6.0, 0.5, 1e-6);
    ++prisms;
  } while (std::next_permutation(ids.begin(), ids.end()));
  EXPECT_EQ(prisms, 720);
}

TEST(SplitPrism, WithALayerOffsetItIsTheGeneralCut) {
  for (const Triangle& bottom : {Triangle{0, 1, 2}, Triangle{2, 0, 1}, Triangle{5, 3, 9}, Triangle{7, 8, 4}}) {
    const auto offset = splitPrism(bottom, 10);
    const auto general = splitPrism(bottom, {bottom[0] + 10, bottom[1] + 10, bottom[2] + 10});
    EXPECT_EQ(offset, general);
  }
}

TEST(SplitPrism, TwoPrismsSharingASideCutItTheSameWayForAnyIds) {
  // Two prisms side by side over the quad (1 2 | 1' 2'): random ids, the smallest anywhere.
  // Conforming means the shared side's two triangles are each used by one tet of each prism.
  std::mt19937 rng(7);
  for (int trial = 0; trial < 500; ++trial) {
    std::array<Index, 8> ids = {0, 1, 2, 3, 4, 5, 6, 7};
    std::shuffle(ids.begin(), ids.end(), rng);
    // Bottom corners a, b, c, d (b-c shared); tops a', b', c', d'.
    const Index a = ids[0], b = ids[1], c = ids[2], d = ids[3], a1 = ids[4], b1 = ids[5], c1 = ids[6], d1 = ids[7];
    std::vector<Tet> tets;
    for (const Tet& t : splitPrism({a, b, c}, {a1, b1, c1})) tets.push_back(t);
    for (const Tet& t : splitPrism({c, b, d}, {c1, b1, d1})) tets.push_back(t);
    // The two prisms' shared side is interior: only their outer sides remain on the boundary
    // (2 + 2 end triangles and 2 x 2 quads of two triangles each).
    EXPECT_EQ(boundaryFaces(tets).size(), 12u) << "trial " << trial;
  }
}

TEST(ExtrudeWall, ClosedSphereShellConformsAndHasTheShellVolume) {
  const auto sphere = makeSphere(3, 1.0);
  ExtrusionSettings settings;
  settings.layers = 3;
  const ExtrudedWall wall = extrudeWall(sphere.vertices, sphere.triangles,
                                        std::vector<double>(sphere.vertices.size(), 0.3), settings);
  ASSERT_EQ(wall.mesh.tets.size(), 3 * 3 * sphere.triangles.size());
  // Conforming: the only faces used by one tet are the inner and outer spheres. A cut that
  // differed between two prisms would leave their shared side as two pairs of lone faces.
  EXPECT_EQ(boundaryFaces(wall.mesh.tets).size(), 2 * sphere.triangles.size());
  const MeshQuality q = measureQuality(wall.mesh);
  EXPECT_EQ(q.invertedTets, 0u);
  EXPECT_GT(q.minVolume, 0);
  double volume = 0;
  for (const Tet& t : wall.mesh.tets) volume += sixVolume(wall.mesh.vertices, t) / 6.0;
  // A polyhedral shell of inscribed spheres: within 3% of (4/3) pi (1.3^3 - 1).
  EXPECT_NEAR(volume, 4.0 / 3.0 * std::numbers::pi * (1.3 * 1.3 * 1.3 - 1.0),
              0.03 * 4.0 / 3.0 * std::numbers::pi * 1.197);
  EXPECT_EQ(wall.shrunkVertices, 0);
}

TEST(ExtrudeWall, OffsetInwardPastTheCentreShrinksInsteadOfInverting) {
  // Reversed triangles face into the sphere: a 1.5 thick wall inward from radius 1 would cross
  // itself at the centre.
  auto sphere = makeSphere(2, 1.0);
  for (Triangle& t : sphere.triangles) std::swap(t[1], t[2]);
  const ExtrudedWall wall =
      extrudeWall(sphere.vertices, sphere.triangles, std::vector<double>(sphere.vertices.size(), 1.5), {});
  EXPECT_GT(wall.shrunkVertices, 0);
  EXPECT_EQ(measureQuality(wall.mesh).invertedTets, 0u);
  for (double t : wall.thickness) EXPECT_LT(t, 1.0);
}

TEST(ExtrudeWall, ThicknessToAnOuterSphereIsTheGap) {
  const auto inner = makeSphere(2, 1.0), outer = makeSphere(4, 1.5);
  const auto n = smoothNormals(vertexNormals(inner.vertices, inner.triangles), inner.triangles, 2);
  const std::vector<double> t = thicknessToSurface(inner.vertices, n, outer.vertices, outer.triangles);
  // The polyhedral outer sphere lies within 1 - cos(edge angle / 2) of radius 1.5.
  for (double ti : t) EXPECT_NEAR(ti, 0.5, 0.01);
}

// The recorded beat smooths its directions every step over neighbours listed once: the same
// sweeps as over the triangles, to the bit. A bumpy sphere (every third vertex pushed out) so
// that the sweeps have something to smooth.
TEST(SmoothNormals, OverListedNeighboursIsTheSameAsOverTriangles) {
  auto sphere = makeSphere(2, 1.0);
  for (std::size_t i = 0; i < sphere.vertices.size(); i += 3) sphere.vertices[i] *= Real(1.2);
  const std::vector<Vec3d> raw = vertexNormals(sphere.vertices, sphere.triangles);
  const auto neighbours = vertexNeighbours(sphere.vertices.size(), sphere.triangles);
  for (int sweeps : {0, 1, 10}) {
    const std::vector<Vec3d> a = smoothNormals(raw, sphere.triangles, sweeps);
    const std::vector<Vec3d> b = smoothNormals(raw, neighbours, sweeps);
    ASSERT_EQ(a.size(), raw.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << "vertex " << i << ", " << sweeps << " sweeps";
  }
  EXPECT_GT((smoothNormals(raw, neighbours, 10)[0] - raw[0]).norm(), 1e-3);  // the sweeps moved them
}

TEST(ClosestPointOnTriangle, AgreesWithDenseSampling) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3d a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng)),
        p(u(rng), u(rng), u(rng));
    const double exact = (closestPointOnTriangle(p, a, b, c) - p).norm();
    double sampled = 1e300;
    const int n = 120;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
        sampled = std::min(sampled, (a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n) - p).norm());
    EXPECT_LE(exact, sampled + 1e-12);
    EXPECT_GE(exact, sampled - 0.05 * (b - a).norm() - 0.05 * (c - a).norm());
  }
}

TEST(ClosestPointQuery, PruningGivesTheBruteForceAnswer) {
  const auto sphere = makeSphere(3, 1.0);
  const ClosestPointQuery query(sphere.vertices, sphere.triangles);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3d p(u(rng), u(rng), u(rng));
    double brute = 1e300;
    for (const Triangle& t : sphere.triangles)
      brute = std::min(brute, (closestPointOnTriangle(p, sphere.vertices[t[0]].cast<double>(),
                                                      sphere.vertices[t[1]].cast<double>(),
                                                      sphere.vertices[t[2]].cast<double>()) -
                               p)
                                  .norm());
    EXPECT_EQ((query.closestPoint(p) - p).norm(), brute);
  }
}

TEST(BoundaryLoops, CupHasOneLoopSphereNone) {
  const auto sphere = makeSphere(3, 1.0);
  EXPECT_TRUE(boundaryLoopVertices(sphere.triangles).empty());
  const auto cup = cupTriangles(sphere, 0.3);
  const auto loops = boundaryLoopVertices(cup);
  ASSERT_EQ(loops.size(), 1u);
  // Each loop edge is one triangle's edge, traversed a -> b by it.
  for (std::size_t k = 0; k < loops[0].size(); ++k) {
    const Index a = loops[0][k], b = loops[0][(k + 1) % loops[0].size()];
    int uses = 0;
    for (const Triangle& t : cup)
      for (int e = 0; e < 3; ++e) uses += t[e] == a && t[(e + 1) % 3] == b;
    EXPECT_EQ(uses, 1);
  }
  // A cup facing out of what it holds: positive capped volume; reversed, negative.
  auto reversed = cup;
  for (Triangle& t : reversed) std::swap(t[1], t[2]);
  EXPECT_GT(cappedSignedVolume(sphere.vertices, cup), 0);
  EXPECT_LT(cappedSignedVolume(sphere.vertices, reversed), 0);
}

TEST(RemeshIsotropic, SphereReachesTheTargetEdgeAndStaysOnTheSurface) {
  const auto sphere = makeSphere(4, 1.0);  // mean edge ~0.08
  for (double target : {0.25, 0.04}) {
    const RemeshedSurface r = remeshIsotropic(sphere.vertices, sphere.triangles, {target, 6});
    const EdgeLengthStats st = edgeLengthStats(r.vertices, r.triangles);
    EXPECT_GT(st.mean, 0.8 * target) << target;
    EXPECT_LT(st.mean, 1.33 * target) << target;
    // Relaxation after the last split may stretch a few edges past 4/3 L.
    EXPECT_LT(st.longest, 1.5 * target) << target;
    const SurfaceCheck check = checkSurface(r.triangles);
    EXPECT_TRUE(check.closed && check.consistentlyOriented) << target;
    // Vertices on the input polyhedron, which lies within 0.4% of the unit sphere.
    for (const Vec3& p : r.vertices) EXPECT_NEAR(p.cast<double>().norm(), 1.0, 0.006) << target;
    EXPECT_GT(enclosedVolume(r.vertices, r.triangles), 0);
  }
}

TEST(RemeshIsotropic, CupKeepsItsLoopOnTheRim) {
  const auto sphere = makeSphere(4, 1.0);
  const auto cup = extractSubSurface(sphere.vertices, sphere.triangles, [&] {
    std::vector<Index> ids;
    const auto kept = cupTriangles(sphere, 0.3);
    for (Index f = 0; f < sphere.triangles.size(); ++f)
      if (std::find(kept.begin(), kept.end(), sphere.triangles[f]) != kept.end()) ids.push_back(f);
    return ids;
  }());
  const RemeshedSurface r = remeshIsotropic(cup.vertices, cup.triangles, {0.15, 6});
  const auto loops = boundaryLoopVertices(r.triangles);
  ASSERT_EQ(loops.size(), 1u);
  const double zRimMax = 0.35;
  for (Index v : loops[0]) {
    EXPECT_GT(r.vertices[v].z(), 0.1);
    EXPECT_LT(r.vertices[v].z(), zRimMax);
  }
  EXPECT_EQ(checkSurface(r.triangles).nonManifoldEdges, 0u);
  EXPECT_GT(cappedSignedVolume(r.vertices, r.triangles), 0);
}

// A cup of the unit sphere remeshed coarsely holds less than the input (chords inside the
// curve); restoring moves the vertices out by one distance (half of it beside the rim) until the
// capped volumes agree, leaves the rim where it was, and works for either orientation.
TEST(RestoreCappedVolume, GivesACoarseCupItsInputVolumeBackAndLeavesTheRim) {
  const auto sphere = makeSphere(4, 1.0);
  std::vector<Index> kept;
  const auto cupFaces = cupTriangles(sphere, 0.3);
  for (Index f = 0; f < sphere.triangles.size(); ++f)
    if (std::find(cupFaces.begin(), cupFaces.end(), sphere.triangles[f]) != cupFaces.end()) kept.push_back(f);
  const auto cup = extractSubSurface(sphere.vertices, sphere.triangles, kept);
  const double input = cappedSignedVolume(cup.vertices, cup.triangles);
  for (const bool reversed : {false, true}) {
    RemeshedSurface r = remeshIsotropic(cup.vertices, cup.triangles, {0.3, 6});
    const auto loops = boundaryLoopVertices(r.triangles);
    ASSERT_EQ(loops.size(), 1u);
    if (reversed)
      for (Triangle& t : r.triangles) std::swap(t[1], t[2]);
    const double before = std::abs(cappedSignedVolume(r.vertices, r.triangles));
    ASSERT_LT(before, 0.98 * input) << "a coarse remesh should lose volume, else this test shows nothing";
    const std::vector<Vec3> remeshed = r.vertices;
    const double d = restoreCappedVolume(r.vertices, r.triangles, reversed ? -input : input);
    EXPECT_NEAR(std::abs(cappedSignedVolume(r.vertices, r.triangles)), input, 1e-6 * input) << reversed;
    EXPECT_GT(d, 0) << reversed;  // outward, whichever way the triangles face
    EXPECT_LT(d, 0.05) << reversed;
    // The rim stays, its neighbours move half the distance, the rest all of it.
    std::vector<int> hops(r.vertices.size(), 2);
    for (Index v : loops[0]) hops[v] = 0;
    for (const Triangle& t : r.triangles)
      for (Index a : t)
        for (Index b : t)
          if (hops[b] == 0 && hops[a] != 0) hops[a] = 1;
    for (std::size_t v = 0; v < r.vertices.size(); ++v)
      EXPECT_NEAR((r.vertices[v] - remeshed[v]).cast<double>().norm(), 0.5 * hops[v] * d, 1e-5) << v;
  }
}

}  // namespace
}  // namespace hs::pbd

namespace hs::pbd {
namespace {

TEST(OffsetDirections, SeeEveryFaceAtTheirVertexWithinSixtyDegrees) {
  // A cube's corners: three faces at right angles; their smoothed normals lie along the
  // diagonal, which sees each face at 54.7 degrees.
  const std::vector<Vec3> v = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                               Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  const std::vector<Triangle> t = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                   {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {0, 4, 7}, {0, 7, 3}};
  ExtrusionSettings settings;
  settings.normalSmoothing = 30;  // smoothing alone would pull the directions around
  const auto d = offsetDirections(v, t, settings);
  for (const Triangle& f : t) {
    const Vec3d n = (v[f[1]] - v[f[0]]).cast<double>().cross((v[f[2]] - v[f[0]]).cast<double>()).normalized();
    for (Index i : f) EXPECT_GE(n.dot(d[i]), settings.minFaceCosine - 1e-9);
  }
}

TEST(ExtrudeWall, LayerSmoothingMovesAcrossTheDirectionsOnlyAndNeverWorsens) {
  // An ellipsoid: layers over a surface of varying curvature.
  auto s = makeSphere(2, 1.0);
  for (Vec3& p : s.vertices) p.z() *= Real(2.5);
  ExtrusionSettings smooth, raw;
  smooth.layers = raw.layers = 3;
  raw.smoothingSweeps = 0;
  const std::vector<double> t(s.vertices.size(), 0.4);
  const ExtrudedWall a = extrudeWall(s.vertices, s.triangles, t, smooth);
  const ExtrudedWall b = extrudeWall(s.vertices, s.triangles, t, raw);
  ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
  const std::size_t n = s.vertices.size();
  for (std::size_t v = 0; v < a.mesh.vertices.size(); ++v) {
    const std::size_t i = v % n, layer = v / n;
    const double along = (a.mesh.vertices[v] - s.vertices[i]).cast<double>().dot(a.directions[i]);
    EXPECT_NEAR(along, a.thickness[i] * double(layer) / 3.0, 1e-5) << v;
  }
  EXPECT_GE(measureQuality(a.mesh).minDihedralDeg, measureQuality(b.mesh).minDihedralDeg);
  EXPECT_EQ(measureQuality(a.mesh).invertedTets, 0u);
}

TEST(LargestFlatRegion, FindsTheFlatCapOfAClosedCup) {
  // The lower hemisphere closed at z = 0 by a fan from the centre: the fan is the flat face.
  const auto sphere = makeSphere(3, 1.0);
  auto cup = cupTriangles(sphere, 0.0);
  std::vector<Vec3> v = sphere.vertices;
  v.emplace_back(0, 0, 0);
  const auto centre = static_cast<Index>(v.size() - 1);
  const auto loops = boundaryLoopVertices(cup);
  ASSERT_EQ(loops.size(), 1u);
  const std::size_t cupSize = cup.size();
  for (std::size_t k = 0; k < loops[0].size(); ++k)
    cup.push_back({centre, loops[0][(k + 1) % loops[0].size()], loops[0][k]});
  double area = 0;
  const auto flat = largestFlatRegion(v, cup, 2.0, 1e-6, &area);
  ASSERT_EQ(flat.size(), loops[0].size());
  for (Index f : flat) EXPECT_GE(f, cupSize);
  EXPECT_NEAR(area, std::numbers::pi, 0.1);  // the inscribed 32-gon of the unit circle
}

TEST(CapWithHoles, CoversTheRimMinusTheHolesAndJoinsTheRim) {
  // A 48-gon of radius 1 with holes of radius 0.35 and 0.25.
  std::vector<Eigen::Vector2d> rim;
  std::vector<Index> ids;
  for (int k = 0; k < 48; ++k) {
    const double phi = 2 * std::numbers::pi * k / 48;
    rim.emplace_back(std::cos(phi), std::sin(phi));
    ids.push_back(static_cast<Index>(k));
  }
  const std::vector<CircularHole> holes = {{{-0.4, 0}, 0.35}, {{0.5, 0}, 0.25}};
  const PlanarCap cap = capWithHoles(rim, ids, 48, holes, 0.12);
  std::vector<Eigen::Vector2d> all = rim;
  all.insert(all.end(), cap.newPoints.begin(), cap.newPoints.end());
  double area = 0;
  for (const Triangle& t : cap.triangles) {
    const Eigen::Vector2d e1 = all[t[1]] - all[t[0]], e2 = all[t[2]] - all[t[0]];
    const double a = 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
    EXPECT_GT(a, 0);  // counter-clockwise
    area += a;
  }
  // Polygons inscribed in the circles: the 48-gon's area less the hole rings' polygons.
  const auto polygonArea = [](double r, int n) {
    return 0.5 * n * r * r * std::sin(2 * std::numbers::pi / n);
  };
  const double expected = polygonArea(1, 48) - polygonArea(0.35, static_cast<int>(cap.holeRings[0].size())) -
                          polygonArea(0.25, static_cast<int>(cap.holeRings[1].size()));
  EXPECT_NEAR(area, expected, 1e-9);
  // Boundary loops: the rim and the two rings, nothing else.
  const auto loops = boundaryLoopVertices(cap.triangles);
  ASSERT_EQ(loops.size(), 3u);
  std::vector<std::size_t> sizes;
  for (const auto& l : loops) sizes.push_back(l.size());
  std::sort(sizes.begin(), sizes.end());
  std::vector<std::size_t> expectedSizes = {cap.holeRings[0].size(), cap.holeRings[1].size(), 48};
  std::sort(expectedSizes.begin(), expectedSizes.end());
  EXPECT_EQ(sizes, expectedSizes);
  EXPECT_THROW(capWithHoles(rim, ids, 48, {{{0.0, 0}, 0.99}}, 0.12), std::invalid_argument);
  EXPECT_THROW(capWithHoles(rim, ids, 48, {{{-0.2, 0}, 0.3}, {{0.2, 0}, 0.3}}, 0.12), std::invalid_argument);
}

}  // namespace
}  // namespace hs::pbd
