#pragma once
// The blood's resolution: a few levels of particle spacing a student (or the viewer, at
// start-up) chooses between, and the choice of the finest level that holds real time on the
// machine the viewer runs on. Each level scales the scenario's own blood: the spacing by s, the
// particle radius and the kernel's support radius alike (normal: radius = spacing / 2, support =
// 2 x spacing, at every level), and the particle count by 1 / s^3, so the same volume is filled:
// the heart stays full and the same share waits in the body. The physics keys (density,
// viscosity, XSPH, iterations, dt) stay as the scenario says. Plain data and text, unit-tested
// (tests/viewer/panels/test_blood_resolution.cpp); resolution_probe.h measures the levels.
#include <array>
#include <optional>
#include <span>
#include <string>

#include "cardiac/scenario.h"

namespace hs::viewer {

// Coarsest first. Fine is the scenario as written.
enum class BloodResolution { Coarse, Medium, Fine, Finest };
inline constexpr int kResolutionCount = 4;
inline constexpr BloodResolution kScenarioResolution = BloodResolution::Fine;

struct ResolutionLevel {
  BloodResolution level;
  const char* name;
  double countFactor;  // particles relative to the scenario's; the spacing scales by its cube root's inverse
};
inline constexpr std::array<ResolutionLevel, kResolutionCount> kResolutionLevels = {{
    {BloodResolution::Coarse, "coarse", 0.25},
    {BloodResolution::Medium, "medium", 0.5},
    {BloodResolution::Fine, "fine", 1.0},
    {BloodResolution::Finest, "finest", 2.0},
}};

const ResolutionLevel& resolutionLevel(BloodResolution level);
const char* resolutionName(BloodResolution level);
// "coarse", "medium", "fine" or "finest"; nullopt for anything else.
std::optional<BloodResolution> parseResolution(const std::string& text);
// The factor of the spacing (and radius and support radius): countFactor^(-1/3).
double resolutionSpacingScale(BloodResolution level);

// The scenario's blood at `level`: spacing, radius and support radius scaled alike, the count
// by countFactor (a count of 0, "fill the start region", stays 0: the fill follows the spacing).
void applyResolution(BloodResolution level, cardiac::Scenario& scenario);
// The count `level` gives, from the count of the run at `running` (what a count of 0 came to).
int particlesAtLevel(BloodResolution level, BloodResolution running, int runningCount);

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
std::string resolutionLine(const ResolutionStatus& status, double livePace, bool behind);

// 4200 -> "4,200".
std::string withThousands(long value);

}  // namespace hs::viewer
