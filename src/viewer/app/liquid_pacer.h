#pragma once
// Keeps the viewer at 25 frames a second with the liquid look. On a software renderer
// (llvmpipe under Xvfb) the liquid's four passes cost about as much as the rest of the frame
// together, and their cost grows with the pixels they cover; drawing the liquid's images at
// half (then a third of) the window's resolution cuts it by 4 (9) with little visible loss,
// because the filter smooths over several pixels anyway. The pacer watches the frame times and
// lowers the liquid's resolution, never raising it again (no back and forth); what it chose
// and why is said in words (the status corner, the scripted run's last line).
#include <string>
#include <vector>

namespace hs::viewer {

class LiquidPacer {
 public:
  static constexpr double kTargetMs = 40;  // 25 fps
  static constexpr int kSkipFrames = 10;   // start-up frames (shader compilation) not judged
  static constexpr int kWindow = 20;       // frames judged at once, by their median
  static constexpr int kCoarsest = 3;

  // One frame drawn in `ms` milliseconds; liquid: whether it drew the liquid look.
  void observe(double ms, bool liquid);
  // The liquid's images at 1 / downsample() of the window's resolution.
  [[nodiscard]] int downsample() const { return m_downsample; }
  // "liquid look: full resolution; now 31 ms" or "liquid look: 1/2 resolution for 25 fps (52 ms
  // a frame at full); now 33 ms"; "" before any judgement.
  [[nodiscard]] const std::string& note() const { return m_note; }

 private:
  int m_downsample = 1;
  int m_seen = 0;
  std::vector<double> m_window;
  std::string m_note;
  std::string m_reason;  // why the resolution was lowered, kept for the note
};

}  // namespace hs::viewer
