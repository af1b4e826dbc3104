#include <gtest/gtest.h>

#include "render/schedule.h"

using namespace relt;

TEST(Schedule, EveryUnitHasExactlyOneOwnerForAnyRankCount) {
  for (int ranks = 1; ranks <= 7; ++ranks)
    for (uint64_t k = 0; k < 5; ++k)
      for (int row = 0; row < 13; ++row) {
        int owners = 0;
        for (int r = 0; r < ranks; ++r) owners += ownsUnit(k, row, 13, r, ranks);
        EXPECT_EQ(owners, 1);
      }
}

TEST(Schedule, WorkIsBalancedAcrossRanks) {
  const int height = 100, ranks = 3;
  int counts[ranks] = {};
  for (uint64_t k = 0; k < 9; ++k)
    for (int row = 0; row < height; ++row)
      for (int r = 0; r < ranks; ++r) counts[r] += ownsUnit(k, row, height, r, ranks);
  for (int r = 0; r < ranks; ++r) EXPECT_EQ(counts[r], 300);
}

TEST(Schedule, TimedRenderStopsBeforeOverrunningTheBudget) {
  EXPECT_TRUE(startAnotherPass(0, 0.0, 0.0, 1.0));
  EXPECT_TRUE(startAnotherPass(0, 5.0, 5.0, 1.0));  // the first pass always runs
  EXPECT_TRUE(startAnotherPass(3, 0.6, 0.2, 1.0));
  EXPECT_FALSE(startAnotherPass(4, 0.9, 0.2, 1.0));
}

TEST(ProgressLine, ShowsPercentElapsedEtaAndRateInTheGivenUnit) {
  EXPECT_EQ(progressLine(0.5, 2.0, 1.5e6), " 50.0%  2.0 s elapsed  ETA 2.0 s  1.50 M samples/s");
  EXPECT_EQ(progressLine(0.25, 1.0, 2e5, "mutations"), " 25.0%  1.0 s elapsed  ETA 3.0 s  0.20 M mutations/s");
  EXPECT_EQ(progressLine(0.0, 0.0, 0.0), "  0.0%  0.0 s elapsed  ETA 0.0 s  0.00 M samples/s");
}
