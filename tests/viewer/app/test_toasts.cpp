// Toasts: shown for reading time within bounds, the newest few kept, a repeat renews instead
// of stacking, nothing empty.
#include <gtest/gtest.h>

#include "viewer/app/toasts.h"

namespace hs::viewer {
namespace {

TEST(Toasts, AMessageStaysForItsReadingTimeThenGoes) {
  Toasts toasts;
  toasts.push("picture saved: /tmp/heartsim_normal_001.png", ToastKind::Info, 10);
  const double stay = Toasts::secondsFor("picture saved: /tmp/heartsim_normal_001.png");
  EXPECT_GE(stay, Toasts::kMinSeconds);
  EXPECT_EQ(toasts.visible(10 + stay - 0.01).size(), 1u);
  EXPECT_TRUE(toasts.visible(10 + stay + 0.01).empty());
}

TEST(Toasts, LongMessagesStayLongerButNotForever) {
  const std::string shortText = "restarted";
  std::string longText;
  for (int i = 0; i < 200; ++i) longText += "word ";
  EXPECT_LT(Toasts::secondsFor(shortText), Toasts::secondsFor("cannot restart: blood.particles must be at most 20000"));
  EXPECT_DOUBLE_EQ(Toasts::secondsFor(longText), Toasts::kMaxSeconds);
}

TEST(Toasts, TheNewestFewAreShownOldestFirst) {
  Toasts toasts;
  for (int i = 0; i < 5; ++i) toasts.push("message " + std::to_string(i), ToastKind::Info, double(i) * 0.1);
  const std::vector<Toast> shown = toasts.visible(1);
  ASSERT_EQ(shown.size(), Toasts::kMaxShown);
  EXPECT_EQ(shown.front().text, "message 2");
  EXPECT_EQ(shown.back().text, "message 4");
}

TEST(Toasts, ARepeatRenewsAndEmptyTextIsIgnored) {
  Toasts toasts;
  toasts.push("the simulation stopped", ToastKind::Warning, 0);
  toasts.push("the simulation stopped", ToastKind::Warning, 3);
  toasts.push("", ToastKind::Info, 3);
  const std::vector<Toast> shown = toasts.visible(3);
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_EQ(shown[0].kind, ToastKind::Warning);
  EXPECT_DOUBLE_EQ(shown[0].until, 3 + Toasts::secondsFor("the simulation stopped"));
}

}  // namespace
}  // namespace hs::viewer
