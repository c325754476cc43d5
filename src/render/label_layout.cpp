#include "render/label_layout.h"

#include <algorithm>
#include <cmath>

namespace hs::render {

std::vector<PlacedLabel> layoutLabels(const std::vector<SceneLabel>& labels,
                                      const std::vector<std::pair<float, float>>& textSizes, const Camera& camera,
                                      int width, int height, const LabelBox& bounds, const LabelSpacing& spacing,
                                      const std::vector<LabelBox>& avoid) {
  std::vector<ProjectedLabel> projected;
  projected.reserve(labels.size());
  float column = 0;
  int onScreen = 0;
  for (const SceneLabel& label : labels) {
    projected.push_back(projectLabel(label, camera, width, height));
    if (projected.back().onScreen) column += projected.back().x, ++onScreen;
  }
  column = onScreen > 0 ? column / float(onScreen) : float(width) / 2;
  const float onColumn = 0.06f * float(width);

  std::vector<LabelBox> taken = avoid;
  auto clearOfAll = [&](const LabelBox& box) {
    return std::none_of(taken.begin(), taken.end(), [&](const LabelBox& q) { return box.overlaps(q); });
  };
  std::vector<PlacedLabel> placed;
  const float reach = spacing.reach, pad = spacing.pad;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const ProjectedLabel& p = projected[i];
    if (!p.onScreen) continue;
    const auto [textWidth, textHeight] = textSizes[i];
    PlacedLabel out;
    out.label = i, out.at = p;
    float tx = 0, ty = 0;  // the text's top-left corner
    if (labels[i].side == LabelSide::Below) {
      out.leaderX = p.x, out.leaderY = p.y + reach / 2;
      tx = out.leaderX - textWidth / 2, ty = out.leaderY + pad;
    } else {
      const bool left = std::abs(p.x - column) < onColumn ? labels[i].side == LabelSide::Left : p.x < column;
      out.leaderX = p.x + (left ? -reach : reach), out.leaderY = p.y - reach / 2;
      tx = left ? out.leaderX - textWidth - pad : out.leaderX + pad, ty = out.leaderY - textHeight / 2;
    }
    LabelBox box{tx - pad, ty - pad, textWidth + 2 * pad, textHeight + 2 * pad};
    const float maxX = std::max(bounds.x, bounds.right() - box.width);
    const float maxY = std::max(bounds.y, bounds.bottom() - box.height);
    box.x = std::clamp(box.x, bounds.x, maxX);
    box.y = std::clamp(box.y, bounds.y, maxY);
    const float first = box.y, line = box.height + pad;
    for (int tries = 1; tries <= 24 && !clearOfAll(box); ++tries) {
      const int lines = (tries + 1) / 2 * (tries % 2 == 1 ? 1 : -1);  // +1, -1, +2, -2, ...
      box.y = std::clamp(first + float(lines) * line, bounds.y, maxY);
    }
    // The leader follows its box up or down.
    out.leaderY += box.y - (ty - pad);
    out.box = box;
    taken.push_back(box);
    placed.push_back(out);
  }
  return placed;
}

}  // namespace hs::render
