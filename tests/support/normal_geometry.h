#pragma once
// The real-size hearts' [model] sizes (scenarios/normal.toml: an adult's left ventricle with an
// atrium, an aortic root with sinuses and both vessels leaning apart), for tests that build the
// model without reading the scenario.
#include "cardiac/anatomy/lv_model.h"

namespace hs::cardiac::testing {

inline LvGeometryParams normalGeometry() {
  LvGeometryParams g;
  g.endoRadius = Real(0.0275);
  g.endoLongAxis = Real(0.081);
  g.wallThickness = Real(0.01);
  g.baseThickness = Real(0.004);
  g.mitralRadius = Real(0.012);
  g.aorticRadius = Real(0.010);
  g.vesselWallThickness = Real(0.0012);
  g.inflowVesselLength = Real(0.06);
  g.outflowVesselLength = Real(0.05);
  g.atriumRadius = Real(0.020);
  g.aorticSinusRadius = Real(0.016);
  g.vesselLeanDeg = Real(40);
  return g;
}

// The same sizes with straight vessels (no atrium, no sinuses, no lean): tubes of the orifices'
// radii, for tests of what holds for any lumen.
inline LvGeometryParams withStraightVessels(LvGeometryParams g) {
  g.atriumRadius = 0;
  g.aorticSinusRadius = 0;
  g.vesselLeanDeg = 0;
  return g;
}

}  // namespace hs::cardiac::testing
