#pragma once
// Scene set-up for fluids: a block of particles on a cubic lattice and the walls of a box.
#include <vector>

#include "pbd/core/constraints.h"
#include "pbd/core/types.h"

namespace hs::pbd {

// A cubic lattice of spacing d filling the box [lower, upper]: one particle at the centre of
// each whole cell of edge d, x = lower + d (i + 1/2), so particles keep d/2 from every face.
std::vector<Vec3> fluidBlock(const Vec3& lower, const Vec3& upper, Real spacing);

// Six inward-facing planes of the box [lower, upper] (walls for FluidStepSettings).
std::vector<Plane> boxWalls(const Vec3& lower, const Vec3& upper);

}  // namespace hs::pbd
