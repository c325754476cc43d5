// The viewer's speed colours on `normal` (coarse blood, a tenth of a second into the beat): they
// come from the flow meter's own smoothing (the Doppler readings' field), and the blood in the
// vessels' far-end buffers, the lumped model's boundary, is grey rather than coloured by the
// speed the boundary imposes on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "cardiac/blood_resolution.h"
#include "cardiac/heart_simulation.h"
#include "io/scenario/scenario_file.h"
#include "render/blood_field.h"
#include "render/scene.h"

namespace hs::viewer {
namespace {

cardiac::Scenario coarseNormal() {
  cardiac::Scenario s = io::loadScenario("normal");
  cardiac::applyResolution(cardiac::BloodResolution::Coarse, s);
  return s;
}

TEST(SpeedColours, TheColoursAndTheDopplerReadOneSmoothedField) {
  cardiac::HeartSimulation sim(coarseNormal(), 1);
  for (int i = 0; i < 100; ++i) sim.step();
  const render::BloodField field = render::smoothedBlood(sim);
  const std::vector<pbd::Vec3>& doppler = sim.smoothedVelocities();
  ASSERT_EQ(doppler.size(), sim.particles().size());
  ASSERT_GT(field.particle.size(), 500u);
  // The same average; only the neighbour lists differ (the solve's, found before the step's
  // contacts, and the drawn positions'), which moves a few particles' values.
  std::vector<double> differences;
  for (std::size_t k = 0; k < field.particle.size(); ++k)
    differences.push_back((field.velocity[k].cast<double>() - doppler[field.particle[k]].cast<double>()).norm());
  std::sort(differences.begin(), differences.end());
  EXPECT_LT(differences[differences.size() / 2], 1e-3);
  EXPECT_LT(differences[differences.size() * 9 / 10], 0.05);
}

TEST(SpeedColours, TheVesselsFarEndsAreGreyNotColoured) {
  cardiac::HeartSimulation sim(coarseNormal(), 1);
  for (int i = 0; i < 20; ++i) sim.step();
  const render::BloodField field = render::smoothedBlood(sim);
  const render::Scene scene = render::buildScene(sim, {});
  ASSERT_EQ(scene.particles.colours.size(), field.particle.size());
  ASSERT_EQ(field.vesselEnd.size(), field.particle.size());
  const double top = render::defaultSpeedScale(sim.scenario());
  std::size_t ends = 0;
  for (std::size_t k = 0; k < field.particle.size(); ++k) {
    const bool end = sim.bloodInVesselEnd(field.particle[k]);
    EXPECT_EQ(field.vesselEnd[k], end ? 1 : 0);
    ends += end;
    const render::Vec3f expected =
        end ? render::kVesselEndColour : render::speedColour(double(field.velocity[k].norm()) / top);
    EXPECT_TRUE(scene.particles.colours[k].isApprox(expected)) << "blood particle " << field.particle[k];
  }
  // Both ends hold a kernel support of blood across their lumens.
  EXPECT_GT(ends, 20u);
  EXPECT_LT(ends, field.particle.size() / 4);
  // No speed colour is the grey.
  for (int i = 0; i <= 100; ++i) EXPECT_FALSE(render::speedColour(i / 100.0).isApprox(render::kVesselEndColour, 0.05f));
}

}  // namespace
}  // namespace hs::viewer
