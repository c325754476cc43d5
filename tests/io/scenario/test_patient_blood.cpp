// Blood in a patient's heart (issue 16, items 2 and 5): the vessels raised on its annuli, the
// flow path that knows its cavity, the sites the blood starts on, and the keys that shape them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "cardiac/heart_simulation.h"
#include "cardiac/heart_sites.h"
#include "cardiac/patient/patient_vessels.h"
#include "io/scenario/scenario_file.h"
#include "pbd/core/tet_geometry.h"
#include "recorded_beat_frames.h"
#include "thrown_message.h"

namespace hs::io {
namespace {

using cardiac::FlowRegion;
using cardiac::LvModel;
using cardiac::Region;
using pbd::Index;
using pbd::Real;
using pbd::Vec3;

bool insideSomeTet(const LvModel& m, const Vec3& p) {
  for (const pbd::Tet& t : m.mesh.tets) {
    const pbd::TetPoints x{m.mesh.vertices[t[0]], m.mesh.vertices[t[1]], m.mesh.vertices[t[2]], m.mesh.vertices[t[3]]};
    if (pbd::isPointInTet(x, p)) return true;
  }
  return false;
}

class PatientBlood : public ::testing::TestWithParam<std::string> {};

TEST_P(PatientBlood, VesselsRiseFromTheAnnuliToPinnedCircularEnds) {
  const cardiac::Scenario s = loadScenario(GetParam());
  ASSERT_TRUE(s.blood.enabled);
  const cardiac::HeartSimulation sim(s, 1);
  const LvModel& m = sim.model();
  const cardiac::FlowPath& path = m.flowPath;
  ASSERT_TRUE(path.cavity);
  EXPECT_EQ(m.mesh.vertices.size() % 2, 0u);
  EXPECT_EQ(m.region.size(), m.mesh.vertices.size());
  const std::set<Index> pinned(m.pinned.begin(), m.pinned.end());
  for (const auto& [ring, orifice, top, region] :
       {std::tuple{&m.mitralRing, &path.mitral, path.inflowTop, Region::InflowVessel},
        std::tuple{&m.aorticRing, &path.aortic, path.outflowTop, Region::OutflowVessel}}) {
    // The vessel's tets hold every ring vertex: the vessel is joined to the wall, not beside it.
    std::set<Index> joined;
    for (const pbd::Tet& t : m.mesh.tets) {
      // region copied into the lambda: clang 14 (the asan-ci preset) cannot capture a structured binding.
      const bool vessel = std::any_of(t.begin(), t.end(), [&, region = region](Index v) { return m.region[v] == region; });
      if (vessel) joined.insert(t.begin(), t.end());
    }
    for (Index v : *ring) EXPECT_TRUE(joined.count(v)) << "ring vertex " << v;
    // The far end: a circle of the orifice's radius about the axis, at the top, pinned.
    int far = 0;
    for (std::size_t v = 0; v < m.mesh.vertices.size(); v += 2) {
      if (m.region[v] != region || std::abs(m.mesh.vertices[v].y() - top) > Real(1e-5)) continue;
      EXPECT_NEAR(orifice->radial(m.mesh.vertices[v]), orifice->radius, 1e-5);
      EXPECT_TRUE(pinned.count(Index(v)) && pinned.count(Index(v + 1)));
      ++far;
    }
    EXPECT_EQ(far, int(ring->size()));
    EXPECT_GE(top - orifice->centre.y(), Real(0.03) - Real(1e-6));  // the scenario's 3 cm
  }
  for (const pbd::Tet& t : m.mesh.tets) {
    const auto& x = m.mesh.vertices;
    ASSERT_GT(pbd::signedTetVolume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]), 0);
  }
  // Each valve lies in its ring's plane: every ring vertex within 3 mm of the disc's plane (the
  // rings are nearly planar), inside its disc, which reaches the farthest one (or the lumen).
  for (const auto& [ring, valve, lumen] : {std::tuple{&m.mitralRing, &path.mitralValve(), &path.mitral},
                                           std::tuple{&m.aorticRing, &path.aorticValve(), &path.aortic}}) {
    Real farthest = 0;
    for (Index v : *ring) {
      EXPECT_LT(std::abs(valve->side(m.mesh.vertices[v])), Real(0.003));
      farthest = std::max(farthest, valve->radial(m.mesh.vertices[v]));
    }
    EXPECT_FLOAT_EQ(valve->radius, std::max(farthest, lumen->radius));
    EXPECT_NEAR(valve->forward.norm(), 1, 1e-5);
  }
  EXPECT_LT(path.mitralValve().forward.y(), 0);  // into the cavity
  EXPECT_GT(path.aorticValve().forward.y(), 0);  // out of it
  // Both lumens larger for the inflow, as the thesis's expert asks.
  EXPECT_GT(path.mitral.radius, path.aortic.radius);
}

