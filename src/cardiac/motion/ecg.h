#pragma once
// A synthetic electrocardiogram (lead II) from the beat's own timing, for the Wiggers diagram a
// textbook draws: the electrical events in their places relative to the mechanical ones. It is
// not a model of conduction: each wave is a Gaussian bump (McSharry et al. 2003, "A dynamical
// model for generating synthetic electrocardiogram signals", IEEE TBME 50(3)) placed by the
// activation times heartsim already has (BeatTiming, the beat clock):
//   QRS: the ventricle's depolarisation, just before its mechanical onset (the R peak 25 ms
//        before it: the electromechanical delay), so before the mitral valve's closure;
//   T:   its repolarisation, ending as the electromechanical systole ends (BeatTiming::systole),
//        where the aortic valve closes;
//   P:   the atrium's depolarisation, just before its contraction (a PR interval before the
//        ventricle's onset).
// In atrial fibrillation the atrium does not contract: no P wave, a fibrillatory baseline
// (f waves, 4-8 Hz, about 0.05 mV) and the irregular RR intervals the beat clock gives.
#include "cardiac/circulation/lumped_circulation.h"

namespace hs::cardiac {

// One beat's waves (mV) at time tau (s) from the ventricle's mechanical onset (negative before it).
double ecgBeatWaveform(double tau, const BeatTiming& timing, bool atrialWaves);

// The ECG (mV) at `time` (s), between the onset before (sinceOnset s ago, negative if none) and
// the onset to come (in untilOnset s, negative if none known): the two beats' waveforms summed,
// so the trace is continuous through every onset; the f waves without atrial contraction.
double syntheticEcg(double time, double sinceOnset, double untilOnset, const BeatTiming& timing, bool atrialWaves);

}  // namespace hs::cardiac
