#pragma once
// The E-wave filling vortex in the long-axis cut, as 4D-flow papers draw it (Elbaz et al. 2014,
// Fig. 2): the vorticity across the cut in colour (red turning clockwise as drawn, blue
// anticlockwise, white still; grey where the cut holds no blood: the wall and outside), the
// in-plane velocity as arrows over it, the vortex cores found (cardiac/blood/filling_vortex.h)
// ringed, the ring's two in black, the mitral plane and the long axis as lines. Drawn on the CPU
// (viz::Image), no GL: the cut's `across` direction to the right, the long axis downward (the
// apex at the bottom), so the procedural heart's mitral orifice is on the left as in the front
// view.
#include <string>

#include "cardiac/blood/filling_vortex.h"
#include "viz/image.h"

namespace hs::render {

// The colour of vorticity omega on a scale of +-scale (1/s): white at 0, red at +scale, blue at
// -scale, clamped beyond.
viz::Rgb vorticityColour(double omega, double scale);

// The picture, about `height` pixels tall (each grid node a whole number of pixels), with a
// title line and a key below.
viz::Image drawEVortexCut(const cardiac::EVortexView& view, int height, const std::string& title);

}  // namespace hs::render
