#pragma once
// Where the anatomy's names go on a picture: pure placement, shared by `heartsim render`
// (anatomy_labels.h, into an image) and the viewer (scene_overlays.h, with ImGui), so that both
// put a name at the same place and neither lets two names lie on each other.
//
// Each name gets a leader line from its anchor out to a box with its text: sideways, away from
// the heart's column (the anchors' mean across), so it points outward in every view (an anchor
// on the column, as in a side view where the atrium and the aortic root lie one behind the
// other, keeps the side it has seen from the front); or straight below for a LabelSide::Below
// name. A box that would cover a box already placed, or one of the `avoid` rectangles (the colour
// key), moves a line down, then up, then two lines, and so on, staying inside `bounds`.
#include <vector>

#include "render/anatomy_labels.h"

namespace hs::render {

// A rectangle in window pixels (x right, y down).
struct LabelBox {
  float x = 0, y = 0, width = 0, height = 0;
  float right() const { return x + width; }
  float bottom() const { return y + height; }
  bool overlaps(const LabelBox& o) const {
    return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom();
  }
};

struct LabelSpacing {
  float reach = 22;  // the leader line's length out from the anchor
  float pad = 2;     // the paper's margin around the text
};

struct PlacedLabel {
  std::size_t label = 0;  // index into the labels laid out
  ProjectedLabel at;      // the anchor and the flow's arrow
  float leaderX = 0, leaderY = 0;  // the leader line's end, at the box
  LabelBox box;           // the paper; the text's top-left is (box.x + pad, box.y + pad)
};

// The names of `labels` on screen, each `textSizes[i]` (width, height) pixels of text, seen by
// `camera` in a width x height window, inside `bounds`, clear of `avoid`. Labels behind the
// camera are left out. When no free place is found within 12 lines either way the box keeps the
// last one tried (never seen with the heart's nine names).
std::vector<PlacedLabel> layoutLabels(const std::vector<SceneLabel>& labels,
                                      const std::vector<std::pair<float, float>>& textSizes, const Camera& camera,
                                      int width, int height, const LabelBox& bounds, const LabelSpacing& spacing,
                                      const std::vector<LabelBox>& avoid = {});

}  // namespace hs::render
