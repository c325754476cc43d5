#include <gtest/gtest.h>

#include <chrono>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "cardiac/anatomy/aha_segments.h"
#include "cardiac/anatomy/lv_model.h"

namespace hs::cardiac {
namespace {

// Thesis Fig. 5.1 model: 1,061 vertices, 2,118 surface faces, 3,345 tets.
constexpr double kThesisVertices = 1061;
constexpr double kThesisFaces = 2118;
constexpr double kThesisTets = 3345;

const LvModel& defaultModel() {
  static const LvModel model = buildLvModel(LvGeometryParams{});
  return model;
}

double sumTetVolumes(const pbd::TetMesh& m) {
  double sum = 0;
  for (const pbd::Tet& t : m.tets) {
    sum += pbd::signedTetVolume(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]);
  }
  return sum;
}

// Angle around the long axis: 0 anterior, 90 septal, 180 inferior, 270 lateral, written out
// from the frame (aha_segments.h): anterior (1/2, 0, -sqrt 3/2), septal (sqrt 3/2, 0, 1/2).
double angleDeg(const Vec3& p) {
  const double s3 = std::sqrt(3.0) / 2;
  const double anterior = 0.5 * double(p.x()) - s3 * double(p.z());
  const double septal = s3 * double(p.x()) + 0.5 * double(p.z());
  const double deg = std::atan2(septal, anterior) * 180.0 / std::numbers::pi;
  return deg < 0 ? deg + 360 : deg;
}

double angularDistance(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

TEST(LvModel, CountsMatchThesisModel) {
  const LvModel& m = defaultModel();
  const pbd::MeshQuality q = pbd::measureQuality(m.mesh);
  std::printf(
      "LV model (resolution 1): %zu vertices, %zu surface faces, %zu tets; dihedral %.2f..%.2f deg, "
      "aspect max %.2f mean %.2f\n",
      m.mesh.vertices.size(), m.surface.size(), m.mesh.tets.size(), double(q.minDihedralDeg),
      double(q.maxDihedralDeg), double(q.maxAspectRatio), double(q.meanAspectRatio));
  EXPECT_NEAR(double(m.mesh.vertices.size()), kThesisVertices, 0.25 * kThesisVertices);
  EXPECT_NEAR(double(m.surface.size()), kThesisFaces, 0.25 * kThesisFaces);
  EXPECT_NEAR(double(m.mesh.tets.size()), kThesisTets, 0.25 * kThesisTets);
  // A shell one tet thick: every vertex is on the surface, in inner/outer pairs.
  std::vector<int> onSurface(m.mesh.vertices.size(), 0);
  for (const pbd::Triangle& f : m.surface) {
    for (Index v : f) onSurface[v] = 1;
  }
  EXPECT_TRUE(std::all_of(onSurface.begin(), onSurface.end(), [](int s) { return s == 1; }));
  EXPECT_EQ(m.mesh.vertices.size() % 2, 0u);
}

// The front view's plane is the three-chamber plane (aha_segments.h): the aortic orifice, where
// the outflow tract leaves, is anteroseptal (60 degrees), the mitral inferolateral (240): the
// outflow on the septal side, blood entering on the viewer's left.
TEST(LvModel, TheOutflowTractIsOnTheSeptalSideTheInflowLateral) {
  const LvModel& m = defaultModel();
  EXPECT_NEAR(angleDeg(m.flowPath.aortic.centre), 60.0, 1e-3);
  EXPECT_NEAR(angleDeg(m.flowPath.mitral.centre), 240.0, 1e-3);
  EXPECT_LT(m.flowPath.mitral.centre.x(), m.flowPath.aortic.centre.x());
  // The segments there: basal anteroseptal (2) under the aortic ring, inferolateral (5) beside
  // the mitral.
  auto nearestSegment = [&](const Vec3& p) {
    double best = 1e30;
    int segment = 0;
    for (std::size_t v = 0; v < m.mesh.vertices.size(); v += 2)
      if (m.segment[v] != 0 && (m.mesh.vertices[v] - p).squaredNorm() < best)
        best = (m.mesh.vertices[v] - p).squaredNorm(), segment = m.segment[v];
    return segment;
  };
  const Vec3 aortic = m.flowPath.aortic.centre, mitral = m.flowPath.mitral.centre;
  EXPECT_EQ(nearestSegment(Vec3(aortic.x() * 3, -m.params.endoLongAxis / 10, aortic.z())), 2);
  EXPECT_EQ(nearestSegment(Vec3(mitral.x() * 3, -m.params.endoLongAxis / 10, mitral.z())), 5);
}

TEST(LvModel, TetsArePositiveAndWellShaped) {
  const pbd::MeshQuality q = pbd::measureQuality(defaultModel().mesh);
  EXPECT_EQ(q.invertedTets, 0u);
  EXPECT_GT(q.minVolume, 0);
  EXPECT_GE(q.minDihedralDeg, Real(10));
  EXPECT_LE(q.maxAspectRatio, Real(6));
}

TEST(LvModel, SurfaceIsClosedOrientedAndEnclosesTheTets) {
  const LvModel& m = defaultModel();
  const pbd::SurfaceCheck check = pbd::checkSurface(m.surface);
  EXPECT_TRUE(check.closed);
  EXPECT_TRUE(check.consistentlyOriented);
  EXPECT_EQ(check.boundaryEdges, 0u);
  EXPECT_EQ(check.nonManifoldEdges, 0u);
  const double tets = sumTetVolumes(m.mesh);
  EXPECT_NEAR(double(pbd::enclosedVolume(m.mesh.vertices, m.surface)), tets, 1e-4 * tets);
}

TEST(LvModel, SegmentsCoverTheMyocardiumInTheirSectors) {
  const LvModel& m = defaultModel();
  const double c = m.params.endoLongAxis;
  std::vector<int> count(18, 0);
  for (std::size_t v = 0; v < m.mesh.vertices.size(); ++v) {
    const int s = m.segment[v];
    if (m.region[v] != Region::Myocardium) {
      EXPECT_EQ(s, 0) << "vertex " << v;
      continue;
    }
    ASSERT_GE(s, 1);
    ASSERT_LE(s, 17);
    ++count[s];
    // Segments are transmural: both layers carry the segment of the inner (even) vertex.
    EXPECT_EQ(m.segment[v], m.segment[v - v % 2]);
    if (v % 2 != 0) continue;
    const Vec3& p = m.mesh.vertices[v];
    const double depth = -double(p.y()) / c;
    const double angle = angleDeg(p);
    if (s <= 6) {
      EXPECT_LT(depth, 1.0 / 3.0 + 1e-6);
      EXPECT_LE(angularDistance(angle, 60.0 * (s - 1)), 30.0 + 1e-6) << "vertex " << v;
    } else if (s <= 12) {
      EXPECT_GE(depth, 1.0 / 3.0 - 1e-6);
      EXPECT_LT(depth, 2.0 / 3.0 + 1e-6);
      EXPECT_LE(angularDistance(angle, 60.0 * (s - 7)), 30.0 + 1e-6) << "vertex " << v;
    } else if (s <= 16) {
      EXPECT_GE(depth, 2.0 / 3.0 - 1e-6);
      EXPECT_LT(depth, 0.9 + 1e-6);
      EXPECT_LE(angularDistance(angle, 90.0 * (s - 13)), 45.0 + 1e-6) << "vertex " << v;
    } else {
      EXPECT_GE(depth, 0.9 - 1e-6);
    }
  }
  for (int s = 1; s <= 17; ++s) EXPECT_GT(count[s], 0) << "segment " << s;
  // Orientation: the anterior segment 1 lies toward kAnterior, the septal ones (3, 14) toward
  // kSeptal, the apical lateral one (16) away from it.
  for (std::size_t v = 0; v < m.mesh.vertices.size(); v += 2) {
    const Eigen::Vector3d p = m.mesh.vertices[v].cast<double>();
    if (m.segment[v] == 1) {
      EXPECT_GT(p.dot(kAnterior), 0);
    }
    if (m.segment[v] == 3 || m.segment[v] == 14) {
      EXPECT_GT(p.dot(kSeptal), 0);
    }
    if (m.segment[v] == 16) {
      EXPECT_LT(p.dot(kSeptal), 0);
    }
  }
}

TEST(LvModel, CavityVolumeMatchesHalfSpheroid) {
  const LvModel& m = defaultModel();
  const double a = m.params.endoRadius;
  const double c = m.params.endoLongAxis;
  const double analytic = 2.0 / 3.0 * std::numbers::pi * a * a * c;
  const double v = cavityVolume(m, m.mesh.vertices);
  std::printf("cavity volume %.4f m^3, analytic %.4f m^3 (%.2f%%)\n", v, analytic, 100 * (v / analytic - 1));
  EXPECT_NEAR(v, analytic, 0.03 * analytic);
  // Moving every vertex by a constant does not change it (the cavity surface is closed).
  std::vector<Vec3> shifted = m.mesh.vertices;
  for (Vec3& p : shifted) p += Vec3(5, -3, 2);
  EXPECT_NEAR(double(cavityVolume(m, shifted)), v, 1e-4 * v);
}

TEST(LvModel, CavitySurfaceWithRingFansIsClosedAndOutward) {
  const LvModel& m = defaultModel();
  std::vector<pbd::Triangle> faces = m.cavitySurface;
  auto extra = static_cast<Index>(m.mesh.vertices.size());
  for (const std::vector<Index>* ring : {&m.mitralRing, &m.aorticRing}) {
    for (std::size_t k = 0; k < ring->size(); ++k)
      faces.push_back({extra, (*ring)[k], (*ring)[(k + 1) % ring->size()]});
    ++extra;
  }
  const pbd::SurfaceCheck check = pbd::checkSurface(faces);
  EXPECT_TRUE(check.closed);
  EXPECT_TRUE(check.consistentlyOriented);
  for (const pbd::Triangle& f : m.cavitySurface) {
    for (Index v : f) {
      EXPECT_EQ(v % 2, 0u);  // inner layer only
      EXPECT_TRUE(m.region[v] == Region::Myocardium || m.region[v] == Region::BasePlate);
    }
  }
}

TEST(LvModel, OrificeRingsSitInTheBasePlane) {
  const LvModel& m = defaultModel();
  auto ringInfo = [&](const std::vector<Index>& ring, double& radius, double& fanNormalY) {
    Vec3 centroid = Vec3::Zero();
    for (Index v : ring) centroid += m.mesh.vertices[v];
    centroid /= Real(ring.size());
    radius = 0;
    fanNormalY = std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec3& a = m.mesh.vertices[ring[k]];
      const Vec3& b = m.mesh.vertices[ring[(k + 1) % ring.size()]];
      EXPECT_NEAR(a.y(), 0, 1e-6);
      radius += (a - centroid).norm() / double(ring.size());
      fanNormalY = std::min(fanNormalY, double((a - centroid).cross(b - centroid).y()));
    }
    return centroid;
  };
  double mitralRadius = 0;
  double aorticRadius = 0;
  double mitralNy = 0;
  double aorticNy = 0;
  const Vec3 mitral = ringInfo(m.mitralRing, mitralRadius, mitralNy);
  const Vec3 aortic = ringInfo(m.aorticRing, aorticRadius, aorticNy);
  for (Index v : m.mitralRing) EXPECT_LT(m.mesh.vertices[v].x(), 0);
  for (Index v : m.aorticRing) EXPECT_GT(m.mesh.vertices[v].x(), 0);
  EXPECT_LT(mitral.x(), 0);
  EXPECT_GT(aortic.x(), 0);
  EXPECT_GT(mitralRadius, aorticRadius);
  EXPECT_NEAR(mitralRadius, m.params.mitralRadius, 0.03 * m.params.mitralRadius);
  EXPECT_GT(mitralNy, 0);  // every fan triangle faces +y
  EXPECT_GT(aorticNy, 0);
}

TEST(LvModel, PinnedVerticesAreTheVesselTops) {
  const LvModel& m = defaultModel();
  const LvGeometryParams& p = m.params;
  ASSERT_FALSE(m.pinned.empty());
  EXPECT_TRUE(std::is_sorted(m.pinned.begin(), m.pinned.end()));
  std::size_t inflow = 0;
  Vec3 inflowCentroid = Vec3::Zero();
  Vec3 outflowCentroid = Vec3::Zero();
  for (Index v : m.pinned) {
    const Vec3& x = m.mesh.vertices[v];
    if (m.region[v] == Region::InflowVessel) {
      ++inflow;
      inflowCentroid += x;
      EXPECT_NEAR(x.y(), p.baseThickness + p.inflowVesselLength, 1e-5);
    } else {
      EXPECT_EQ(m.region[v], Region::OutflowVessel);
      outflowCentroid += x;
      EXPECT_NEAR(x.y(), p.baseThickness + p.outflowVesselLength, 1e-5);
    }
    // Both layers of the far ring: the pair partner is pinned too.
    EXPECT_TRUE(std::binary_search(m.pinned.begin(), m.pinned.end(), v ^ 1u));
  }
  ASSERT_GT(inflow, 0u);
  ASSERT_LT(inflow, m.pinned.size());
  EXPECT_LT(inflowCentroid.x(), 0);
  EXPECT_GT(outflowCentroid.x(), 0);
  // Nothing is higher than the pinned rings.
  for (const Vec3& x : m.mesh.vertices) EXPECT_LE(x.y(), p.baseThickness + p.inflowVesselLength + 1e-5);
}

TEST(LvModel, RegionsCentreAndLongAxis) {
  const LvModel& m = defaultModel();
  const LvGeometryParams& p = m.params;
  EXPECT_NEAR(m.longAxisLength, p.endoLongAxis + p.wallThickness, 1e-6);
  EXPECT_NEAR(m.centre.x(), 0, 0.02);
  EXPECT_NEAR(m.centre.z(), 0, 0.02);
  EXPECT_LT(m.centre.y(), 0);
  EXPECT_GT(m.centre.y(), -p.endoLongAxis);
  Real minY = 0;
  for (std::size_t v = 0; v < m.mesh.vertices.size(); ++v) {
    const Vec3& x = m.mesh.vertices[v];
    minY = std::min(minY, x.y());
    if (m.region[v] == Region::BasePlate) {
      EXPECT_GE(x.y(), -1e-6);
      EXPECT_LE(x.y(), p.baseThickness + 1e-6);
    }
    if (m.region[v] == Region::Myocardium) {
      EXPECT_LE(x.y(), p.baseThickness + 1e-6);
    }
  }
  EXPECT_NEAR(minY, -m.longAxisLength, 1e-5);  // the epicardial apex
}

TEST(LvModel, ResolutionScalesElementCount) {
  LvGeometryParams p;
  p.resolution = 2;
  const LvModel fine = buildLvModel(p);
  const double ratio = double(fine.mesh.tets.size()) / double(defaultModel().mesh.tets.size());
  const pbd::MeshQuality q = pbd::measureQuality(fine.mesh);
  std::printf(
      "LV model (resolution 2): %zu vertices, %zu surface faces, %zu tets (x%.2f); dihedral %.2f..%.2f "
      "deg, aspect max %.2f\n",
      fine.mesh.vertices.size(), fine.surface.size(), fine.mesh.tets.size(), ratio, double(q.minDihedralDeg),
      double(q.maxDihedralDeg), double(q.maxAspectRatio));
  EXPECT_GT(ratio, 3.2);
  EXPECT_LT(ratio, 4.8);
  EXPECT_EQ(q.invertedTets, 0u);
  EXPECT_TRUE(pbd::checkSurface(fine.surface).closed);
  const double analytic = 2.0 / 3.0 * std::numbers::pi * p.endoRadius * p.endoRadius * p.endoLongAxis;
  EXPECT_NEAR(double(cavityVolume(fine, fine.mesh.vertices)), analytic, 0.01 * analytic);
}

TEST(LvModel, EveryResolutionAndScaleBuildsAValidShell) {
  for (const Real resolution : {Real(0.25), Real(0.5), Real(3)}) {
    LvGeometryParams p;
    p.resolution = resolution;
    const LvModel m = buildLvModel(p);
    EXPECT_EQ(pbd::measureQuality(m.mesh).invertedTets, 0u) << "resolution " << resolution;
    const pbd::SurfaceCheck check = pbd::checkSurface(m.surface);
    EXPECT_TRUE(check.closed && check.consistentlyOriented) << "resolution " << resolution;
  }
  // (Resolution 8, ~211k tets, is left to the build of the apps: the O(n^2) plate Delaunay
  // takes minutes under sanitizers.)
  // A human-sized ventricle (all lengths x 0.03) keeps the mesh of the default model.
  LvGeometryParams small;
  const Real k = Real(0.03);
  for (Real* x : {&small.endoRadius, &small.endoLongAxis, &small.wallThickness, &small.baseThickness,
                  &small.mitralRadius, &small.aorticRadius, &small.vesselWallThickness,
                  &small.inflowVesselLength, &small.outflowVesselLength}) {
    *x *= k;
  }
  const LvModel m = buildLvModel(small);
  EXPECT_EQ(m.mesh.tets.size(), defaultModel().mesh.tets.size());
  EXPECT_EQ(pbd::measureQuality(m.mesh).invertedTets, 0u);
  const double v0 = cavityVolume(defaultModel(), defaultModel().mesh.vertices);
  EXPECT_NEAR(double(cavityVolume(m, m.mesh.vertices)), v0 * k * k * k, 1e-3 * v0 * k * k * k);
}

TEST(LvModel, BuildIsDeterministic) {
  const LvModel a = buildLvModel(LvGeometryParams{});
  const LvModel& b = defaultModel();
  ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
  // Bitwise reproducibility is the point here, so exact comparison is intended.
  for (std::size_t v = 0; v < a.mesh.vertices.size(); ++v) {
    ASSERT_TRUE((a.mesh.vertices[v].array() == b.mesh.vertices[v].array()).all()) << "vertex " << v;
  }
  EXPECT_EQ(a.mesh.tets, b.mesh.tets);
  EXPECT_EQ(a.surface, b.surface);
  EXPECT_EQ(a.segment, b.segment);
  EXPECT_EQ(a.region, b.region);
  EXPECT_EQ(a.pinned, b.pinned);
  EXPECT_EQ(a.cavitySurface, b.cavitySurface);
  EXPECT_EQ(a.mitralRing, b.mitralRing);
  EXPECT_EQ(a.aorticRing, b.aorticRing);
}

// The least wall, plate, vessel lengths and aortic orifice the checks let through (shares of
// endo_radius, 2 m) are meshed without a flat tet at the coarsest and the thesis's resolution.
TEST(LvModel, TheThinnestPartsTheChecksAcceptAreMeshed) {
  for (const float resolution : {0.25f, 1.0f}) {
    LvGeometryParams p;
    p.resolution = resolution;
    p.wallThickness = 0.2f;
    p.baseThickness = 0.1f;
    p.inflowVesselLength = p.outflowVesselLength = 0.4f;
    p.aorticRadius = 0.2f;
    EXPECT_NO_THROW(buildLvModel(p)) << "resolution " << resolution;
  }
}

TEST(LvModel, BadParametersThrowNamingTheKey) {
  struct Case {
    std::string key;
    std::function<void(LvGeometryParams&)> edit;
  };
  const std::vector<Case> cases = {
      {"model.endo_radius", [](LvGeometryParams& p) { p.endoRadius = -1; }},
      {"model.endo_long_axis", [](LvGeometryParams& p) { p.endoLongAxis = 0; }},
      {"model.wall_thickness",
       [](LvGeometryParams& p) { p.wallThickness = std::numeric_limits<Real>::quiet_NaN(); }},
      {"model.base_thickness",
       [](LvGeometryParams& p) { p.baseThickness = std::numeric_limits<Real>::infinity(); }},
      {"model.base_thickness", [](LvGeometryParams& p) { p.baseThickness = 5.0f; }},
      {"model.vessel_wall_thickness", [](LvGeometryParams& p) { p.vesselWallThickness = 0; }},
      {"model.inflow_vessel_length", [](LvGeometryParams& p) { p.inflowVesselLength = -0.1f; }},
      {"model.outflow_vessel_length", [](LvGeometryParams& p) { p.outflowVesselLength = 0; }},
      {"model.aortic_radius", [](LvGeometryParams& p) { p.aorticRadius = 0; }},
      {"model.mitral_radius", [](LvGeometryParams& p) { p.mitralRadius = 0.2f; }},
      {"model.mitral_radius", [](LvGeometryParams& p) { p.mitralRadius = 1.5f; }},  // does not fit
      {"model.resolution", [](LvGeometryParams& p) { p.resolution = 0.1f; }},
      {"model.resolution", [](LvGeometryParams& p) { p.resolution = 9; }},
      // A needle: refused before meshing (it would take a minute), see LvModel.NeedleIsRefusedAtOnce.
      {"model.endo_long_axis", [](LvGeometryParams& p) { p.endoLongAxis = 1e6f; }},
      {"model.inflow_vessel_length", [](LvGeometryParams& p) { p.inflowVesselLength = 41; }},
      {"model.outflow_vessel_length", [](LvGeometryParams& p) { p.outflowVesselLength = 1e6f; }},
      {"model.wall_thickness", [](LvGeometryParams& p) { p.wallThickness = 41; }},
      // Thinner than a mesh holds without flat tets, in shares of endo_radius (2 m here).
      {"model.wall_thickness", [](LvGeometryParams& p) { p.wallThickness = 0.19f; }},          // < 0.1
      {"model.base_thickness", [](LvGeometryParams& p) { p.baseThickness = 0.09f; }},          // < 0.05
      {"model.vessel_wall_thickness", [](LvGeometryParams& p) { p.vesselWallThickness = 0.001f; }},  // < 0.001
      {"model.outflow_vessel_length", [](LvGeometryParams& p) { p.outflowVesselLength = 0.39f; }},   // < 0.2
      {"model.aortic_radius", [](LvGeometryParams& p) { p.aorticRadius = 0.19f; }},            // < 0.1
      {"model.endo_long_axis", [](LvGeometryParams& p) { p.endoLongAxis = 1.9f; }},           // < 1
  };
  for (const Case& c : cases) {
    LvGeometryParams p;
    c.edit(p);
    try {
      buildLvModel(p);
      ADD_FAILURE() << "no exception for " << c.key;
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(c.key + ":", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  LvGeometryParams p;
  p.mitralRadius = 0.2f;
  try {
    buildLvModel(p);
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "model.mitral_radius: must be larger than model.aortic_radius (0.55 m), got 0.2");
  }
}

// Geometry that cannot be meshed in reasonable time is refused at once, in the validation
// before any meshing (the needle used to mesh for 61 s).
TEST(LvModel, NeedleIsRefusedAtOnce) {
  LvGeometryParams p;
  p.endoLongAxis = 1e6f;
  const auto start = std::chrono::steady_clock::now();
  try {
    buildLvModel(p);
    ADD_FAILURE() << "a needle 1e6 m long was meshed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("at most 20 x model.endo_radius (40 m)"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

// Orifices that leave slivers of plate between them (a gap of 6.6 mm on a 2 m plate) would
// mesh the plate at the gap's size: about 330,000 points, an hour's Delaunay. Refused before
// meshing, naming the keys that widen the gaps; the finest resolution of the default sizes is
// still built.
TEST(LvModel, ABasePlateOfSliversIsRefusedAtOnce) {
  LvGeometryParams p;
  p.mitralRadius = 1.05f;
  p.aorticRadius = 0.9401f;
  p.vesselWallThickness = 0.002f;
  try {
    buildLvModel(p);
    ADD_FAILURE() << "a plate of slivers was meshed";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("model.mitral_radius: the base plate's gaps"), std::string::npos) << m;
    EXPECT_NE(m.find("more than 25000"), std::string::npos) << m;
    EXPECT_NE(m.find("model.aortic_radius"), std::string::npos) << m;
  }
  LvGeometryParams finest;
  finest.resolution = 8;
  EXPECT_NO_THROW(buildLvModel(finest));
}

}  // namespace
}  // namespace hs::cardiac