TEST_P(PatientBlood, TheBloodStartsInTheLumenAtARadiusFromTheWall) {
  const cardiac::Scenario s = loadScenario(GetParam());
  const cardiac::HeartSimulation sim(s, 1);
  const LvModel& m = sim.model();
  const std::vector<Vec3> sites = cardiac::heartSites(s, m);
  ASSERT_GT(sites.size(), 2500u);
  std::size_t inVessels = 0;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const Vec3& p = sites[k];
    if (k % 7 == 0) {  // a seventh, by brute force
      EXPECT_FALSE(insideSomeTet(m, p)) << p.transpose();
    }
    const FlowRegion r = m.flowPath.classify(p, s.blood.radius, s.blood.spacing);
    EXPECT_NE(r, FlowRegion::Outside) << p.transpose();
    inVessels += r == FlowRegion::InflowVessel || r == FlowRegion::OutflowVessel;
  }
  EXPECT_GT(inVessels, 150u);
  // A spacing apart at least: no two sites on top of each other.
  std::vector<Vec3> sorted = sites;
  std::sort(sorted.begin(), sorted.end(), [](const Vec3& a, const Vec3& b) { return a.y() < b.y(); });
  for (std::size_t i = 0; i < sorted.size(); ++i)
    for (std::size_t j = i + 1; j < sorted.size() && sorted[j].y() - sorted[i].y() < s.blood.radius; ++j)
      ASSERT_GT((sorted[j] - sorted[i]).norm(), s.blood.radius) << sorted[i].transpose();
}

TEST_P(PatientBlood, TheCavityTestSeesTheVentricleAndNotTheRoomAroundIt) {
  const cardiac::Scenario s = loadScenario(GetParam());
  const cardiac::HeartSimulation sim(s, 1);
  const LvModel& m = sim.model();
  const cardiac::FlowPath& path = m.flowPath;
  // Halfway from the mitral orifice to the endocardial apex: the ventricle. Beside the heart,
  // beyond the apex and above the vessels' ends: outside.
  Vec3 apex = m.mesh.vertices[0];
  for (std::size_t v = 0; v < m.mesh.vertices.size(); v += 2)
    if (m.region[v] == Region::Myocardium && m.mesh.vertices[v].y() < apex.y()) apex = m.mesh.vertices[v];
  const Vec3 middle = Real(0.5) * (path.mitral.centre + apex);
  EXPECT_EQ(path.classify(middle, 0, 0), FlowRegion::Ventricle);
  EXPECT_EQ(path.classify(apex - Vec3(0, Real(0.02), 0), 0, 0), FlowRegion::Outside);
  EXPECT_EQ(path.classify(middle + Vec3(Real(0.2), 0, 0), 0, 0), FlowRegion::Outside);
  EXPECT_EQ(path.classify(path.mitral.centre + Vec3(0, Real(0.01), 0), 0, 0), FlowRegion::InflowVessel);
  EXPECT_EQ(path.classify(path.aortic.centre + Vec3(0, Real(0.01), 0), 0, 0), FlowRegion::OutflowVessel);
  Vec3 aboveTheEnd = path.aortic.centre;
  aboveTheEnd.y() = path.outflowTop + Real(0.05);
  EXPECT_EQ(path.classify(aboveTheEnd, 0, 0), FlowRegion::Outside);
}

INSTANTIATE_TEST_SUITE_P(BuiltIn, PatientBlood, ::testing::Values("patient-biv-me", "idealized-lv"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param == "idealized-lv" ? "IdealizedLv" : "PatientBivme"; });

