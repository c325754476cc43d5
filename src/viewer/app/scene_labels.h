#pragma once
// The anatomy's names in the viewer: render/anatomy_labels.h, shared with `heartsim render`.
// scene_overlays draws them over the scene (key N or the Display section toggles them).
#include "render/anatomy_labels.h"

namespace hs::viewer {

using render::anatomyLabels;
using render::LabelSide;
using render::ProjectedLabel;
using render::projectLabel;
using render::SceneLabel;

}  // namespace hs::viewer
