#pragma once
// The AHA 17-segment bull's-eye (Cerqueira et al. 2002, Circulation 105:539) as geometry: the
// polar map the viewer's panel draws and clicks. Pure maths (no ImGui), unit-tested.
//
// Diagram coordinates: centre (0, 0), outer radius 1, x to the right, y UP. The standard
// layout: the apex (17) in the middle, then the apical ring (13-16), the mid ring (7-12) and the
// basal ring (1-6) outermost; anterior at the top, septum on the left, inferior at the bottom,
// lateral on the right. Basal and mid sectors are 60 degrees wide, centred on the top for
// anterior (1, 7) and following counter-clockwise: anteroseptal, inferoseptal, inferior,
// inferolateral, anterolateral; so the 2/3 and 5/6 borders are horizontal. Apical sectors are
// 90 degrees wide, centred on top (13 anterior), left (14 septal), bottom (15 inferior) and
// right (16 lateral).
//
// It is cardiac::ahaSegment's classification drawn flat: a model angle a (0 anterior, 90
// septal, cardiac::ahaAngleDeg) lands at the diagram angle 90 + a (counter-clockwise from the
// right), and depth from the base runs from the rim inward.
#include <string>

namespace hs::viewer {

// Ring boundaries as a share of the outer radius: apex disc, apical, mid, basal rings.
inline constexpr float kBullseyeApexRadius = 0.25f;
inline constexpr float kBullseyeApicalRadius = 0.5f;
inline constexpr float kBullseyeMidRadius = 0.75f;

// One segment's patch: the ring [innerRadius, outerRadius] between the diagram angles
// [startDeg, endDeg] (counter-clockwise from +x; endDeg > startDeg, may exceed 360). The apex
// is the full disc: inner 0, 0..360.
struct BullseyeSector {
  float innerRadius = 0, outerRadius = 1;
  float startDeg = 0, endDeg = 360;
};

BullseyeSector bullseyeSector(int segment);  // segment 1..17

// The segment (1..17) under the point (x, y) of the diagram, 0 outside the disc of radius 1.
int bullseyeSegmentAt(float x, float y);

// Where to write a segment's number: the middle of its patch.
void bullseyeLabelPosition(int segment, float& x, float& y);

// "7 mid anterior", "17 apex"; "" for a number outside 1..17.
std::string ahaSegmentName(int segment);

}  // namespace hs::viewer
