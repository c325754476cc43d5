// The plots' valve flows, smoothed over about 25 ms: blood is counted in whole particles per
// step (one particle in a step of 1 ms is 46.66 mL/s in `normal`), and particles jitter to and
// fro across an open valve's disc. The centred mean over 25 steps must bring such a signal back
// within a few mL/s of the flow it counts, leave a constant as it is, and span exactly the
// window it states.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "viewer/plots/plot_history.h"

namespace hs::viewer {
namespace {

constexpr double kMl = 1e-6;                  // m^3
constexpr double kParticle = 0.0466559982e-6;  // m^3: normal's spacing^3 (3.6 mm)

PumpSample rates(double time, double mitral, double aortic = 0) {
  PumpSample s;
  s.time = time;
  s.mitralRate = mitral;
  s.aorticRate = aortic;
  return s;
}

// A filling flow of 150 +- 150 mL/s at 1.25 Hz, counted in whole particles per step, with a
// particle crossing back and forth every 40th step (an open valve's jitter).
double trueFlow(double t) { return (150 + 150 * std::sin(2 * std::numbers::pi * 1.25 * t)) * kMl; }
double trueVolume(double t) {
  const double w = 2 * std::numbers::pi * 1.25;
  return (150 * t + 150 / w * (1 - std::cos(w * t))) * kMl;
}

TEST(FlowSmoothing, ParticleStepsComeBackToTheFlowTheyCount) {
  const double dt = 0.001;
  PlotHistory h(5.0);
  double worstRaw = 0;
  for (int i = 1; i <= 2000; ++i) {
    const double t = i * dt;
    const double crossed =
        std::floor(trueVolume(t) / kParticle) - std::floor(trueVolume(t - dt) / kParticle);
    const double jitter = i % 40 == 0 ? -1 : i % 40 == 1 ? 1 : 0;
    const double raw = (crossed + jitter) * kParticle / dt;
    worstRaw = std::max(worstRaw, std::abs(raw - trueFlow(t - dt / 2)));
    h.push(rates(t, raw));
  }
  EXPECT_GT(worstRaw, 40 * kMl) << "the raw signal steps by a particle per step";
  ASSERT_EQ(h.smoothingHalfSteps(), 12);
  int known = 0;
  bool negative = false;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const PumpSample& s = h[i];
    if (!std::isfinite(s.mitralSmoothed)) continue;
    ++known;
    // The window's centre is the middle of the sample's own step.
    EXPECT_NEAR(s.mitralSmoothed / kMl, trueFlow(s.time - dt / 2) / kMl, 4.5) << "at t = " << s.time;
    negative = negative || s.mitralSmoothed < 0;
  }
  EXPECT_EQ(known, 2000 - 2 * 12) << "all but the half windows at either end";
  EXPECT_FALSE(negative) << "a filling flow does not read as backward";
}

TEST(FlowSmoothing, AConstantStaysConstant) {
  PlotHistory h(5.0);
  for (int i = 1; i <= 300; ++i) h.push(rates(i * 0.001, 120 * kMl, -30 * kMl));
  for (std::size_t i = 0; i < h.size(); ++i) {
    const bool inside = i >= 12 && i + 12 < h.size();
    ASSERT_EQ(std::isfinite(h[i].mitralSmoothed), inside) << "at " << i;
    if (!inside) continue;
    EXPECT_NEAR(h[i].mitralSmoothed / kMl, 120, 1e-9);
    EXPECT_NEAR(h[i].aorticSmoothed / kMl, -30, 1e-9);
  }
}

// One particle in one step spreads over exactly the window's steps and no further.
void expectWindow(double dt, int halfSteps, double seconds) {
  PlotHistory h(5.0);
  const int impulse = 200;
  for (int i = 1; i <= 400; ++i) h.push(rates(i * dt, i == impulse ? kParticle / dt : 0));
  EXPECT_EQ(h.smoothingHalfSteps(), halfSteps) << "dt " << dt;
  EXPECT_NEAR(h.smoothingSeconds(), seconds, 1e-12) << "dt " << dt;
  const int width = 2 * halfSteps + 1;
  int touched = 0;
  double volume = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double v = h[i].mitralSmoothed;
    if (!std::isfinite(v) || v == 0) continue;
    ++touched;
    EXPECT_NEAR(v, kParticle / dt / width, 1e-18);
    EXPECT_LE(std::abs(int(i) + 1 - impulse), halfSteps);
    volume += v * dt;
  }
  EXPECT_EQ(touched, width);
  EXPECT_NEAR(volume, kParticle, 1e-18) << "the volume is kept, only spread";
}

TEST(FlowSmoothing, TheWindowIsTheStatedLength) {
  expectWindow(0.001, 12, 0.025);    // normal: 25 steps
  expectWindow(0.005, 2, 0.025);     // the thesis's dt: 5 steps
  expectWindow(0.0005, 25, 0.0255);  // aortic-stenosis: 51 steps, the nearest odd count
}

TEST(FlowSmoothing, StartsOverWithTheSimulation) {
  PlotHistory h(5.0);
  for (int i = 1; i <= 100; ++i) h.push(rates(i * 0.001, 500 * kMl));
  for (int i = 1; i <= 100; ++i) h.push(rates(i * 0.005, 0));  // a restart at another dt
  EXPECT_EQ(h.smoothingHalfSteps(), 2);
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (!std::isfinite(h[i].mitralSmoothed)) continue;
    EXPECT_EQ(h[i].mitralSmoothed, 0) << "nothing from the run before";
  }
}

}  // namespace
}  // namespace hs::viewer
