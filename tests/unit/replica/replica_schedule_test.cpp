// The replica round schedule: equal steps for every chain, the budget met exactly, time budgets
// stop at round boundaries.
#include <gtest/gtest.h>

#include "replica/replica_schedule.h"

using namespace relt;

TEST(ReplicaSchedule, SplitsTheBudgetIntoRoundsOfTheInterval) {
  // 10 x 10 pixels x 3 mutations = 300 steps over 8 chains: 38 per chain (rounded up), rounds of 16.
  const ReplicaSchedule s(100.0, 8, 16, std::nullopt, 3.0);
  EXPECT_EQ(s.stepsInRound(0), 16u);
  EXPECT_EQ(s.stepsInRound(1), 16u);
  EXPECT_EQ(s.stepsInRound(2), 6u);
  EXPECT_EQ(s.stepsInRound(3), 0u);
  EXPECT_TRUE(s.anotherRound(2, 0.0, 0.0));
  EXPECT_FALSE(s.anotherRound(3, 0.0, 0.0));
  EXPECT_EQ(s.stepsAfter(3), 38u);
  EXPECT_DOUBLE_EQ(replicaResolveDivisor(38, 2, 100.0), 0.76);
}

TEST(ReplicaSchedule, TimedRendersRunWholeRoundsWithinTheBudget) {
  const ReplicaSchedule s(100.0, 8, 16, 10.0, 1.0);
  EXPECT_TRUE(s.anotherRound(0, 0.0, 0.0));
  EXPECT_TRUE(s.anotherRound(5, 8.0, 1.5));
  EXPECT_FALSE(s.anotherRound(6, 9.5, 1.5));
  EXPECT_EQ(s.stepsInRound(1000), 16u);
  EXPECT_EQ(s.stepsAfter(6), 96u);
}
