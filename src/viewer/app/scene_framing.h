#pragma once
// Where the heart is framed in the window: between the two side panels and above the
// circulation panel (a strip at the bottom, circulation_panel.h). The renderer projects over
// the whole window height, so framing into a shorter area is a zoom out (the bounds fill the
// area's height instead of the window's) and a pan up (the area's centre instead of the
// window's). Pure camera arithmetic on a CameraController, unit-tested.
#include "render/renderer.h"
#include "viewer/app/camera_controller.h"

namespace hs::viewer {

// Window pixels; the area's top is the window's.
struct SceneArea {
  float left = 0, right = 1;  // the side panels' inner edges
  float strip = 0;            // the height of the strip at the bottom (0: none)
};

// The named view framing the camera's bounds in `area` of a windowWidth x windowHeight window.
void frameView(CameraController& camera, render::View view, const SceneArea& area, int windowWidth,
               int windowHeight);
// A camera framed for a strip `from` pixels tall, moved to one framed for a strip `to` pixels
// tall, its orientation and the user's zoom and pan kept: the inverse of one fitting, then the
// other (showing or hiding the circulation panel).
void refitForStrip(CameraController& camera, float from, float to, int windowHeight);

}  // namespace hs::viewer
