// The blood's smoothed field (render/blood_field.h): the grid search gives the brute-force
// result; a constant field stays constant (Shepard normalisation), a noisy one is calmed, and
// the scene's colours come from the smoothed speed, not each particle's own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "cardiac/heart_simulation.h"
#include "falling_block.h"
#include "render/blood_field.h"
#include "render/scene.h"

namespace {

using hs::pbd::Real;
using hs::pbd::Vec3;
using hs::render::FieldValue;

// Points in a 1 x 1 x 1 box at a fixed pseudo-random sequence, with values of noise around a
// base value.
struct Cloud {
  std::vector<Vec3> positions;
  std::vector<FieldValue> values;
};
Cloud randomCloud(int count, Real noise, std::uint32_t seed = 7) {
  auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return Real(seed >> 8) / Real(1 << 24);
  };
  Cloud c;
  for (int i = 0; i < count; ++i) {
    c.positions.emplace_back(next(), next(), next());
    FieldValue v;
    v << 1 + noise * (next() - Real(0.5)), -2, 0.5, 1000 + 100 * noise * (next() - Real(0.5));
    c.values.push_back(v);
  }
  return c;
}

double variance(const std::vector<FieldValue>& values, int channel) {
  double sum = 0, sumSq = 0;
  for (const FieldValue& v : values) sum += double(v[channel]), sumSq += double(v[channel]) * double(v[channel]);
  const double n = double(values.size());
  return sumSq / n - (sum / n) * (sum / n);
}

TEST(BloodField, GridSearchGivesTheBruteForceResult) {
  const Cloud c = randomCloud(600, 1);
  const std::vector<FieldValue> grid = hs::render::smoothField(c.positions, c.values, Real(0.15));
  const std::vector<FieldValue> brute = hs::render::smoothFieldBruteForce(c.positions, c.values, Real(0.15));
  ASSERT_EQ(grid.size(), brute.size());
  for (std::size_t i = 0; i < grid.size(); ++i)
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(double(grid[i][k]), double(brute[i][k]), 1e-4 * (1 + std::abs(double(brute[i][k]))));
}

TEST(BloodField, AConstantFieldStaysConstantEvenAtTheEdge) {
  const Cloud c = randomCloud(400, 0);
  for (const FieldValue& v : hs::render::smoothField(c.positions, c.values, Real(0.2)))
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(double(v[k]), double(c.values[0][k]), 1e-4 * (1 + std::abs(double(v[k]))));
}

TEST(BloodField, NoiseIsCalmedAndTheMeanKept) {
  const Cloud c = randomCloud(2000, 1);
  const std::vector<FieldValue> smoothed = hs::render::smoothField(c.positions, c.values, Real(0.15));
  EXPECT_LT(variance(smoothed, 0), variance(c.values, 0) / 4);
  double before = 0, after = 0;
  for (std::size_t i = 0; i < smoothed.size(); ++i) before += double(c.values[i][0]), after += double(smoothed[i][0]);
  EXPECT_NEAR(after / double(smoothed.size()), before / double(smoothed.size()), 0.02);
}

TEST(BloodField, SceneColoursComeFromTheSmoothedSpeed) {
  hs::cardiac::HeartSimulation sim(hs::testing::fallingBlock(), 1);
  for (int i = 0; i < 20; ++i) sim.step();
  const hs::render::BloodField field = hs::render::smoothedBlood(sim);
  const hs::render::Scene scene = hs::render::buildScene(sim, {});
  ASSERT_EQ(scene.particles.colours.size(), field.velocity.size());
  ASSERT_GT(field.velocity.size(), 100u);
  const double top = hs::render::defaultSpeedScale(sim.scenario());
  for (std::size_t k = 0; k < field.velocity.size(); ++k) {
    EXPECT_TRUE(scene.particles.colours[k].isApprox(hs::render::speedColour(double(field.velocity[k].norm()) / top)));
    EXPECT_TRUE(field.position[k].isApprox(sim.particles().position[field.particle[k]].cast<float>()));
  }
}

}  // namespace
