// Placement from measured speed: counts in proportion to speed, the slowest rank's time never
// worse, noise below the threshold moves nothing, and the moves turn one placement into the other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// The move threshold follows the window's own noise: steady round times give the floor; round
// times that vary give a threshold that shrinks as 1 / sqrt(rounds) and grows with the rank count
// (the slowest of many ranks looks slow by noise alone).
TEST(LoadBalance, TheMoveThresholdFollowsTheMeasuredNoise) {
  // Two ranks, 100 rounds of exactly 2 ms: no noise, the floor.
  EXPECT_DOUBLE_EQ(noiseGain({8, 8}, {0.2, 0.2}, {100 * 4e-6, 100 * 4e-6}, 100.0, 0.01, 0.1), 0.01);
  // Round times 2 ms with a 20 % standard deviation on one rank: relative error 0.2 / sqrt(n).
  auto squares = [](double mean, double sd, double n) { return n * (mean * mean + sd * sd); };
  const double z2 = std::sqrt(2.0 * std::log(2.0)) + 1.0;
  EXPECT_NEAR(noiseGain({8, 8}, {0.2, 0.2}, {squares(2e-3, 4e-4, 100), squares(2e-3, 0.0, 100)}, 100.0, 0.01, 0.1), z2 * 0.02, 1e-9);
  EXPECT_NEAR(noiseGain({8, 8}, {1.6, 1.6}, {squares(2e-3, 4e-4, 800), squares(2e-3, 0.0, 800)}, 800.0, 0.0, 0.1),
              z2 * 0.2 / std::sqrt(800.0), 1e-9);
  // The same noise on 1,024 ranks: the slowest looks slower by chance, the threshold is higher.
  std::vector<double> seconds(1024, 0.2), sq(1024, squares(2e-3, 4e-4, 100));
  EXPECT_NEAR(noiseGain(std::vector<int>(1024, 8), seconds, sq, 100.0, 0.01, 0.1), (std::sqrt(2.0 * std::log(1024.0)) + 1.0) * 0.02, 1e-9);
  // Heavy tails (a rank losing time slices: 13 rounds of 0.3 ms, then one of 8.3 ms): at most the
  // ceiling, so a rank at a third of its speed still gets help.
  std::vector<double> slices;
  for (int i = 0; i < 56; ++i) slices.push_back(i % 14 == 13 ? 8.3e-3 : 0.3e-3);
  double sum = 0.0, sumSq = 0.0;
  for (double t : slices) sum += t, sumSq += t * t;
  EXPECT_DOUBLE_EQ(noiseGain({8, 8}, {sum / 3.0, sum}, {sumSq / 9.0, sumSq}, 56.0, 0.01, 0.1), 0.1);
  // Fewer than 4 rounds: no spread measured yet, the ceiling; one rank: the floor.
  EXPECT_DOUBLE_EQ(noiseGain({8, 8}, {0.002, 0.004}, {4e-6, 1.6e-5}, 1.0, 0.01, 0.1), 0.1);
  EXPECT_DOUBLE_EQ(noiseGain({8, 8}, {0.006, 0.012}, {1.2e-5, 4.8e-5}, 3.0, 0.01, 0.1), 0.1);
  EXPECT_DOUBLE_EQ(noiseGain({8}, {0.2}, {squares(2e-3, 4e-4, 100)}, 100.0, 0.01, 0.1), 0.01);
  // A rank without chains steps nothing: its tiny, jittery times count neither for the noise nor
  // for the rank count (1 us rounds with one 50 us hiccup would set the threshold to the ceiling).
  const double idle = 16e-6 + 49e-6, idleSq = 15 * 1e-12 + 50e-6 * 50e-6;
  EXPECT_DOUBLE_EQ(noiseGain({32, 32, 0}, {0.032, 0.0352, idle}, {16 * 4e-6, 16 * 4.84e-6, idleSq}, 16.0, 0.01, 0.1), 0.01);
  EXPECT_DOUBLE_EQ(noiseGain({32, 32, 1}, {0.032, 0.0352, idle}, {16 * 4e-6, 16 * 4.84e-6, idleSq}, 16.0, 0.01, 0.1), 0.1);
}
