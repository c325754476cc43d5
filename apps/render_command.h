#pragma once
// `heartsim render SCENARIO --times 0,0.08,1,2 --views front,right,left,top --out DIR`: runs
// the scenario headless and draws it offscreen (EGL, no display needed) at the given times from
// the given sides: DIR/t<time>_<view>.png for each, and DIR/contact_sheet.png with one row per
// time and one column per view (docs/rendering.md).
// `heartsim render normal --e-vortex 4 --out DIR`: instead, runs to the E-wave peak of beat 4 and
// draws the filling vortex in the long-axis cut (render/vortex_cut.h) into DIR/e_vortex_beat4.png,
// on the CPU (no GL).
#include <optional>
#include <string>
#include <vector>

namespace hs::app {

struct RenderOptions {
  std::string scenario = "heart-only";
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string resolution;              // --resolution: the blood's level; empty: as written (fine)
  std::string times;                   // "0,0.08,1": seconds; empty: 0 and the duration
  std::string views = "front,left,right,top";
  std::string outDir;                  // empty: results/<scenario name>/render
  std::string size = "800x600";        // WxH pixels of each view
  std::optional<bool> clip;            // cut the wall open at z = clipZ; default: when there is a heart
  double clipZ = 0;                    // m
  double wallOpacity = 1;              // (0, 1]; < 1 draws a see-through wall
  double speedMax = 0;                 // m/s, top of the blood colour scale; 0: from the scenario
  std::string bloodColour = "speed";   // speed, pressure, origin, components or stay
  double pressureMax = 0;              // mmHg, top of the pressure colour scale; 0: from the scenario
  std::string bloodLook = "liquid";    // liquid or spheres
  std::string flow = "off";            // off, streaks or arrows
  std::string labels = "off";          // off or anatomy (render/anatomy_labels.h)
  int threads = 0;                     // 0 = all cores
  std::optional<int> eVortexBeat;      // --e-vortex: the beat whose E-wave vortex is drawn (1 = first)
};

// "0", "0.08", "1.5": seconds with up to 6 decimals and no trailing zeros (file names, labels).
std::string formatTime(double seconds);

int renderCommand(const RenderOptions& options);

}  // namespace hs::app
