// The flow components' bookkeeping on a scripted toy flow: ten particles whose entries into and
// exits from the ventricle are known beat by beat, so every share is known exactly.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cardiac/blood/flow_components.h"

namespace hs::cardiac {
namespace {

// '1' in the ventricle, '0' outside, one character per particle.
std::vector<std::uint8_t> inside(const std::string& pattern) {
  std::vector<std::uint8_t> v;
  for (const char c : pattern) v.push_back(c == '1');
  return v;
}

TEST(FlowComponents, AScriptedFlowGivesItsKnownShares) {
  FlowComponentTracker tracker(10);
  // At the start particles 0-5 are in the ventricle; 6-9 wait in the atrium.
  tracker.observe(inside("1111110000"));
  EXPECT_FALSE(tracker.endSystole()) << "no end-diastole seen yet: no beat";
  // Diastole 1: 6 and 7 enter. End-diastole: 0-7 inside; 6, 7 new.
  tracker.observe(inside("1111111100"));
  tracker.endDiastole();
  // Systole 1: 0, 1 (from the start) and 6 (new) leave.
  tracker.observe(inside("0011110100"));
  const std::optional<FlowComponents> first = tracker.endSystole();
  ASSERT_TRUE(first);
  EXPECT_EQ(first->particles, 8u);
  EXPECT_DOUBLE_EQ(first->direct, 1.0 / 8);           // 6
  EXPECT_DOUBLE_EQ(first->retainedInflow, 1.0 / 8);   // 7
  EXPECT_DOUBLE_EQ(first->delayedEjection, 2.0 / 8);  // 0, 1
  EXPECT_DOUBLE_EQ(first->residual, 4.0 / 8);         // 2-5
  EXPECT_DOUBLE_EQ(first->sum(), 1.0);
  EXPECT_DOUBLE_EQ(first->meanResidenceBeats, 1.0) << "of the ejected, only 6 was seen entering: one beat";

  // Diastole 2: 0, 6, 8 and 9 enter (0 and 6 come round again through the loop).
  tracker.observe(inside("1011111111"));
  tracker.endDiastole();
  // Diastole 2 brought 0, 6, 8 and 9 (new); 2, 3, 4, 5 and 7 were there before. Systole 2: 7
  // (entered in diastole 1), 8 (new) and 2 (from the start) leave.
  tracker.observe(inside("1001111001"));
  const std::optional<FlowComponents> second = tracker.endSystole();
  ASSERT_TRUE(second);
  EXPECT_EQ(second->particles, 9u);
  EXPECT_DOUBLE_EQ(second->direct, 1.0 / 9);           // 8
  EXPECT_DOUBLE_EQ(second->retainedInflow, 3.0 / 9);   // 0, 6, 9
  EXPECT_DOUBLE_EQ(second->delayedEjection, 2.0 / 9);  // 2, 7
  EXPECT_DOUBLE_EQ(second->residual, 3.0 / 9);         // 3, 4, 5
  EXPECT_DOUBLE_EQ(second->meanResidenceBeats, 1.5) << "8 spent one beat, 7 two";
  EXPECT_DOUBLE_EQ(second->stayedOverThreeBeats, 0.0) << "two beats at most so far";
}

TEST(FlowComponents, BloodThereFromTheStartCountsAsStayingLong) {
  FlowComponentTracker tracker(2);
  tracker.observe(inside("10"));
  for (int beat = 1; beat <= 4; ++beat) {
    tracker.observe(inside("11"));
    tracker.endDiastole();
    tracker.observe(inside("10"));  // particle 1 enters and leaves every beat
    const std::optional<FlowComponents> c = tracker.endSystole();
    ASSERT_TRUE(c);
    EXPECT_DOUBLE_EQ(c->direct, 0.5);
    EXPECT_DOUBLE_EQ(c->residual, 0.5);
    // Particle 0 has been in the ventricle since the start: beats 1 to `beat`.
    EXPECT_DOUBLE_EQ(c->stayedOverThreeBeats, beat > 3 ? 0.5 : 0.0) << "beat " << beat;
  }
}

TEST(FlowComponents, ACheckpointResumesTheBookkeeping) {
  FlowComponentTracker a(3);
  a.observe(inside("100"));
  a.observe(inside("110"));
  a.endDiastole();
  pbd::StateWriter w;
  a.save(w);
  FlowComponentTracker b(3);
  pbd::StateReader r(w.bytes());
  b.load(r);
  for (FlowComponentTracker* t : {&a, &b}) t->observe(inside("011"));
  const std::optional<FlowComponents> ca = a.endSystole(), cb = b.endSystole();
  ASSERT_TRUE(ca && cb);
  EXPECT_EQ(ca->particles, cb->particles);
  EXPECT_DOUBLE_EQ(ca->direct, cb->direct);
  EXPECT_DOUBLE_EQ(ca->delayedEjection, cb->delayedEjection);
}

// One character per particle: '.' None, 'D' direct, 'R' retained inflow, 'Y' delayed ejection
// (the papers' yellow), 'S' residual (stayed).
std::string letters(const std::vector<FlowComponent>& components) {
  std::string s;
  for (const FlowComponent c : components) s += ".DRYS"[int(c)];
  return s;
}

TEST(FlowComponents, EachParticleShowsItsComponentFromEndDiastoleOn) {
  FlowComponentTracker tracker(6);
  // 0-2 in the ventricle from the start; 3-5 in the atrium.
  tracker.observe(inside("111000"));
  EXPECT_EQ(letters(tracker.components()), "......") << "no end-diastole yet";
  // Diastole 1: 3 and 4 enter; 5 stays out.
  tracker.observe(inside("111110"));
  EXPECT_EQ(letters(tracker.components()), "......") << "still filling";
  tracker.endDiastole();
  // At end-diastole nothing has left: new blood is retained inflow, earlier blood residual.
  EXPECT_EQ(letters(tracker.components()), "SSSRR.");
  // Early systole: 0 (earlier) leaves.
  tracker.observe(inside("011110"));
  EXPECT_EQ(letters(tracker.components()), "YSSRR.");
  // End-systole: 3 (new) has left too; the colours are endSystole's count.
  tracker.observe(inside("011010"));
  EXPECT_EQ(letters(tracker.components()), "YSSDR.");
  const std::optional<FlowComponents> beat = tracker.endSystole();
  ASSERT_TRUE(beat);
  EXPECT_DOUBLE_EQ(beat->direct, 1.0 / 5);
  EXPECT_DOUBLE_EQ(beat->retainedInflow, 1.0 / 5);
  EXPECT_DOUBLE_EQ(beat->delayedEjection, 1.0 / 5);
  EXPECT_DOUBLE_EQ(beat->residual, 2.0 / 5);
  EXPECT_EQ(letters(tracker.components()), "YSSDR.") << "the beat just counted";
  // Diastole 2: 0 comes round through the loop and enters again, 5 enters for the first time.
  // Until the next end-diastole the last beat's colours stay: 0 still left in it, 5 was not
  // there at its end-diastole.
  tracker.observe(inside("111011"));
  EXPECT_EQ(letters(tracker.components()), "YSSDR.");
  tracker.endDiastole();
  EXPECT_EQ(letters(tracker.components()), "RSS.SR") << "sorted again: 0 and 5 new, 3 outside";
}

TEST(FlowComponents, BloodStayingMoreThanThreeBeatsIsMarked) {
  FlowComponentTracker tracker(3);
  tracker.observe(inside("100"));  // 0 from the start
  for (int beat = 1; beat <= 4; ++beat) {
    tracker.observe(inside(beat == 1 ? "110" : "111"));  // 1 enters in diastole 1, 2 in diastole 2
    tracker.endDiastole();
    const Stay longer = beat >= 4 ? Stay::OverThreeBeats : Stay::UpToThreeBeats;
    const std::vector<Stay> stays = tracker.stays();
    EXPECT_EQ(stays[0], longer) << "beat " << beat;
    EXPECT_EQ(stays[1], longer) << "beat " << beat;
    EXPECT_EQ(stays[2], beat == 1 ? Stay::Outside : Stay::UpToThreeBeats) << "beat " << beat << ": three beats at most";
    tracker.endSystole();
  }
  tracker.observe(inside("011"));
  EXPECT_EQ(tracker.stays()[0], Stay::Outside) << "ejected at last";
}

}  // namespace
}  // namespace hs::cardiac
