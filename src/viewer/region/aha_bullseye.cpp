#include "viewer/region/aha_bullseye.h"

#include <cmath>

namespace hs::viewer {
namespace {

constexpr float kDegrees = 180.0f / float(M_PI);

// Walls in order anterior, anteroseptal, inferoseptal, inferior, inferolateral, anterolateral
// (basal and mid), anterior, septal, inferior, lateral (apical).
constexpr const char* kSixWalls[] = {"anterior", "anteroseptal",  "inferoseptal",
                                     "inferior", "inferolateral", "anterolateral"};
constexpr const char* kFourWalls[] = {"anterior", "septal", "inferior", "lateral"};

}  // namespace

BullseyeSector bullseyeSector(int segment) {
  if (segment == 17) return {0, kBullseyeApexRadius, 0, 360};
  if (segment >= 13 && segment <= 16) {
    // Sector k centred on 90 + 90 k degrees (top, left, bottom, right).
    const float centre = 90.0f + 90.0f * float(segment - 13);
    return {kBullseyeApexRadius, kBullseyeApicalRadius, centre - 45, centre + 45};
  }
  const bool basal = segment <= 6;
  const int k = (basal ? segment - 1 : segment - 7);
  const float centre = 90.0f + 60.0f * float(k);
  return {basal ? kBullseyeMidRadius : kBullseyeApicalRadius, basal ? 1.0f : kBullseyeMidRadius, centre - 30,
          centre + 30};
}

int bullseyeSegmentAt(float x, float y) {
  const float r = std::hypot(x, y);
  if (!(r <= 1.0f)) return 0;  // also rejects NaN
  if (r < kBullseyeApexRadius) return 17;
  // Counter-clockwise from the top: 0 anterior, 90 septal (left), the model's angle.
  float a = std::atan2(y, x) * kDegrees - 90.0f;
  while (a < 0) a += 360.0f;
  while (a >= 360.0f) a -= 360.0f;
  if (r < kBullseyeApicalRadius) return 13 + int(std::fmod(a + 45.0f, 360.0f) / 90.0f) % 4;
  const int sector = int(std::fmod(a + 30.0f, 360.0f) / 60.0f) % 6;
  return (r < kBullseyeMidRadius ? 7 : 1) + sector;
}

void bullseyeLabelPosition(int segment, float& x, float& y) {
  if (segment == 17) {
    x = y = 0;
    return;
  }
  const BullseyeSector s = bullseyeSector(segment);
  const float r = (s.innerRadius + s.outerRadius) / 2, a = (s.startDeg + s.endDeg) / 2 / kDegrees;
  x = r * std::cos(a);
  y = r * std::sin(a);
}

std::string ahaSegmentName(int segment) {
  if (segment < 1 || segment > 17) return "";
  const std::string number = std::to_string(segment) + " ";
  if (segment == 17) return number + "apex";
  if (segment >= 13) return number + "apical " + kFourWalls[segment - 13];
  return number + (segment <= 6 ? "basal " : "mid ") + kSixWalls[(segment - 1) % 6];
}

}  // namespace hs::viewer
