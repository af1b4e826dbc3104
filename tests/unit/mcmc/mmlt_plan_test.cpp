// mmlt's chains over path lengths: a fixed plan in proportion to each depth's bootstrap mean, and
// the weights that join the per-depth films into one image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mcmc/mmlt.h"

using namespace relt;

namespace {

// Bootstrap targets whose mean at depth d (sample i has depth 1 + i mod D) is mean[d - 1].
std::vector<double> targetsWithMeans(const std::vector<double>& mean, int perDepth) {
  std::vector<double> t(mean.size() * static_cast<size_t>(perDepth));
  for (size_t i = 0; i < t.size(); ++i) t[i] = mean[i % mean.size()];
  return t;
}

std::vector<int> chainsPerDepth(const MmltChainPlan& plan, int depths) {
  std::vector<int> n(static_cast<size_t>(depths), 0);
  for (int d : plan.depth) ++n[static_cast<size_t>(d - 1)];
  return n;
}

}  // namespace

TEST(MmltPlan, ChainsFollowEachDepthsShareWithOneForEveryLitDepth) {
  // Shares 0.5, 0.25, 0, 0.2, 0.05 of 100 chains: 50, 25, 0, 20, 5 exactly.
  const auto t = targetsWithMeans({0.5, 0.25, 0.0, 0.2, 0.05}, 10);
  MmltChainPlan plan = planMmltChains(t, 5, 100);
  ASSERT_TRUE(plan.stratified);
  ASSERT_EQ(plan.depth.size(), 100u);
  EXPECT_EQ(chainsPerDepth(plan, 5), (std::vector<int>{50, 25, 0, 20, 5}));
  // A tiny share still gets its chain; the rest follow the quotas within one chain.
  const auto tiny = targetsWithMeans({1.0, 1e-6, 0.5, 0.0}, 10);
  plan = planMmltChains(tiny, 4, 7);
  ASSERT_TRUE(plan.stratified);
  const std::vector<int> n = chainsPerDepth(plan, 4);
  EXPECT_EQ(n[0] + n[1] + n[2] + n[3], 7);
  EXPECT_EQ(n[1], 1);
  EXPECT_EQ(n[3], 0);
  EXPECT_NEAR(n[0], 6.0 * 2.0 / 3.0, 1.0);
  EXPECT_NEAR(n[2], 6.0 / 3.0, 1.0);
  // Chains are listed by depth, so chain c's depth never depends on the rank count.
  EXPECT_TRUE(std::is_sorted(plan.depth.begin(), plan.depth.end()));
}

TEST(MmltPlan, FewerChainsThanLitDepthsOrNothingVisibleFallsBackToPickingByTarget) {
  EXPECT_FALSE(planMmltChains(targetsWithMeans({1.0, 1.0, 1.0}, 4), 3, 2).stratified);
  EXPECT_FALSE(planMmltChains(targetsWithMeans({0.0, 0.0}, 4), 2, 16).stratified);
}

// Weights (b_d / b) (N / N_d): each depth's film gets its own normaliser over its own steps, so a
// depth with more chains than its share is scaled down, and b_d pools the large steps taken there.
TEST(MmltPlan, DepthWeightsGiveEachDepthItsNormaliserOverItsSteps) {
  const auto t = targetsWithMeans({0.6, 0.4}, 50);  // bootstrap b_1 = 0.6, b_2 = 0.4 from 50 each
  std::vector<ChainCounters> perDepth(2);
  perDepth[0].smallProposed = 700;
  perDepth[0].largeProposed = 300;  // N_1 = 1000
  perDepth[0].largeTargetSum = 300 * 0.9;  // the large steps say b_1 = 0.9
  perDepth[1].smallProposed = 3000;  // N_2 = 3000, no large steps: b_2 stays 0.4
  const std::vector<double> w = mmltDepthWeights(t, 2, perDepth);
  const double b1 = (50 * 0.6 + 300 * 0.9) / 350.0, b2 = 0.4, b = b1 + b2, n = 4000.0;
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NEAR(w[0], b1 / b * n / 1000.0, 1e-12);
  EXPECT_NEAR(w[1], b2 / b * n / 3000.0, 1e-12);
  EXPECT_NEAR(mmltNormaliser(t, 2, perDepth), b, 1e-12);
  // A depth without steps contributes nothing (and no division by zero).
  perDepth[1] = ChainCounters{};
  EXPECT_EQ(mmltDepthWeights(t, 2, perDepth)[1], 0.0);
}
