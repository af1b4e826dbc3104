// Round decisions of the Markov-chain loop: chain shares, the budget, the time limit, snapshots.
#include <gtest/gtest.h>

#include "mcmc/round_schedule.h"

using namespace relt;

TEST(RoundSchedule, BudgetedRenderGivesEveryChainItsShareInRoundsOfOneMutationPerPixel) {
  // 100 pixels, 7 chains: 14 steps per chain and round; 1000 mutations = 142 or 143 per chain.
  const RoundSchedule s(100.0, 7, std::nullopt, 1000);
  EXPECT_EQ(s.doneAfter(1, 0), 14u);
  EXPECT_EQ(s.doneAfter(100, 0), 143u);  // chains 0..5 get the 6 left over
  EXPECT_EQ(s.doneAfter(100, 6), 142u);
  EXPECT_EQ(s.mutationsAfter(100), 1000u);
  EXPECT_TRUE(s.anotherRound(10, 0.0, 0.0));   // 10 rounds: 980 steps
  EXPECT_FALSE(s.anotherRound(11, 0.0, 0.0));  // 11 rounds: every chain done
  EXPECT_DOUBLE_EQ(s.fraction(5, 123.0), 490.0 / 1000.0);
}

TEST(RoundSchedule, TimedRenderRunsTheFirstRoundAndThenOnlyRoundsExpectedToFit) {
  const RoundSchedule s(64.0, 256, 10.0, 0);
  EXPECT_EQ(s.doneAfter(3, 5), 3u);  // at least one step per round
  EXPECT_TRUE(s.anotherRound(0, 50.0, 50.0));
  EXPECT_TRUE(s.anotherRound(4, 8.0, 2.0));
  EXPECT_FALSE(s.anotherRound(4, 8.5, 2.0));
  EXPECT_DOUBLE_EQ(s.fraction(4, 5.0), 0.5);
}

TEST(SnapshotDue, OnlyWhenEnabledDueAndNotAfterTheLastRound) {
  EXPECT_FALSE(snapshotDue(0.0, 10.0, 0.0, true));
  EXPECT_FALSE(snapshotDue(2.0, 1.5, 0.0, true));
  EXPECT_TRUE(snapshotDue(2.0, 2.0, 0.0, true));
  EXPECT_FALSE(snapshotDue(2.0, 5.0, 0.0, false));
}
