// The heart's phase from the valves (heart_phase.h): each rule of the table, a whole beat in the
// textbook's order, the diastasis before the ventricle's onset, and a leaking valve.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cardiac/circulation/heart_phase.h"

namespace hs::cardiac {
namespace {

PhaseSignals valves(bool mitral, bool aortic, bool contracting) { return {true, mitral, aortic, contracting}; }

TEST(HeartPhase, AnOpenValveNamesThePhase) {
  for (const HeartPhase previous : {HeartPhase::None, HeartPhase::IsovolumicContraction, HeartPhase::Ejection,
                                    HeartPhase::IsovolumicRelaxation, HeartPhase::Filling}) {
    EXPECT_EQ(heartPhaseAfter(previous, valves(false, true, true)), HeartPhase::Ejection);
    EXPECT_EQ(heartPhaseAfter(previous, valves(true, false, false)), HeartPhase::Filling);
    EXPECT_EQ(heartPhaseAfter(previous, valves(true, true, true)), HeartPhase::Ejection);
    EXPECT_EQ(heartPhaseAfter(previous, valves(true, true, false)), HeartPhase::Filling);
    EXPECT_EQ(heartPhaseAfter(previous, {false, true, true, true}), HeartPhase::None) << "no valves";
  }
}

TEST(HeartPhase, BothShutIsIsovolumicAndTheMuscleSaysWhichAfterFilling) {
  const PhaseSignals shutContracting = valves(false, false, true), shutRelaxed = valves(false, false, false);
  EXPECT_EQ(heartPhaseAfter(HeartPhase::Ejection, shutContracting), HeartPhase::IsovolumicRelaxation);
  EXPECT_EQ(heartPhaseAfter(HeartPhase::IsovolumicRelaxation, shutRelaxed), HeartPhase::IsovolumicRelaxation);
  EXPECT_EQ(heartPhaseAfter(HeartPhase::IsovolumicContraction, shutContracting),
            HeartPhase::IsovolumicContraction);
  EXPECT_EQ(heartPhaseAfter(HeartPhase::Filling, shutContracting), HeartPhase::IsovolumicContraction);
  EXPECT_EQ(heartPhaseAfter(HeartPhase::Filling, shutRelaxed), HeartPhase::Filling)
      << "the atrium's relaxation floats the mitral valve shut before the ventricle's onset";
  EXPECT_EQ(heartPhaseAfter(HeartPhase::None, shutContracting), HeartPhase::IsovolumicContraction);
  EXPECT_EQ(heartPhaseAfter(HeartPhase::None, shutRelaxed), HeartPhase::IsovolumicRelaxation);
}

TEST(HeartPhase, ABeatRunsThroughTheFourPhasesInTheTextbooksOrder) {
  // mitral, aortic, contracting per step, as normal's lumped heart gives them (metrics.csv).
  const std::vector<PhaseSignals> beat = {
      valves(true, false, false),  valves(false, false, false),  // A wave ends, valve floats shut
      valves(false, false, true),  valves(false, false, true),   // onset: isovolumic contraction
      valves(false, true, true),   valves(false, true, true),    // ejection
      valves(false, false, true),  valves(false, false, false),  // isovolumic relaxation
      valves(true, false, true),   valves(true, false, false),   // filling (E wave)
  };
  const std::vector<HeartPhase> expected = {
      HeartPhase::Filling, HeartPhase::Filling, HeartPhase::IsovolumicContraction,
      HeartPhase::IsovolumicContraction, HeartPhase::Ejection, HeartPhase::Ejection,
      HeartPhase::IsovolumicRelaxation, HeartPhase::IsovolumicRelaxation, HeartPhase::Filling,
      HeartPhase::Filling};
  HeartPhase phase = HeartPhase::Filling;
  for (std::size_t i = 0; i < beat.size(); ++i) {
    phase = heartPhaseAfter(phase, beat[i]);
    EXPECT_EQ(phase, expected[i]) << "step " << i;
  }
}

TEST(HeartPhase, NamesKeysAndLeaks) {
  EXPECT_EQ(std::string(heartPhaseName(HeartPhase::IsovolumicContraction)), "isovolumic contraction");
  EXPECT_EQ(std::string(heartPhaseKey(HeartPhase::IsovolumicRelaxation)), "isovolumic_relaxation");
  EXPECT_EQ(std::string(heartPhaseKey(HeartPhase::None)), "none");
  EXPECT_EQ(std::string(heartPhaseShortName(HeartPhase::IsovolumicContraction)), "IVC");
  EXPECT_TRUE(heartPhaseLeaks(HeartPhase::IsovolumicContraction, true, false)) << "mitral regurgitation";
  EXPECT_FALSE(heartPhaseLeaks(HeartPhase::IsovolumicContraction, false, false));
  EXPECT_FALSE(heartPhaseLeaks(HeartPhase::Ejection, true, false)) << "not an isovolumic phase";
}

}  // namespace
}  // namespace hs::cardiac

namespace hs::cardiac {
namespace {

TEST(HeartPhase, TheSoundsComeAsTheValvesClose) {
  EXPECT_EQ(heartSoundAt(HeartPhase::Filling, HeartPhase::IsovolumicContraction), HeartSound::S1);
  EXPECT_EQ(heartSoundAt(HeartPhase::Filling, HeartPhase::Ejection), HeartSound::S1) << "no isovolumic phase";
  EXPECT_EQ(heartSoundAt(HeartPhase::Ejection, HeartPhase::IsovolumicRelaxation), HeartSound::S2);
  EXPECT_EQ(heartSoundAt(HeartPhase::IsovolumicContraction, HeartPhase::IsovolumicContraction), HeartSound::None);
  EXPECT_EQ(heartSoundAt(HeartPhase::IsovolumicRelaxation, HeartPhase::Filling), HeartSound::None);
  EXPECT_EQ(std::string(heartSoundName(HeartSound::S2)), "S2");
  EXPECT_EQ(std::string(heartSoundName(HeartSound::None)), "");
}

}  // namespace
}  // namespace hs::cardiac
