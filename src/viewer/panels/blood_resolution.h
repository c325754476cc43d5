#pragma once
// The viewer's side of the blood's resolution (the levels: cardiac/blood_resolution.h): the
// choice, at start-up, of the finest level that holds real time on the machine the viewer runs
// on, and the panel's line about it. Plain data and text, unit-tested
// (tests/viewer/panels/test_blood_resolution.cpp); resolution_probe.h measures the levels.
#include <optional>
#include <span>
#include <string>

#include "cardiac/blood_resolution.h"
#include "cardiac/scenario.h"

namespace hs::viewer {

// The levels themselves (cardiac/blood_resolution.h), as every command names them.
using cardiac::applyResolution;
using cardiac::BloodResolution;
using cardiac::kResolutionCount;
using cardiac::kResolutionLevels;
using cardiac::kScenarioResolution;
using cardiac::parseResolution;
using cardiac::particlesAtLevel;
using cardiac::resolutionLevel;
using cardiac::ResolutionLevel;
using cardiac::resolutionName;
using cardiac::resolutionSpacingScale;

// One level's measurement at start-up: its steps' pace, simulated seconds per wall second of
// stepping (while the window draws). Unmeasured: coarser levels were too slow, or it could not
// be built (a spacing the scenario's geometry cannot hold).
struct LevelMeasurement {
  BloodResolution level = kScenarioResolution;
  bool measured = false;
  double pace = 0;
};

// A pace at or above this holds real time: the measurement leaves out what the viewer adds
// (copying the scene for each frame, the pump's readout), and a machine shared with other work
// varies; 10% in hand.
inline constexpr double kHoldsRealTimePace = 1.1;

// The finest measured level that holds real time; none holding, the coarsest measured (which
// runs in slow motion, and says so); none measured, the scenario's own.
BloodResolution chooseResolution(std::span<const LevelMeasurement> measurements);
// Measured coarsest first, a level is worth measuring while every coarser one measured held
// real time (a finer level is slower).
bool worthMeasuring(std::span<const LevelMeasurement> measuredSoFar);

// What the panel shows of the blood's resolution.
struct ResolutionStatus {
  BloodResolution level = kScenarioResolution;  // of the run
  int particles = 0;                             // the run's blood particles
  double spacing = 0;                            // m, the run's particle spacing
  std::optional<double> measuredPace;            // the start-up measurement of this level
  // Non-empty: what fixed the count ("as --set blood.particles sets it"); it runs as given and
  // the line says so, until another level is picked.
  std::string fixedBy;
  bool measuring = false;          // the start-up measurement is going on
  std::string measuringWhat;       // "medium (2 of 4)"
};

// One line: "blood: medium, 2,100 particles, holds real time (1.3x)"; behind: "..., 0.45x
// real time: slow motion"; while measuring: "measuring this computer's pace: medium (2 of 4)".
// livePace / behind: the simulation thread's pace now and whether it falls short of 1x.
// paused: "blood: medium, 2,100 particles, paused" (no pace while nothing runs).
std::string resolutionLine(const ResolutionStatus& status, double livePace, bool behind, bool paused = false);

// 4200 -> "4,200".
std::string withThousands(long value);

}  // namespace hs::viewer
