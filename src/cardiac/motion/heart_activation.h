#pragma once
// The lumped heart's activation (lumped_circulation.h) from the beating regions' clocks: the
// ventricle contracts with each region's systole, weighted by the share of the wall that
// region holds (an akinetic or late region adds nothing to that beat's contractility); the
// atrium contracts a PR interval before the main region's next systole.
#include <vector>

#include "cardiac/circulation/lumped_circulation.h"
#include "cardiac/motion/cardiac_cycle.h"

namespace hs::cardiac {

// Each region's share of the myocardium's cavity-side vertices (CardiacCycle::regions order).
std::vector<double> regionShares(const CardiacCycle& cycle, const LvModel& model, Index firstParticle);

// The activation during the coming step of length dt (evaluated at its middle), read before
// the clocks advance. `atrialContraction` false: no A wave.
Activation heartActivation(const CardiacCycle& cycle, const std::vector<double>& shares, const BeatTiming& timing,
                           bool atrialContraction, Real dt);

}  // namespace hs::cardiac
