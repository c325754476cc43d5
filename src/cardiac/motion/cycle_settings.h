#pragma once
// The cardiac cycle's settings ([cycle] of a scenario, cardiac_cycle.h): which clock, which
// pattern of beats, which part of the wall beats and how far.
#include <vector>

#include "pbd/core/types.h"

namespace hs::cardiac {

using pbd::Index;
using pbd::Real;
using pbd::Vec3;

enum class TimingMode { Thesis, Physiological };
enum class BeatPattern { Normal, Irregular, Inconsistent };

struct CycleSettings {
  bool enabled = true;
  TimingMode mode = TimingMode::Thesis;
  BeatPattern pattern = BeatPattern::Normal;
  int beats = 0;  // number of beats, then the wall relaxes; 0 = no limit
  // Thesis mode (Algorithms 2-3, Table 5.4).
  int beatingDuration = 8;       // steps per phase
  Real beatingDisplace = Real(0.08);   // m per systolic step
  // Physiological mode.
  Real heartRateBpm = 72;
  Real systolicFraction = Real(0.35);  // share of the cycle spent in systole
  Real contraction = Real(0.3);        // m, total inward displacement of a beating vertex per systole
  Real relaxationFraction = Real(0.8); // share of a regular diastole spent returning to rest (0 = released at once)
  bool baseHeld = false;  // sections shrink about the long axis, none at the base (base_taper.h; cardiac_cycle.cpp)
  // Which vertices beat: the union of these selections. Empty everything = all myocardium.
  std::vector<int> segments;        // AHA segments 1..17
  std::vector<Index> vertices;      // vertex ids
  bool sphereEnabled = false;
  Vec3 sphereCentre = Vec3::Zero();  // m
  Real sphereRadius = 0;             // m
  // Irregular pattern: each diastole is shortened by a random share in [0, irregularity).
  Real irregularity = Real(0.6);
  bool irregularBothWays = false;  // set with the lumped circulation (beat_clock.h), not a key
  unsigned seed = 1;
  // Inconsistent pattern: these segments beat with their own rate and phase.
  std::vector<int> inconsistentSegments = {7, 13, 17};
  Real inconsistentRateFactor = Real(0.5);    // beat rate relative to the rest
  Real inconsistentPhaseOffset = Real(0.5);   // fraction of a cycle
};

}  // namespace hs::cardiac
