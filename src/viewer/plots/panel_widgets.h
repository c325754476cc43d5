#pragma once
// ImGui pieces the viewer's panels share (ui_panel, pump_panel, blood_controls, region_panel):
// hover help for the last item and the fixed, full-height side panels. Need an ImGui frame in
// progress.
#include <string>

namespace hs::viewer {

// Tooltips wrap at this width (px), so that one beside the window's edge fits in the window
// (ImGui moves a tooltip inside the window, but cannot shrink one wider than the room left).
inline constexpr float kTooltipWidth = 320;

// Shows `text` while the mouse is over the last item, wrapped at kTooltipWidth.
void tooltip(const char* text);
void tooltip(const std::string& text);
// A tooltip of `text` now, wrapped at kTooltipWidth (for hover tests of one's own).
void wrappedTooltip(const char* text);

// A window of `width` x the window's height at x = `left`, neither movable nor resizable, its
// items `-90` px wide (room for their labels), headed by `title` and a separator. Close it
// with endSidePanel().
void beginSidePanel(const char* id, const char* title, float left, float width, int windowHeight);
void endSidePanel();

}  // namespace hs::viewer
