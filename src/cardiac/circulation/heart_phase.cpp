#include "cardiac/circulation/heart_phase.h"

#include <cstddef>

namespace hs::cardiac {

HeartPhase heartPhaseAfter(HeartPhase previous, const PhaseSignals& now) {
  if (!now.valves) return HeartPhase::None;
  if (now.aorticOpen && now.mitralOpen) return now.contracting ? HeartPhase::Ejection : HeartPhase::Filling;
  if (now.aorticOpen) return HeartPhase::Ejection;
  if (now.mitralOpen) return HeartPhase::Filling;
  switch (previous) {
    case HeartPhase::Ejection:
    case HeartPhase::IsovolumicRelaxation:
      return HeartPhase::IsovolumicRelaxation;
    case HeartPhase::IsovolumicContraction:
      return HeartPhase::IsovolumicContraction;
    case HeartPhase::Filling:
      return now.contracting ? HeartPhase::IsovolumicContraction : HeartPhase::Filling;
    case HeartPhase::None:
      break;
  }
  // The first step: both valves shut, so isovolumic; which one, by the muscle.
  return now.contracting ? HeartPhase::IsovolumicContraction : HeartPhase::IsovolumicRelaxation;
}

namespace {

// Every name of a phase, in HeartPhase's order.
struct PhaseNames {
  const char* name;
  const char* shortName;
  const char* key;
  const char* explanation;
};
constexpr PhaseNames kPhaseNames[] = {
    {"", "", "none",
     "This scenario has no valves: only the wall's own clock (contracting or relaxing) is known."},
    {"isovolumic contraction", "IVC", "isovolumic_contraction",
     "The ventricle contracts with both valves shut: its pressure climbs, its volume stays, until it exceeds "
     "the aorta's and the aortic valve opens."},
    {"ejection", "ej.", "ejection",
     "The aortic valve is open: the contracting ventricle pushes blood into the aorta and its volume falls."},
    {"isovolumic relaxation", "IVR", "isovolumic_relaxation",
     "The aortic valve has shut and the mitral valve is not yet open: the ventricle relaxes, its pressure "
     "falls, its volume stays."},
    {"filling", "fill.", "filling",
     "The mitral valve is open: blood flows in from the atrium, first as the ventricle relaxes (E wave), then "
     "pushed by the atrium's contraction (A wave, the atrial kick)."},
};

const PhaseNames& names(HeartPhase phase) { return kPhaseNames[std::size_t(phase)]; }

}  // namespace

const char* heartPhaseName(HeartPhase phase) { return names(phase).name; }
const char* heartPhaseShortName(HeartPhase phase) { return names(phase).shortName; }
const char* heartPhaseKey(HeartPhase phase) { return names(phase).key; }
const char* heartPhaseExplanation(HeartPhase phase) { return names(phase).explanation; }

bool heartPhaseLeaks(HeartPhase phase, bool mitralLeak, bool aorticLeak) {
  const bool isovolumic = phase == HeartPhase::IsovolumicContraction || phase == HeartPhase::IsovolumicRelaxation;
  return isovolumic && (mitralLeak || aorticLeak);
}

HeartSound heartSoundAt(HeartPhase previous, HeartPhase now) {
  if (now == HeartPhase::IsovolumicContraction && previous != HeartPhase::IsovolumicContraction) return HeartSound::S1;
  if (now == HeartPhase::Ejection && previous == HeartPhase::Filling) return HeartSound::S1;
  if (previous == HeartPhase::Ejection && now != HeartPhase::Ejection) return HeartSound::S2;
  return HeartSound::None;
}

const char* heartSoundName(HeartSound sound) {
  switch (sound) {
    case HeartSound::S1: return "S1";
    case HeartSound::S2: return "S2";
    case HeartSound::None: break;
  }
  return "";
}

std::string heartPhaseLabel(HeartPhase phase, const PhaseDetail& d) {
  if (phase == HeartPhase::None)
    return d.wallContracting ? "the wall contracts (no valves: only the wall's own clock)"
                             : "the wall relaxes (no valves: only the wall's own clock)";
  std::string label = heartPhaseName(phase);
  if (phase == HeartPhase::Filling && d.atrialKick) label += ": atrial kick (A wave)";
  if (heartPhaseLeaks(phase, d.mitralLeak, d.aorticLeak))
    label += d.mitralLeak ? ": not isovolumic, blood leaks back into the atrium"
                          : ": not isovolumic, blood leaks back from the aorta";
  return label;
}

}  // namespace hs::cardiac
