// The flow view's lines (scene.h): streaks from the recorded pathlines, arrows from the
// smoothed velocity, as flat-coloured segments for the renderer.
#include <algorithm>

#include "render/scene.h"

namespace hs::render {

void addStreaks(FlowLines& lines, const PathlineRecorder& pathlines, double speedMax, float width) {
  const float window = float(std::max(pathlines.window(), 1e-9));
  for (const PathlineRecorder::Segment& s : pathlines.segments()) {
    // Tapering from the head (age 0, full width) to a third of it at the window's far end.
    auto taper = [&](float age) { return width * (1 - 2.0f / 3 * std::clamp(age / window, 0.0f, 1.0f)); };
    const float ageFrom = s.age + (s.to - s.from).norm() / std::max(s.speed, 1e-6f);
    lines.from.push_back(s.from);
    lines.to.push_back(s.to);
    lines.colours.push_back(speedColour(double(s.speed) / speedMax));
    lines.widthFrom.push_back(taper(ageFrom));
    lines.widthTo.push_back(taper(s.age));
  }
}

void addArrows(FlowLines& lines, const std::vector<Vec3f>& positions, const std::vector<Vec3f>& velocities,
               double speedMax, float width, int stride) {
  constexpr float kSeconds = 0.01f;  // an arrow is the distance covered in 10 ms
  const float longest = 2 * float(speedMax) * kSeconds;
  auto add = [&](const Vec3f& a, const Vec3f& b, const Vec3f& colour, float w0, float w1) {
    lines.from.push_back(a);
    lines.to.push_back(b);
    lines.colours.push_back(colour);
    lines.widthFrom.push_back(w0);
    lines.widthTo.push_back(w1);
  };
  for (std::size_t i = 0; i < positions.size(); i += std::size_t(std::max(1, stride))) {
    const float speed = velocities[i].norm();
    if (!(speed > 0)) continue;
    const Vec3f direction = velocities[i] / speed;
    const Vec3f shaft = direction * std::min(speed * kSeconds, longest);
    const Vec3f colour = speedColour(double(speed) / speedMax);
    const Vec3f tip = positions[i] + shaft;
    add(positions[i], tip, colour, width * 0.6f, width);
    // The head: a wedge from 30% back along the shaft, 3 widths wide at its base, to the tip.
    add(tip - 0.3f * shaft, tip, colour, 3 * width, 0.5f);
  }
}

}  // namespace hs::render
