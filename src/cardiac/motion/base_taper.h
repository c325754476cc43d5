#pragma once
// The base ring is held by the fibrous skeleton (the annuli and the base plate), which does not
// shorten: a wall's inward motion fades from the mid-ventricle (a third of `length` below the
// base plane y = 0) to none at the base plane, smoothly, s^2 (3 - 2 s), s = -y / (length / 3)
// clamped to [0, 1], so the plate's rim and the vessels' roots on it are not crushed. Read by
// the lumped circulation's wall (volume_driven_wall.h) and by the own cycle with
// cycle.base_held (cardiac_cycle.h).
#include <algorithm>

#include "pbd/core/types.h"

namespace hs::cardiac {

inline pbd::Real baseTaper(pbd::Real y, double length) {
  const double s = std::clamp(-double(y) / (length / 3), 0.0, 1.0);
  return pbd::Real(s * s * (3 - 2 * s));
}

}  // namespace hs::cardiac