// A recorded beat (recorded_beat.h) carries the vessels on its annuli as the procedural heart
// carries its own: each vessel vertex by its share of its ring vertex's displacement, 1 at the
// ring, 0 at the pinned far end: no vessel vertex is left to the constraints.
TEST(PatientBloodVessels, ARecordedBeatCarriesTheVesselsByTheirRings) {
  cardiac::Scenario s = loadScenario("patient-biv-me");
  s.motion.frames = "frame_{frame:03d}.obj";
  s.motion.count = 25;
  s.motion.period = Real(0.8);
  s.motion.frameSurfaces = hs::testing::scaledFrames(s.patient.endocardiumSurface, 25, 0.3, 0.36);
  cardiac::HeartSimulation sim(s, 1);
  const LvModel& m = sim.model();
  ASSERT_FALSE(m.vesselFollowers.empty());
  for (std::size_t v = 0; v < m.mesh.vertices.size(); ++v) {
    if (m.region[v] == Region::Myocardium) continue;
    ASSERT_EQ(sim.particles().inverseMass[v], 0) << "vessel vertex " << v << " is left to the constraints";
  }
  for (int k = 0; k < 200; ++k) sim.step();  // 0.2 s, late systole: the annuli have moved
  const std::vector<Vec3>& x = sim.particles().position;
  const std::vector<Vec3>& rest = m.mesh.vertices;
  Real ringTravel = 0;
  for (const cardiac::VesselFollower& f : m.vesselFollowers) {
    EXPECT_GT(f.share, 0);
    EXPECT_LT(f.share, 1);
    ringTravel = std::max(ringTravel, (x[f.root] - rest[f.root]).norm());
    const Vec3 expected = rest[f.vertex] + f.share * (x[f.root] - rest[f.root]);
    EXPECT_LT((x[f.vertex] - expected).norm(), Real(1e-6)) << "vessel vertex " << f.vertex;
  }
  EXPECT_GT(ringTravel, Real(0.001));  // the annuli moved by more than a millimetre
  for (Index v : m.pinned) EXPECT_EQ(x[v], rest[v]) << "pinned vertex " << v;
  EXPECT_EQ(sim.tissueStats().invertedTets, 0u);
}

TEST(PatientBloodVessels, AnnuliTooCloseForTwoVesselsAreRefusedWithTheirDistance) {
  const cardiac::Scenario s = loadScenario("idealized-lv", {"blood.enabled=false"});
  const cardiac::HeartSimulation sim(s, 1);
  LvModel m = sim.model();  // without vessels
  m.flowPath.aortic.centre = m.flowPath.mitral.centre + Vec3(Real(0.01), 0, 0);
  const std::string message =
      hs::testing::thrownMessage<std::invalid_argument>([&] { cardiac::attachPatientVessels(m, {}); });
  EXPECT_NE(message.find("would overlap"), std::string::npos) << message;
  EXPECT_NE(message.find("10 mm apart"), std::string::npos) << message;
}

TEST(PatientBloodKeys, OnlyTheHeartStartAndVesselsOfARealSizeAreTaken) {
  auto error = [](const std::vector<std::string>& set) {
    return hs::testing::thrownMessage<ScenarioError>([&] { loadScenario("patient-biv-me", set); });
  };
  const std::string start = error({"blood.start=vessel"});
  EXPECT_NE(start.find("blood.start"), std::string::npos) << start;
  EXPECT_NE(start.find("\"vessel\""), std::string::npos) << start;
  const std::string length = error({"model.inflow_vessel_length=2"});
  EXPECT_NE(length.find("model.inflow_vessel_length: must be within [0.01, 0.1] m"), std::string::npos) << length;
  const std::string wall = error({"model.vessel_wall_thickness=0.0001"});
  EXPECT_NE(wall.find("model.vessel_wall_thickness"), std::string::npos) << wall;
  for (const std::string& m : {start, length, wall}) EXPECT_EQ(std::count(m.begin(), m.end(), '\n'), 0) << m;
}

}  // namespace
}  // namespace hs::io
