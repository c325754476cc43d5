#pragma once
// The heart's phase, as a physiology text names it (Wiggers 1915): isovolumic contraction,
// ejection, isovolumic relaxation, filling. It is read from the valves, not from the wall's own
// clock: the wall's clock says when the muscle contracts (systole) and relaxes (diastole), but
// the ventricle ejects only while the aortic valve is open and fills only while the mitral valve
// is, and between those both valves are shut (the isovolumic phases). Every place that names the
// phase (metrics.csv's `phase` column, the viewer's pump panel and information box, the Wiggers
// diagram's bands) reads it from heartPhaseAfter() and names it with heartPhaseName(), so none
// can say "ejecting" while the mitral valve is open.
//
// The rule, one step at a time (the previous step's phase and this step's valves):
//   aortic valve open (forward flow)  -> ejection
//   mitral valve open (forward flow)  -> filling
//   both shut, after ejection or in isovolumic relaxation         -> isovolumic relaxation
//   both shut, in isovolumic contraction                          -> isovolumic contraction
//   both shut after filling: isovolumic contraction once the ventricle contracts; until then
//     still filling (the atrium's relaxation floats the mitral valve shut just before the
//     ventricle's onset; lumped_beat.cpp counts the isovolumic contraction from the later of
//     the two, as this rule does)
//   both open (a leaking valve in the wrong phase): ejection while the ventricle contracts,
//     filling otherwise.
// "Open" means forward flow: with a leaking valve blood leaves or enters through the shut valve,
// so the "isovolumic" phases of mitral regurgitation lose volume back into the atrium. The phase
// keeps its textbook name there (both forward valves shut) and the viewer says that the volume
// is not constant (heartPhaseLeaks).
#include <cstdint>
#include <string>

namespace hs::cardiac {

enum class HeartPhase : std::uint8_t {
  None = 0,  // no valves in the scenario: only the wall's own clock (cardiac::Phase) is known
  IsovolumicContraction = 1,
  Ejection = 2,
  IsovolumicRelaxation = 3,
  Filling = 4,
};

// What the phase is read from in one step.
struct PhaseSignals {
  bool valves = false;       // the scenario has valves (a circulation)
  bool mitralOpen = false;   // forward flow atrium -> ventricle in the step
  bool aorticOpen = false;   // forward flow ventricle -> aorta in the step
  bool contracting = false;  // the ventricle is activated (lumped) or in its wall's systole
};

// The phase of this step from the previous step's (None before the first) and this step's signals.
HeartPhase heartPhaseAfter(HeartPhase previous, const PhaseSignals& now);

// "isovolumic contraction", "ejection", "isovolumic relaxation", "filling"; "" for None.
const char* heartPhaseName(HeartPhase phase);
// "IVC", "ej.", "IVR", "fill.": for a band too narrow for the name.
const char* heartPhaseShortName(HeartPhase phase);
// metrics.csv's `phase` column: "isovolumic_contraction", "ejection", "isovolumic_relaxation",
// "filling"; "none" without valves.
const char* heartPhaseKey(HeartPhase phase);
// A sentence for a student: what the ventricle and its valves do in the phase.
const char* heartPhaseExplanation(HeartPhase phase);
// True for an isovolumic phase in which blood still leaves or enters through a shut valve
// (backward flow through it in the step): the volume is then not constant.
bool heartPhaseLeaks(HeartPhase phase, bool mitralLeak, bool aorticLeak);

// The heart sounds, where the phase says the valves close: S1 ("lub") as the ventricle's
// contraction shuts the mitral valve (the isovolumic contraction begins, or ejection straight
// after filling), S2 ("dub") as the aortic valve shuts (ejection ends).
enum class HeartSound : std::uint8_t { None = 0, S1 = 1, S2 = 2 };
HeartSound heartSoundAt(HeartPhase previous, HeartPhase now);
// "S1", "S2" or "" (metrics.csv's heart_sound column).
const char* heartSoundName(HeartSound sound);

// What a label adds to the phase's name.
struct PhaseDetail {
  bool wallContracting = false;  // the wall's own clock is in systole (named when there are no valves)
  bool atrialKick = false;       // filling while the atrium contracts (the A wave)
  bool mitralLeak = false, aorticLeak = false;  // backward flow through the valve in the step
};
// The one line every place shows: "ejection", "filling: atrial kick (A wave)", "isovolumic
// contraction: not isovolumic, blood leaks back into the atrium", or without valves "the wall
// contracts (no valves: only the wall's own clock)".
std::string heartPhaseLabel(HeartPhase phase, const PhaseDetail& detail);

}  // namespace hs::cardiac
