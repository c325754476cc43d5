#pragma once
// A complete beat of the pump readout, for the lessons' tests: its index, its length (the RR
// interval it closes, s) and its volumes (mL).
#include "cardiac/circulation/beat_metrics.h"

namespace hs::viewer::testing {

inline cardiac::BeatSummary completeBeat(int index, double durationS, double edvMl, double esvMl) {
  cardiac::BeatSummary b;
  b.index = index;
  b.duration = durationS;
  b.complete = true;
  b.edv = edvMl * 1e-6;
  b.esv = esvMl * 1e-6;
  return b;
}

}  // namespace hs::viewer::testing
