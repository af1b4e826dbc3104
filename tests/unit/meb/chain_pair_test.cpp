// meb's chain pair on the thesis's toy (digest §6.2, scenario 1): the integral over [0, 1]^2 of
// 50 narrow Gaussian lobes, cut off at 3 sigma so that the visibility target is not 1 everywhere,
// estimated as meb estimates an iteration's light subpaths: an initial set, chain pairs started
// from it, expected-value splats scaled by the frozen normalisers, each chain's sum rescaled by
// the normalisers from the initial set and every large step.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "meb/adaptive_step.h"
#include "meb/chain_pair.h"
#include "meb/initial_set.h"

using namespace relt;

namespace {

struct Lobe {
  Vec2 centre;
  float sigma, amplitude;
};

struct Value {
  double v = 0.0;
  int lobe = -1;  // the lobe the point is in (the first that holds it)
  double luminance() const { return v; }
};

class Lobes {
 public:
  explicit Lobes(int count) {
    Rng rng(5, 1);
    for (int i = 0; i < count; ++i)
      lobes_.push_back({Vec2(0.1f + 0.8f * rng.uniform(), 0.1f + 0.8f * rng.uniform()),
                        0.005f + 0.015f * rng.uniform(), 0.5f + 1.5f * rng.uniform()});
  }
  Value operator()(SampleSource& u) const {
    const Vec2 p = u.next2(SampleStream::Light);
    Value out;
    for (size_t i = 0; i < lobes_.size(); ++i) {
      const Vec2 d = p - lobes_[i].centre;
      const float r2 = glm::dot(d, d), s2 = lobes_[i].sigma * lobes_[i].sigma;
      if (r2 >= 9.0f * s2) continue;
      out.v += lobes_[i].amplitude * std::exp(-0.5 * r2 / s2);
      if (out.lobe < 0) out.lobe = int(i);
    }
    return out;
  }
  double integral() const {
    double sum = 0.0;
    for (const Lobe& l : lobes_) sum += l.amplitude * 2.0 * std::numbers::pi * l.sigma * l.sigma * (1.0 - std::exp(-4.5));
    return sum;
  }
  size_t size() const { return lobes_.size(); }

 private:
  std::vector<Lobe> lobes_;
};

struct ToyRun {
  double estimate = 0.0;
  double missedLobes = 0.0;  // fraction of lobes the contribution chain never splatted
  double exchangeRate = 0.0, contributionAcceptance = 0.0;
};

ToyRun estimate(const Lobes& lobes, uint64_t key, int pairs, int stepsPerPair) {
  MebInitialSet<Value> initial;
  initial.evaluate(hashKey(key, 1), 0, 10000, [&](SampleSource& u, uint32_t) { return lobes(u); });
  EXPECT_TRUE(initial.prepare());
  const MebNormalisers frozen = initial.sums().mean();
  NormaliserSums all = initial.sums();
  double sum[2] = {0.0, 0.0};
  std::vector<bool> seen(lobes.size(), false);
  ToyRun run;
  for (int k = 0; k < pairs; ++k) {
    Rng pick(hashKey(key, 2, k));
    MebChainPair<Value> pair(hashKey(key, 3, k), frozen, 0.3f);
    pair.start(initial.visibilityStart(pick), initial.contributionStart(pick));
    NormaliserSums large;
    const auto splat = [&](MebChain chain, const Value& c, double weight) {
      sum[int(chain)] += c.v * weight;
      if (chain == MebChain::Contribution && c.lobe >= 0) seen[size_t(c.lobe)] = true;
    };
    for (int s = 0; s < stepsPerPair; ++s) pair.step([&](SampleSource& u) { return lobes(u); }, splat, large);
    all.add(large);
    run.exchangeRate += double(pair.exchanges()) / double(pair.exchangesTried()) / pairs;
    run.contributionAcceptance += pair.adaptation(MebChain::Contribution).acceptanceRate() / pairs;
  }
  const MebNormalisers b = all.mean();
  run.estimate = (sum[0] * b.visibility / frozen.visibility + sum[1] * b.contribution / frozen.contribution) /
                 (double(pairs) * stepsPerPair);
  for (bool s : seen) run.missedLobes += s ? 0.0 : 1.0 / double(lobes.size());
  return run;
}

}  // namespace

