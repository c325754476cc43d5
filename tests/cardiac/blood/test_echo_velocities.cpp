// The Doppler peaks per cycle (echo_velocities.h): a scripted cycle's aortic peak in ejection,
// mitral E before the atrial kick and A during it, none without a kick; cycles close at
// end-diastole; checkpoints carry the cycle in progress.
#include <gtest/gtest.h>

#include <vector>

#include "cardiac/blood/echo_velocities.h"

namespace hs::cardiac {
namespace {

using P = HeartPhase;

struct Script {
  EchoVelocities echo;
  P last = P::None;
  double t = 0;
  void step(P phase, double aortic, double mitral, bool kick = false) {
    echo.observe(aortic, mitral, last, phase, kick, t += 0.01);
    last = phase;
  }
  // One cycle from end-diastole: ejection peaking at `aortic`, then filling with E, a diastasis,
  // the kick's A (if any), and the next end-diastole.
  void cycle(double aortic, double e, std::optional<double> a) {
    step(P::IsovolumicContraction, 0.1, 0.2);  // end-diastole (after filling): not ejection
    step(P::Ejection, 0.5 * aortic, 0.9);      // the mitral reading in ejection is not E
    step(P::Ejection, aortic, 0);
    step(P::IsovolumicRelaxation, 3, 0);       // not ejection: not the aortic peak
    step(P::Filling, -2, 0.5 * e);
    step(P::Filling, 0, e);
    step(P::Filling, 0, 0.1);                  // diastasis
    if (a) step(P::Filling, 0, *a, true);
    if (a) step(P::Filling, 0, 0.5 * *a, true);
    step(P::Filling, 0, 0.05);                 // after the kick: neither E nor A
  }
};

TEST(EchoVelocities, PeaksOfEachCycleByPhase) {
  Script s;
  s.step(P::Filling, 0, 7);  // before the first end-diastole: no cycle
  s.cycle(1.2, 0.8, 0.4);
  s.cycle(1.0, 0.7, std::nullopt);
  s.step(P::IsovolumicContraction, 0, 0);  // closes the second
  const std::vector<CycleEcho>& c = s.echo.cycles();
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c[0].aorticPeak, 1.2);
  EXPECT_DOUBLE_EQ(c[0].mitralE, 0.8);
  ASSERT_TRUE(c[0].mitralA.has_value());
  EXPECT_DOUBLE_EQ(*c[0].mitralA, 0.4);
  EXPECT_DOUBLE_EQ(c[1].aorticPeak, 1.0);
  EXPECT_DOUBLE_EQ(c[1].mitralE, 0.7);
  EXPECT_FALSE(c[1].mitralA.has_value()) << "no atrial kick, no A wave";
  EXPECT_NEAR(c[0].end, c[1].start, 1e-12);
  EXPECT_LT(c[0].start, c[0].end);
}

TEST(EchoVelocities, ACheckpointCarriesTheCycleInProgress) {
  Script a;
  a.step(P::Filling, 0, 0);  // so that the cycle's first step is an end-diastole
  a.cycle(1.3, 0.9, 0.5);
  a.step(P::IsovolumicContraction, 0, 0);
  a.step(P::Ejection, 1.4, 0);
  pbd::StateWriter w;
  a.echo.save(w);
  Script b;
  pbd::StateReader r(w.bytes());
  b.echo.load(r);
  b.last = a.last;
  b.t = a.t;
  for (Script* s : {&a, &b}) {
    s->step(P::Filling, 0, 0.6);
    s->step(P::IsovolumicContraction, 0, 0);
  }
  ASSERT_EQ(b.echo.cycles().size(), 2u);
  EXPECT_DOUBLE_EQ(b.echo.cycles()[1].aorticPeak, 1.4);
  EXPECT_DOUBLE_EQ(b.echo.cycles()[1].mitralE, 0.6);
  EXPECT_EQ(a.echo.cycles()[1].aorticPeak, b.echo.cycles()[1].aorticPeak);
}

}  // namespace
}  // namespace hs::cardiac
