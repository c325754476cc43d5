#pragma once
// The panel's "Blood" section: viscosity, particle count, where the blood starts, two-way
// coupling and the valves. The simulation fixes all of them when it starts (HeartSimulation
// offers no way to change them while it runs), so a change restarts it from t = 0 with the
// scenario's settings changed, through the same path as Reset. Needs an ImGui frame for
// drawBloodSection; the rest is plain data, unit-tested.
#include "cardiac/scenario.h"
#include "viewer/panels/blood_resolution.h"

namespace hs::viewer {

struct BloodControls {
  double viscosity = 0.04;  // Pa s
  BloodResolution resolution = kScenarioResolution;  // spacing and count (blood_resolution.h)
  int particles = 1000;
  bool particlesEdited = false;  // the scenario may say 0 (fill the start region): keep it until edited
  cardiac::BloodSettings::Start start = cardiac::BloodSettings::Start::Block;
  bool twoWay = false;
  cardiac::ValveMode valveMode = cardiac::ValveMode::Timing;
  bool changed = false;  // one-frame request: restart with these settings
};

// The controls as a scenario sets them; `particleCount` is the count the simulation made
// (what blood.particles = 0 came to).
BloodControls bloodControlsFrom(const cardiac::Scenario& scenario, int particleCount);
// Writes the controls into the scenario's settings: the resolution's spacing and count, then an
// edited count.
void applyBloodControls(const BloodControls& controls, cardiac::Scenario& scenario);

// resolution: the run's level and count, for the resolution list's counts.
// hasHeart: the start, coupling and valve controls need the heart; lumped: the lumped
// circulation moves the wall and opens the valves, so the blood's settings cannot change EF or
// the pressures (the section says so) and the valve mode is its; wallYields: some wall vertex is
// free for the blood to push (two-way coupling is offered).
void drawBloodSection(BloodControls& controls, const ResolutionStatus& resolution, bool hasHeart, bool lumped,
                      bool wallYields);

}  // namespace hs::viewer