TEST(MebChainPair, EstimatesTheToysIntegralWithoutBias) {
  const Lobes lobes(50);
  const int runs = 40;
  double mean = 0.0, square = 0.0, missed = 0.0, exchange = 0.0, accept = 0.0;
  for (int r = 0; r < runs; ++r) {
    const ToyRun run = estimate(lobes, 100 + r, 8, 2500);
    mean += run.estimate / runs;
    square += run.estimate * run.estimate / runs;
    missed += run.missedLobes / runs;
    exchange += run.exchangeRate / runs;
    accept += run.contributionAcceptance / runs;
  }
  const double standardError = std::sqrt((square - mean * mean) / (runs - 1));
  const double truth = lobes.integral();
  EXPECT_NEAR(mean, truth, 4.0 * standardError) << "standard error " << standardError;
  EXPECT_LT(standardError / truth, 0.03) << "each run's error should be a few percent";
  EXPECT_LT(missed, 0.05) << "the exchanges should carry the contribution chain to every lobe";
  EXPECT_GT(exchange, 0.05);
  EXPECT_NEAR(accept, StepSizeAdaptation::kTargetAcceptance, 0.06) << "the small steps adapt towards 23.4 %";
}

TEST(MebChainPair, TheSplatScaleIsTheSameForBothChainsAndCountsEachHalf) {
  const MebNormalisers b{0.25, 3.0};
  // 2 / (1 / b_vis + c / b_con)
  EXPECT_DOUBLE_EQ(mebSplatScale(3.0, b), 2.0 / (4.0 + 1.0));
  EXPECT_DOUBLE_EQ(mebSplatScale(0.0, b), 0.0);
  // The weights w_vis + w_con = 1 for any state: b_vis / pi_vis * w_vis + ... gives back the scale.
  const double c = 1.7, wVis = (1.0 / b.visibility) / (1.0 / b.visibility + c / b.contribution);
  EXPECT_DOUBLE_EQ(2.0 * wVis * b.visibility / 1.0, mebSplatScale(c, b));
  EXPECT_DOUBLE_EQ(2.0 * (1.0 - wVis) * b.contribution / c, mebSplatScale(c, b));
}

TEST(MebChainPair, ExchangeAcceptanceIsTheRatioOfContributions) {
  EXPECT_DOUBLE_EQ(mebExchangeAcceptance(1.0, 4.0), 0.25);
  EXPECT_DOUBLE_EQ(mebExchangeAcceptance(4.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(mebExchangeAcceptance(0.0, 1.0), 0.0) << "an invisible state never enters the contribution chain";
  EXPECT_DOUBLE_EQ(mebExchangeAcceptance(2.0, 0.0), 0.0) << "nor an invisible one the visibility chain";
}

// The displacement, folded onto the circle of [0, 1), is symmetric, and its mean size is that of
// (2 xi)^(1 / theta) folded the same way (theta / (1 + theta) but for the rare steps beyond 1/2).
TEST(MebAdaptiveStep, IsSymmetricWithTheMeanSizeOfItsTheta) {
  const auto folded = [](double d) { return d <= 0.5 ? d : 1.0 - d; };
  for (float theta : {0.01f, 0.2f}) {
    double expected = 0.0;
    const int cells = 1000000;
    for (int i = 0; i < cells; ++i) expected += folded(std::pow((i + 0.5) / cells, 1.0 / theta)) / cells;
    Rng rng(3, 4);
    double up = 0.0, down = 0.0, size = 0.0;
    const int n = 400000;
    for (int i = 0; i < n; ++i) {
      // From 0.75 (floats as fine on both sides, unlike at 0.5), folded onto (-1/2, 1/2].
      double d = double(adaptiveSmallStep(0.75f, rng.uniform(), theta)) - 0.75;
      if (d > 0.5) d -= 1.0;
      if (d < -0.5) d += 1.0;
      up += d > 0.0 ? 1.0 : 0.0;  // steps below float resolution move neither way
      down += d < 0.0 ? 1.0 : 0.0;
      size += std::abs(d) / n;
    }
    EXPECT_NEAR(up / (up + down), 0.5, 4.0 * 0.5 / std::sqrt(up + down)) << theta;
    EXPECT_NEAR(size, expected, 0.03 * expected) << theta;
  }
  for (float xi : {0.0f, 0.25f, 0.49f, 0.51f, 0.999f}) {
    const float v = adaptiveSmallStep(0.99f, xi, 1.0f);
    EXPECT_GE(v, 0.0f);
    EXPECT_LT(v, 1.0f);
  }
}

TEST(MebAdaptiveStep, TheSizeGrowsWhenTooManyAreAcceptedAndShrinksWhenTooFew) {
  StepSizeAdaptation grow, shrink;
  for (int i = 0; i < 100; ++i) {
    grow.record(0.9);
    shrink.record(0.0);
  }
  EXPECT_GT(grow.theta(), StepSizeAdaptation::kInitialTheta * 10.0);
  EXPECT_LT(shrink.theta(), StepSizeAdaptation::kInitialTheta / 2.0);
  EXPECT_NEAR(grow.acceptanceRate(), 0.9, 1e-12);
}
