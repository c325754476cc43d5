#pragma once
// The real-size hearts' [model] sizes (scenarios/normal.toml), for tests that build the model
// without reading the scenario.
#include "cardiac/lv_model.h"

namespace hs::cardiac::testing {

inline LvGeometryParams normalGeometry() {
  LvGeometryParams g;
  g.endoRadius = Real(0.032);
  g.endoLongAxis = Real(0.06);
  g.wallThickness = Real(0.01);
  g.baseThickness = Real(0.004);
  g.mitralRadius = Real(0.0125);
  g.aorticRadius = Real(0.010);
  g.vesselWallThickness = Real(0.002);
  g.inflowVesselLength = Real(0.03);
  g.outflowVesselLength = Real(0.03);
  return g;
}

// The anatomical vessels (docs/lv-model.md) on a heart's sizes: a 32 mm aortic root, a 40 mm
// atrium, both vessels leaning 35 degrees, 60 and 50 mm long.
inline LvGeometryParams withAnatomicalVessels(LvGeometryParams g) {
  g.inflowVesselLength = Real(0.06);
  g.outflowVesselLength = Real(0.05);
  g.aorticSinusRadius = Real(0.016);
  g.atriumRadius = Real(0.020);
  g.vesselLeanDeg = Real(35);
  return g;
}

}  // namespace hs::cardiac::testing
