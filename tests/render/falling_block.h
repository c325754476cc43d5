#pragma once
// A small block of blood falling in a box, no heart: a simulation whose blood moves from the
// first step, cheap enough for unit tests of what is drawn from it.
#include "cardiac/scenario.h"

namespace hs::testing {

inline cardiac::Scenario fallingBlock() {
  cardiac::Scenario scenario;
  scenario.heart = false;
  scenario.cycle.enabled = false;
  scenario.blood.enabled = true;
  scenario.blood.particles = 0;
  scenario.blood.radius = 0.0025f;
  scenario.blood.spacing = 0.005f;
  scenario.blood.supportRadius = 0.01f;
  scenario.blood.blockMin = pbd::Vec3(0, 0.02f, 0);
  scenario.blood.blockMax = pbd::Vec3(0.03f, 0.05f, 0.03f);
  scenario.container.enabled = true;
  scenario.container.min = pbd::Vec3(0, 0, 0);
  scenario.container.max = pbd::Vec3(0.06f, 0.06f, 0.06f);
  return scenario;
}

}  // namespace hs::testing
