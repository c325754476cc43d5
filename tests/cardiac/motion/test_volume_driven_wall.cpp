// The wall driven to the lumped circulation's volume (volume_driven_wall.h) with an akinetic
// region: every myocardium vertex is driven, the infarct's core only descends with the base,
// and its border zone moves in with the beating wall, less with the distance from it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "cardiac/motion/volume_driven_wall.h"
#include "normal_geometry.h"

namespace hs::cardiac {
namespace {

// anterior-infarct's segments (scenarios/anterior-infarct.toml) do not beat.
bool inInfarct(int segment) {
  for (int s : {1, 2, 7, 8, 13, 14, 17})
    if (segment == s) return true;
  return false;
}

TEST(VolumeDrivenWall, AnAkineticRegionOnlyMovesInAtItsBorder) {
  const LvModel model = buildLvModel(testing::normalGeometry());
  const auto& x = model.mesh.vertices;
  std::vector<Index> beating;
  for (std::size_t v = 0; v < x.size(); ++v)
    if (model.region[v] == Region::Myocardium && !inInfarct(model.segment[v])) beating.push_back(Index(v));
  VolumeDrivenWall wall(model, beating, 0);
  std::vector<std::uint8_t> driven(x.size(), 0);
  for (Index v : wall.drivenVertices()) driven[v] = 1;
  // Systole: a cavity a fifth smaller than at rest.
  std::vector<Vec3> predicted = x;
  wall.drive(x, predicted, 0.8 * double(cavityVolume(model, x)));
  ASSERT_GT(wall.contraction(), 0);
  // Radial travel toward the long axis (the y axis), per vertex, against its distance from the
  // nearest beating vertex.
  double coreRadialMax = 0, borderRadialMin = HUGE_VAL, beatingRadialMin = HUGE_VAL;
  int core = 0, border = 0;
  const double zone = 0.25 * double(model.longAxisLength);
  for (std::size_t v = 0; v < x.size(); ++v) {
    if (model.region[v] != Region::Myocardium || x[v].y() > -0.5 * double(model.params.endoLongAxis)) continue;
    EXPECT_TRUE(driven[v]) << "myocardium vertex " << v << " is left to the constraints";
    const double radial = std::hypot(double(x[v].x()), double(x[v].z())) -
                          std::hypot(double(predicted[v].x()), double(predicted[v].z()));
    if (!inInfarct(model.segment[v])) {
      beatingRadialMin = std::min(beatingRadialMin, radial);
      continue;
    }
    double nearest = HUGE_VAL;
    for (Index b : beating) nearest = std::min(nearest, double((x[v] - x[b]).norm()));
    if (nearest >= zone) coreRadialMax = std::max(coreRadialMax, std::abs(radial)), ++core;
    if (nearest < 0.3 * zone) borderRadialMin = std::min(borderRadialMin, radial), ++border;
  }
  ASSERT_GT(core, 0) << "the infarct must have a core beyond the border zone";
  ASSERT_GT(border, 0);
  EXPECT_LT(coreRadialMax, 1e-6) << "the core does not move in";
  EXPECT_GT(borderRadialMin, 0) << "the border zone moves in";
  EXPECT_GT(beatingRadialMin, 0);
}

// Each vessel is stretched between the plate and its own far end: an atrium longer than the
// aortic root must not make the root's top row take the descent the longer vessel spreads over
// its length. Every vessel tet then changes its volume by at most descent / L (the rows' vertical
// stretch, L the vessel's height above the plate).
TEST(VolumeDrivenWall, EachVesselIsStretchedOverItsOwnLength) {
  const LvModel model = buildLvModel(testing::normalGeometry());
  ASSERT_NE(model.params.inflowVesselLength, model.params.outflowVesselLength);
  const auto& x = model.mesh.vertices;
  std::vector<Index> beating;
  for (std::size_t v = 0; v < x.size(); ++v)
    if (model.region[v] == Region::Myocardium) beating.push_back(Index(v));
  VolumeDrivenWall wall(model, beating, 0);
  std::vector<Vec3> predicted = x;
  wall.drive(x, predicted, 0.6 * double(cavityVolume(model, x)));
  const double descent = wall.baseDescent(wall.contraction());
  ASSERT_GT(descent, 0.005);
  const double shorter = double(std::min(model.params.inflowVesselLength, model.params.outflowVesselLength));
  auto volume = [](const std::vector<Vec3>& p, const pbd::Tet& t) {
    return double((p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).dot(p[t[3]] - p[t[0]])) / 6;
  };
  double worst = 0;
  for (const pbd::Tet& t : model.mesh.tets) {
    bool vessel = true;
    for (Index v : t) vessel = vessel && (model.region[v] == Region::InflowVessel || model.region[v] == Region::OutflowVessel);
    if (vessel) worst = std::max(worst, std::abs(volume(predicted, t) / volume(x, t) - 1));
  }
  EXPECT_LT(worst, 1.05 * descent / shorter);
}

}  // namespace
}  // namespace hs::cardiac
