// The bull's-eye's hit test: known points of every segment land in that segment (standard AHA
// layout: anterior at the top, septum on the left), points outside the disc in none, the
// labels sit inside their own patch, and the diagram agrees with the model's classification
// (cardiac::ahaSegment) all around.
#include <gtest/gtest.h>

#include <cmath>

#include "cardiac/anatomy/aha_segments.h"
#include "viewer/region/aha_bullseye.h"

namespace hs::viewer {
namespace {

// A point at radius r and angle a (degrees counter-clockwise from the right, y up).
struct Polar {
  float r, a;
};

float px(Polar p) { return p.r * std::cos(p.a * float(M_PI) / 180); }
float py(Polar p) { return p.r * std::sin(p.a * float(M_PI) / 180); }

TEST(AhaBullseye, KnownPointsOfEverySegment) {
  // Basal ring (r 0.75..1): 1 top, then counter-clockwise 2 upper left, 3 lower left, 4 bottom,
  // 5 lower right, 6 upper right; the 2/3 and 5/6 borders are horizontal.
  const struct {
    Polar p;
    int segment;
  } kCases[] = {
      {{0.9f, 90}, 1},
      {{0.9f, 65}, 1},
      {{0.9f, 115}, 1},
      {{0.9f, 150}, 2},
      {{0.9f, 175}, 2},
      {{0.9f, 185}, 3},
      {{0.9f, 210}, 3},
      {{0.9f, 270}, 4},
      {{0.9f, 330}, 5},
      {{0.9f, 355}, 5},
      {{0.9f, 5}, 6},
      {{0.9f, 30}, 6},
      {{0.99f, 90}, 1},
      // Mid ring (r 0.5..0.75), same sectors.
      {{0.6f, 90}, 7},
      {{0.6f, 150}, 8},
      {{0.6f, 210}, 9},
      {{0.6f, 270}, 10},
      {{0.6f, 330}, 11},
      {{0.6f, 30}, 12},
      {{0.74f, 100}, 7},
      // Apical ring (r 0.25..0.5): 13 top, 14 left (septal), 15 bottom, 16 right (lateral).
      {{0.4f, 90}, 13},
      {{0.4f, 130}, 13},
      {{0.4f, 140}, 14},
      {{0.4f, 180}, 14},
      {{0.4f, 270}, 15},
      {{0.4f, 0}, 16},
      {{0.4f, 50}, 13},
      {{0.4f, 40}, 16},
      {{0.26f, 200}, 14},
      // Apex disc.
      {{0.0f, 0}, 17},
      {{0.2f, 45}, 17},
      {{0.24f, 300}, 17},
  };
  for (const auto& c : kCases) {
    SCOPED_TRACE("r = " + std::to_string(c.p.r) + ", angle = " + std::to_string(c.p.a));
    EXPECT_EQ(bullseyeSegmentAt(px(c.p), py(c.p)), c.segment);
  }
  // The septum is on the left: a point left of the centre in the basal ring is septal (2, 3).
  EXPECT_EQ(bullseyeSegmentAt(-0.9f, 0.05f), 2);
  EXPECT_EQ(bullseyeSegmentAt(-0.9f, -0.05f), 3);
  EXPECT_EQ(bullseyeSegmentAt(0, 0.9f), 1);   // anterior at the top
  EXPECT_EQ(bullseyeSegmentAt(0, -0.9f), 4);  // inferior at the bottom
}

TEST(AhaBullseye, OutsideTheDiscIsNoSegment) {
  EXPECT_EQ(bullseyeSegmentAt(1.01f, 0), 0);
  EXPECT_EQ(bullseyeSegmentAt(0.8f, 0.8f), 0);
  EXPECT_EQ(bullseyeSegmentAt(0, -3), 0);
  EXPECT_EQ(bullseyeSegmentAt(NAN, 0), 0);
}

TEST(AhaBullseye, EachLabelAndSectorCentreLiesInItsOwnSegment) {
  for (int s = 1; s <= 17; ++s) {
    float x = 0, y = 0;
    bullseyeLabelPosition(s, x, y);
    EXPECT_EQ(bullseyeSegmentAt(x, y), s) << "label of segment " << s;
    const BullseyeSector sector = bullseyeSector(s);
    EXPECT_LT(sector.innerRadius, sector.outerRadius);
    EXPECT_LT(sector.startDeg, sector.endDeg);
    // Just inside each corner of the patch.
    for (const float fr : {0.05f, 0.95f})
      for (const float fa : {0.05f, 0.95f}) {
        const Polar p{sector.innerRadius + fr * (sector.outerRadius - sector.innerRadius),
                      sector.startDeg + fa * (sector.endDeg - sector.startDeg)};
        EXPECT_EQ(bullseyeSegmentAt(px(p), py(p)), s) << "corner of segment " << s;
      }
  }
}

TEST(AhaBullseye, SegmentNamesFollowTheAhaNomenclature) {
  EXPECT_EQ(ahaSegmentName(1), "1 basal anterior");
  EXPECT_EQ(ahaSegmentName(3), "3 basal inferoseptal");
  EXPECT_EQ(ahaSegmentName(6), "6 basal anterolateral");
  EXPECT_EQ(ahaSegmentName(7), "7 mid anterior");
  EXPECT_EQ(ahaSegmentName(11), "11 mid inferolateral");
  EXPECT_EQ(ahaSegmentName(13), "13 apical anterior");
  EXPECT_EQ(ahaSegmentName(14), "14 apical septal");
  EXPECT_EQ(ahaSegmentName(16), "16 apical lateral");
  EXPECT_EQ(ahaSegmentName(17), "17 apex");
  EXPECT_EQ(ahaSegmentName(0), "");
  EXPECT_EQ(ahaSegmentName(18), "");
}

// The diagram is the model's classification drawn flat: model angle a (0 anterior, 90 septal)
// at diagram angle 90 + a, depth from the base from the rim inward.
TEST(AhaBullseye, AgreesWithTheModelsClassificationAllAround) {
  constexpr double kCavity = 4.0;  // base plane to endocardial apex (m)
  const struct {
    double depth;  // share of the cavity length below the base plane
    float r;       // the diagram radius of that depth band's middle
  } kBands[] = {{1.0 / 6, 0.875f}, {0.5, 0.625f}, {0.78, 0.375f}, {0.95, 0.1f}};
  for (const auto& band : kBands)
    for (int k = 0; k < 52; ++k) {
      const double a = 1.0 + 7.0 * k;  // degrees, never on a border
      const double rad = a * M_PI / 180;
      // ahaAngleDeg is atan2(p . kSeptal, p . kAnterior): cos a kAnterior + sin a kSeptal gives a.
      Eigen::Vector3d p = std::cos(rad) * cardiac::kAnterior + std::sin(rad) * cardiac::kSeptal;
      p.y() = -band.depth * kCavity;
      ASSERT_NEAR(cardiac::ahaAngleDeg(p), a, 1e-9);
      const Polar q{band.r, float(90 + a)};
      EXPECT_EQ(bullseyeSegmentAt(px(q), py(q)), int(cardiac::ahaSegment(p, kCavity)))
          << "model angle " << a << ", depth " << band.depth;
    }
}

}  // namespace
}  // namespace hs::viewer
