#pragma once
// The panel's "Beating region" section: the AHA bull's-eye to tick segments, the brush
// controls, and Apply / Clear / All myocardium. Like the rest of the panel (ui_panel.h) it only
// reads a RegionStatus and writes requests into RegionControls; RegionEditor acts on them.
// Needs an ImGui frame in progress.
#include <array>
#include <cstddef>

#include "viewer/region/beating_selection.h"

namespace hs::viewer {

struct RegionControls {
  bool paintMode = false;    // left drag on the heart paints instead of orbiting (key B)
  float brushRadiusPx = 24;  // window pixels (keys [ and ])
  bool showRegion = false;   // tint the chosen region on the heart
  static constexpr float kMinBrushPx = 4, kMaxBrushPx = 150;

  // One-frame requests, cleared by RegionEditor.
  int segmentToggled = 0;  // 1..17: the bull's-eye was clicked there
  bool clearRequested = false, allRequested = false, revertRequested = false;
  bool applyRequested = false;  // restart the cycle with the selection (Enter)
};

struct RegionStatus {
  std::array<SegmentState, 18> segments{};  // [1..17]
  std::array<bool, 18> outOfStep{};         // [1..17]: beats out of step (the inconsistent pattern)
  std::size_t count = 0, selectable = 0;    // chosen and choosable wall vertices
  bool pending = false;                     // the selection differs from the one the simulation runs
  bool cycleEnabled = true;                 // off: nothing beats, whatever is chosen
  double brushWorldRadius = 0;              // m: the brush radius at the distance of the camera's target
};

// Diameter of the bull's-eye in pixels.
inline constexpr float kBullseyeDiameter = 156;

void drawRegionSection(RegionControls& controls, const RegionStatus& status);

// The bull's-eye alone: filled where chosen, a tooltip with the segment's name on hover, a
// click toggles (controls.segmentToggled).
void drawBullseye(RegionControls& controls, const RegionStatus& status, float diameter);
// The brush's outline at the cursor while painting over the scene: orange adds, blue removes
// (Shift). Nothing when not painting or over a panel.
void drawBrushOutline(const RegionControls& controls);

}  // namespace hs::viewer
