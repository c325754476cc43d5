// Names along a row (label_row.h): none covers another when the row has room, each stays as
// near its place as that allows, and names already apart do not move.
#include <gtest/gtest.h>

#include <vector>

#include "viewer/plots/label_row.h"

namespace hs::viewer {
namespace {

TEST(LabelRow, NamesThatFitStayWhereTheyWant) {
  std::vector<float> x = {10, 60, 200};
  spreadLabelRow(x, {30, 40, 50}, 0, 400, 3);
  EXPECT_EQ(x, (std::vector<float>{10, 60, 200}));
}

TEST(LabelRow, ANarrowPhasesNameNoLongerCoversItsNeighbour) {
  // The Wiggers band of mitral regurgitation: "IVC" (21 px) centred on a 10 px phase right
  // before "ejection" (56 px) centred on its own.
  std::vector<float> x = {630, 650, 720};
  const std::vector<float> w = {21, 56, 21};
  spreadLabelRow(x, w, 600, 880, 3);
  for (std::size_t i = 0; i + 1 < x.size(); ++i) EXPECT_LE(x[i] + w[i] + 3, x[i + 1]) << i;
  EXPECT_GE(x[0], 600);
  EXPECT_LE(x.back() + w.back(), 880);
  EXPECT_EQ(x[0], 630) << "the first keeps its place; the next moves right";
}

TEST(LabelRow, NamesAtTheRowsEndMoveLeftAndStayInside) {
  std::vector<float> x = {300, 310, 330};
  const std::vector<float> w = {20, 20, 20};
  spreadLabelRow(x, w, 0, 340, 2);
  EXPECT_LE(x.back() + w.back(), 340);
  for (std::size_t i = 0; i + 1 < x.size(); ++i) EXPECT_LE(x[i] + w[i] + 2, x[i + 1]) << i;
}

}  // namespace
}  // namespace hs::viewer
