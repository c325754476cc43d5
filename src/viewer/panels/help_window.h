#pragma once
// The student's help window (H, F1, or the Help button): what each number means and its
// normal range in an adult at rest, what the colours mean, what each control changes and what
// it cannot change, and the mouse and keys. Needs an ImGui frame in progress.

namespace hs::viewer {

// Its pages: the numbers, the colours, the controls, the mouse and keys.
inline constexpr int kHelpPageCount = 4;
// `page` (0 to kHelpPageCount - 1) is the page shown; the page buttons change it.
void drawHelpWindow(bool& open, int& page, int windowWidth, int windowHeight);

}  // namespace hs::viewer
