// The panel's blood settings round-trip through the scenario: unchanged controls leave the
// scenario exactly as it was (a restart from the panel runs what `heartsim run` runs), edited
// ones land in the right keys.
#include <gtest/gtest.h>

#include "io/scenario/scenario_file.h"
#include "viewer/panels/blood_controls.h"

namespace hs::viewer {
namespace {

TEST(ViewerBloodControls, UnchangedControlsLeaveTheScenarioAsItWas) {
  for (const char* name : {"paper-chamber-beating", "paper-vessel", "dam-break"}) {
    const cardiac::Scenario original = io::loadScenario(name);
    cardiac::Scenario s = original;
    applyBloodControls(bloodControlsFrom(original, 1234), s);
    EXPECT_EQ(s.blood.viscosity, original.blood.viscosity) << name;
    EXPECT_EQ(s.blood.particles, original.blood.particles) << name << ": 0 (fill) stays 0";
    EXPECT_EQ(s.blood.start, original.blood.start) << name;
    EXPECT_EQ(s.circulation.twoWay, original.circulation.twoWay) << name;
    EXPECT_EQ(s.circulation.valveMode, original.circulation.valveMode) << name;
  }
}

TEST(ViewerBloodControls, EditedControlsLandInTheScenario) {
  cardiac::Scenario s = io::loadScenario("paper-chamber-beating");
  BloodControls c = bloodControlsFrom(s, 1000);
  EXPECT_EQ(c.particles, 1000);
  c.viscosity = 0.0035;
  c.particles = 600;
  c.particlesEdited = true;
  c.start = cardiac::BloodSettings::Start::Vessel;
  c.twoWay = true;
  c.valveMode = cardiac::ValveMode::Pressure;
  applyBloodControls(c, s);
  EXPECT_FLOAT_EQ(float(s.blood.viscosity), 0.0035f);
  EXPECT_EQ(s.blood.particles, 600);
  EXPECT_EQ(s.blood.start, cardiac::BloodSettings::Start::Vessel);
  EXPECT_TRUE(s.circulation.twoWay);
  EXPECT_EQ(s.circulation.valveMode, cardiac::ValveMode::Pressure);
}

TEST(ViewerBloodControls, AScenarioThatFillsItsStartShowsTheCountItMade) {
  cardiac::Scenario s = io::loadScenario("paper-chamber-beating");
  s.blood.particles = 0;
  EXPECT_EQ(bloodControlsFrom(s, 1789).particles, 1789);
}

}  // namespace
}  // namespace hs::viewer
