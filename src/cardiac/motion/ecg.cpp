#include "cardiac/motion/ecg.h"

#include <cmath>
#include <numbers>

namespace hs::cardiac {
namespace {

double bump(double tau, double centre, double width, double amplitude) {
  const double z = (tau - centre) / width;
  return amplitude * std::exp(-0.5 * z * z);
}

// The T wave's width (s): its end, two widths after its peak, is where the systole ends.
constexpr double kTWidth = 0.045;

}  // namespace

double ecgBeatWaveform(double tau, const BeatTiming& timing, bool atrialWaves) {
  double v = bump(tau, -0.040, 0.007, -0.12)    // Q
             + bump(tau, -0.025, 0.009, 1.20)   // R, 25 ms before the mechanical onset
             + bump(tau, -0.010, 0.008, -0.30)  // S
             + bump(tau, timing.systole - 2 * kTWidth, kTWidth, 0.30);  // T, ending with the systole
  if (atrialWaves) v += bump(tau, -timing.prInterval - 0.020, 0.022, 0.15);  // P, before the atrium contracts
  return v;
}

double syntheticEcg(double time, double sinceOnset, double untilOnset, const BeatTiming& timing, bool atrialWaves) {
  double v = 0;
  if (sinceOnset >= 0) v += ecgBeatWaveform(sinceOnset, timing, atrialWaves);
  if (untilOnset >= 0) v += ecgBeatWaveform(-untilOnset, timing, atrialWaves);
  if (!atrialWaves) {
    // f waves: two incommensurate rhythms, so the baseline never repeats.
    constexpr double kTwoPi = 2 * std::numbers::pi;
    v += 0.035 * std::sin(kTwoPi * 5.9 * time) + 0.025 * std::sin(kTwoPi * 7.7 * time + 1.3);
  }
  return v;
}

}  // namespace hs::cardiac
