// When a group's placement is decided again (replica/balance_window.h).
#include "replica/balance_window.h"

#include <gtest/gtest.h>

namespace relt {
namespace {

TEST(BalanceWindows, TheFirstDecisionsComeAfterAnEighthAQuarterAndAHalfOfTheWindow) {
  BalanceWindows w(1, 2, 1.0);  // one group, two ranks, a window of 1 s
  EXPECT_FALSE(w.due(0, 1));
  w.addRound(0, {0.1, 0.12}, true);
  EXPECT_FALSE(w.due(0, 1));  // 0.12 < 1/8
  w.addRound(0, {0.01, 0.01}, true);
  EXPECT_TRUE(w.due(0, 1));  // the slowest rank: 0.13 >= 1/8
  w.decided(0, true);
  EXPECT_FALSE(w.due(0, 1));  // a move starts a new window, now a quarter
  EXPECT_EQ(w.rounds(0), 0.0);
  w.addRound(0, {0.2, 0.3}, true);
  EXPECT_TRUE(w.due(0, 1));
  w.decided(0, true);
  w.addRound(0, {0.4, 0.3}, true);
  EXPECT_FALSE(w.due(0, 1));  // 0.4 < 1/2
  w.addRound(0, {0.1, 0.0}, true);
  EXPECT_TRUE(w.due(0, 1));
}

TEST(BalanceWindows, GroupsTakingTurnsCountTheirShareOfTheTime) {
  BalanceWindows w(4, 2, 1.0);
  w.addRound(2, {0.04, 0.03}, true);
  EXPECT_TRUE(w.due(2, 4));  // 0.04 x 4 groups >= 1/8
  EXPECT_FALSE(w.due(1, 4));
}

TEST(BalanceWindows, ADecisionThatMovesNothingDoublesTheWindowUpToEight) {
  BalanceWindows w(1, 3, 1.0);
  for (int d = 0; d < 3; ++d) {  // past the short first windows
    w.addRound(0, {1.0, 1.0, 1.0}, true);
    ASSERT_TRUE(w.due(0, 1));
    w.decided(0, true);
  }
  w.addRound(0, {0.0, 0.99, 0.0}, true);
  EXPECT_FALSE(w.due(0, 1));  // a whole window now
  w.addRound(0, {0.0, 0.02, 0.0}, true);
  // Nothing moved: the sums are kept and the window doubles (2, 4, 8 s), then a new one starts.
  for (double span : {2.0, 4.0, 8.0}) {
    ASSERT_TRUE(w.due(0, 1)) << span;
    w.decided(0, false);
    EXPECT_FALSE(w.due(0, 1)) << span;
    EXPECT_GT(w.rounds(0), 0.0);
    w.addRound(0, {0.0, span / 2.0, 0.0}, true);
  }
  ASSERT_TRUE(w.due(0, 1));
  w.decided(0, false);  // eight windows measured: the measurement starts again over one
  EXPECT_EQ(w.rounds(0), 0.0);
  EXPECT_EQ(w.seconds(0), (std::vector<double>{0.0, 0.0, 0.0}));
  w.addRound(0, {0.0, 1.0, 0.0}, true);
  EXPECT_TRUE(w.due(0, 1));
}

TEST(BalanceWindows, UntimedRoundsAddNoRoundAndOneRankOrNoWindowNeverDecides) {
  BalanceWindows w(1, 2, 1.0);
  w.addRound(0, {0.0, 0.0}, false);
  EXPECT_EQ(w.rounds(0), 0.0);
  w.addRound(0, {3.0, 4.0}, true);
  EXPECT_EQ(w.rounds(0), 1.0);
  EXPECT_EQ(w.seconds(0), (std::vector<double>{3.0, 4.0}));
  EXPECT_EQ(w.squares(0), (std::vector<double>{9.0, 16.0}));
  BalanceWindows alone(1, 1, 1.0), off(1, 2, 0.0);
  alone.addRound(0, {100.0}, true);
  off.addRound(0, {100.0, 100.0}, true);
  EXPECT_FALSE(alone.due(0, 1));
  EXPECT_FALSE(off.due(0, 1));
}

}  // namespace
}  // namespace relt
