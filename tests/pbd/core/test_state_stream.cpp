// The checkpoint streams: values, lists, optionals, the random generator's state and sections
// read back as written, and a reader that meets the wrong section or the stream's end says so
// with the byte offset instead of reading on.
#include <gtest/gtest.h>

#include <deque>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "pbd/core/particles.h"
#include "pbd/core/state_stream.h"
#include "thrown_message.h"

namespace hs::pbd {
namespace {

TEST(StateStream, ValuesListsAndOptionalsReadBackAsWritten) {
  StateWriter w;
  const std::vector<Vec3> points{Vec3(1, 2, 3), Vec3(-4, 5.5f, 6)};
  const std::deque<Index> queue{7, 8, 9};
  const std::optional<double> some = 0.25, none;
  w.section("piece");
  w.fields(std::int64_t(-12), true, std::string("text"), points, queue, some, none, std::array<double, 2>{1.5, 2.5});
  StateReader r(w.bytes());
  std::int64_t i = 0;
  bool flag = false;
  std::string text;
  std::vector<Vec3> readPoints;
  std::deque<Index> readQueue;
  std::optional<double> readSome, readNone = 3.0;
  std::array<double, 2> pair{};
  r.section("piece");
  r.fields(i, flag, text, readPoints, readQueue, readSome, readNone, pair);
  EXPECT_EQ(i, -12);
  EXPECT_TRUE(flag);
  EXPECT_EQ(text, "text");
  EXPECT_EQ(readPoints, points);
  EXPECT_EQ(readQueue, queue);
  EXPECT_EQ(readSome, some);
  EXPECT_FALSE(readNone.has_value());
  EXPECT_EQ(pair[1], 2.5);
  EXPECT_TRUE(r.atEnd());
}

TEST(StateStream, RandomGeneratorContinuesWhereItStopped) {
  std::mt19937 random(42);
  for (int k = 0; k < 1000; ++k) random();
  StateWriter w;
  w.put(random);
  std::mt19937 restored;
  StateReader r(w.bytes());
  r.get(restored);
  for (int k = 0; k < 10; ++k) EXPECT_EQ(restored(), random());
}

TEST(StateStream, WrongSectionNamesBothAndTheOffset) {
  StateWriter w;
  w.put(std::int32_t(5));
  w.section("valves");
  StateReader r(w.bytes());
  std::int32_t five = 0;
  r.get(five);
  try {
    r.section("flow meter");
    FAIL() << "no error";
  } catch (const StateError& e) {
    EXPECT_EQ(std::string(e.what()), "expected section 'flow meter', found 'valves'");
    EXPECT_EQ(e.offset, 4u);
  }
}

TEST(StateStream, ListRunningPastTheEndIsRefused) {
  StateWriter w;
  w.put(std::vector<double>{1, 2, 3});
  std::vector<std::uint8_t> cut = w.bytes();
  cut.resize(cut.size() - 1);
  StateReader r(cut);
  std::vector<double> values;
  EXPECT_NE(testing::thrownMessage<StateError>([&] { r.get(values); }).find("runs past the end"), std::string::npos);
}

TEST(StateStream, ParticlesOfAnotherCountAreAnotherScenarios) {
  Particles two, three;
  for (int k = 0; k < 2; ++k) two.add(Vec3::Zero(), 1, ParticleKind::Fluid);
  for (int k = 0; k < 3; ++k) three.add(Vec3::Zero(), 1, ParticleKind::Fluid);
  StateWriter w;
  two.save(w);
  StateReader r(w.bytes());
  EXPECT_EQ(testing::thrownMessage<StateError>([&] { three.load(r); }),
            "particles: positions: 2 values where the scenario has 3");
}

TEST(StateStream, ParticlesRoundTripEveryColumn) {
  Particles p;
  p.add(Vec3(1, 2, 3), 0.5f, ParticleKind::Tissue);
  p.add(Vec3(4, 5, 6), 2, ParticleKind::Fluid);
  p.state[1] = ParticleState::Parked;
  p.velocity[0] = Vec3(7, 8, 9);
  p.predicted[1] = Vec3(-1, -2, -3);
  permuteRange(p, 0, {1, 0});
  StateWriter w;
  p.save(w);
  Particles q;
  q.add(Vec3::Zero(), 1, ParticleKind::Tissue);
  q.add(Vec3::Zero(), 1, ParticleKind::Tissue);
  StateReader r(w.bytes());
  q.load(r);
  StateWriter again;
  q.save(again);
  EXPECT_EQ(again.bytes(), w.bytes());
  EXPECT_EQ(q.id[0], 1u);
  EXPECT_EQ(q.state[0], ParticleState::Parked);
}

}  // namespace
}  // namespace hs::pbd
