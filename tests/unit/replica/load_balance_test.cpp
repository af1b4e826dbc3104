// Placement from measured speed: counts in proportion to speed, the slowest rank's time never
// worse, noise below the threshold moves nothing, and the moves turn one placement into the other.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "core/rng.h"
#include "replica/load_balance.h"

using namespace relt;

namespace {

double slowestTime(const std::vector<int>& counts, const std::vector<double>& speed) {
  double t = 0.0;
  for (size_t r = 0; r < counts.size(); ++r)
    if (speed[r] > 0.0) t = std::max(t, counts[r] / speed[r]);
  return t;
}

}  // namespace

TEST(LoadBalance, ARankTwiceAsSlowGetsHalfTheChains) {
  // 128 chains each; rank 1 takes twice as long: 256 chains split 171 / 85 (time 171 vs 170).
  const std::vector<int> counts = balancedCounts({128, 128}, {1.0, 2.0}, 0.01);
  EXPECT_EQ(counts, (std::vector<int>{171, 85}));
}

TEST(LoadBalance, EqualSpeedsAndSmallGainsMoveNothing) {
  EXPECT_EQ(balancedCounts({128, 128}, {1.0, 1.0}, 0.01), (std::vector<int>{128, 128}));
  // 0.5 % faster: one chain would gain less than the threshold.
  EXPECT_EQ(balancedCounts({128, 128}, {1.0, 1.005}, 0.01), (std::vector<int>{128, 128}));
  EXPECT_EQ(balancedCounts({7, 8}, {1.0, 1.3}, 0.01), (std::vector<int>{8, 7}));
}

TEST(LoadBalance, RanksWithoutChainsOrTimingsKeepTheirCounts) {
  EXPECT_EQ(balancedCounts({0, 10, 10}, {0.0, 1.0, 3.0}, 0.01), (std::vector<int>{0, 15, 5}));
  EXPECT_EQ(balancedCounts({4, 4}, {0.0, 0.0}, 0.01), (std::vector<int>{4, 4}));
  // A very slow rank keeps one chain, so its speed stays measured.
  EXPECT_EQ(balancedCounts({5, 5}, {1.0, 1000.0}, 0.01), (std::vector<int>{9, 1}));
}

TEST(LoadBalance, CountsKeepEveryChainAndNeverSlowTheSlowestRank) {
  Rng rng(17);
  for (int trial = 0; trial < 500; ++trial) {
    const size_t ranks = 1 + rng.below(9);
    std::vector<int> chains(ranks);
    std::vector<double> seconds(ranks), speed(ranks);
    for (size_t r = 0; r < ranks; ++r) {
      chains[r] = int(rng.below(40));
      seconds[r] = chains[r] ? 0.1 + 3.0 * rng.uniformDouble() : 0.0;
      speed[r] = chains[r] ? chains[r] / seconds[r] : 0.0;
    }
    const std::vector<int> counts = balancedCounts(chains, seconds, 0.0);
    EXPECT_EQ(std::accumulate(counts.begin(), counts.end(), 0), std::accumulate(chains.begin(), chains.end(), 0));
    EXPECT_LE(slowestTime(counts, speed), slowestTime(chains, speed) * (1.0 + 1e-12));
    for (size_t r = 0; r < ranks; ++r) {
      if (chains[r] > 0) EXPECT_GE(counts[r], 1);
      // Optimal: moving any one chain from the slowest-finishing rank elsewhere does not help.
      if (speed[r] > 0.0 && counts[r] / speed[r] == slowestTime(counts, speed) && counts[r] > 1)
        for (size_t o = 0; o < ranks; ++o)
          if (o != r && speed[o] > 0.0) EXPECT_GE((counts[o] + 1) / speed[o], slowestTime(counts, speed) * (1 - 1e-12));
    }
  }
}

TEST(LoadBalance, MovesTurnThePlacementIntoTheCounts) {
  const std::vector<std::vector<int>> hosted = {{0, 3, 6, 9}, {1, 4, 7, 10}, {2, 5, 8, 11}};
  const std::vector<ChainMove> moves = planMoves(hosted, {2, 4, 6});
  EXPECT_EQ(moves, (std::vector<ChainMove>{{6, 0, 2}, {9, 0, 2}}));
  const std::vector<std::vector<int>> after = applyMoves(hosted, moves);
  EXPECT_EQ(after, (std::vector<std::vector<int>>{{0, 3}, {1, 4, 7, 10}, {2, 5, 8, 11, 6, 9}}));

  const std::vector<ChainMove> two = planMoves(hosted, {6, 1, 5});
  EXPECT_EQ(two, (std::vector<ChainMove>{{4, 1, 0}, {7, 1, 0}, {10, 1, 2}}));
  EXPECT_TRUE(planMoves(hosted, {4, 4, 4}).empty());
}
