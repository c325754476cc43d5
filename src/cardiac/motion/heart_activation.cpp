#include "cardiac/motion/heart_activation.h"

#include <algorithm>

namespace hs::cardiac {

std::vector<double> regionShares(const CardiacCycle& cycle, const LvModel& model, Index firstParticle) {
  std::vector<double> shares;
  for (const BeatingRegion& region : cycle.regions()) {
    std::vector<Index> vertices(region.particles);
    for (Index& v : vertices) v -= firstParticle;
    shares.push_back(myocardiumShare(model, vertices));
  }
  return shares;
}

Activation heartActivation(const CardiacCycle& cycle, const std::vector<double>& shares, const BeatTiming& timing,
                           bool atrialContraction, Real dt) {
  Activation a;
  const double half = 0.5 * double(dt);
  const auto& regions = cycle.regions();
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const BeatClock& clock = regions[r].clock;
    if (clock.phase() != Phase::Systole) continue;
    const double sinceOnset = double(clock.stepsInPhase()) * double(dt) + half;
    a.ventricle += shares[r] * ventricularActivationCurve(sinceOnset, timing.contraction, timing.relaxation);
  }
  if (!atrialContraction || regions.empty()) return a;
  // The atrium's onset: a PR interval before the main region's next (or this) systole.
  const BeatClock& main = regions.front().clock;
  double sinceAtrialOnset = -1;
  if (main.phase() == Phase::Systole) {
    sinceAtrialOnset = timing.prInterval + double(main.stepsInPhase()) * double(dt) + half;
  } else if (main.phase() == Phase::Diastole) {
    const double untilSystole = double(main.diastoleLength(dt) - main.stepsInPhase()) * double(dt) - half;
    sinceAtrialOnset = timing.prInterval - untilSystole;
  }
  a.atrium = activationCurve(sinceAtrialOnset, timing.atrialContraction, timing.atrialRelaxation);
  return a;
}

}  // namespace hs::cardiac
