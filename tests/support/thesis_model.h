#pragma once
// The thesis-scale LV model (LvGeometryParams defaults), built once for all tests of a binary.
#include "cardiac/anatomy/lv_model.h"

namespace hs::cardiac::testing {

inline const LvModel& thesisModel() {
  static const LvModel model = buildLvModel(LvGeometryParams{});
  return model;
}

}  // namespace hs::cardiac::testing
