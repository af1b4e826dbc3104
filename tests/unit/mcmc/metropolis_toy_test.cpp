// Metropolis-Hastings on the toy target of thesis digest §2.3: pi(u) = (u - 1/2)^2 on [0, 1],
// started at u = 0. The combined mutation (10 % uniform, else local) reaches the target; the local
// mutation alone almost never crosses to the right half, and the same test must catch that.
#include <gtest/gtest.h>

#include <functional>

#include "chi_square.h"
#include "core/rng.h"
#include "mcmc/metropolis.h"
#include "pss/primary_sample_vector.h"

using namespace relt;

namespace {

float target(float u) { return u >= 0.0f && u <= 1.0f ? (u - 0.5f) * (u - 0.5f) : 0.0f; }

// Final states of many independent chains are independent draws, so Pearson's test applies
// (consecutive states of one chain would not be).
std::vector<float> finalStates(const std::function<float(float, Rng&)>& mutate, int chains, int steps) {
  std::vector<float> out;
  for (int c = 0; c < chains; ++c) {
    Rng rng(hashKey(77, c));
    float u = 0.0f;
    for (int i = 0; i < steps; ++i) {
      const float v = mutate(u, rng);
      if (rng.uniform() < acceptance(target(u), target(v))) u = v;
    }
    out.push_back(u);
  }
  return out;
}

test::ChiSquareResult testAgainstTarget(const std::vector<float>& samples) {
  const int bins = 20;
  std::vector<double> observed(bins, 0.0), expected(bins, 0.0);
  for (float u : samples) observed[std::min(bins - 1, static_cast<int>(u * bins))] += 1.0;
  // The normalised target 12 (u - 1/2)^2 integrated over each bin.
  auto cdf = [](double u) { return 4.0 * std::pow(u - 0.5, 3) + 0.5; };
  for (int b = 0; b < bins; ++b) expected[b] = samples.size() * (cdf((b + 1.0) / bins) - cdf(double(b) / bins));
  return test::chiSquareTest(observed, expected);
}

float local(float u, Rng& rng) { return u + (rng.uniform() - 0.5f) / 10.0f; }

}  // namespace

TEST(MetropolisToy, CombinedMutationMatchesTheTarget) {
  const auto samples = finalStates(
      [](float u, Rng& rng) { return rng.uniform() < 0.1f ? rng.uniform() : local(u, rng); }, 20000, 200);
  const test::ChiSquareResult r = testAgainstTarget(samples);
  EXPECT_TRUE(r.passes(0.01)) << r.describe();
}

TEST(MetropolisToy, LocalMutationAloneNeverReachesTheRightHalfAndFailsTheTest) {
  const auto samples = finalStates(local, 20000, 200);
  int right = 0;
  for (float u : samples) right += u > 0.5f;
  // The target puts half its mass there; crossing the zero at u = 1/2 with steps of at most 0.05
  // is rare (0.2 % of these chains manage it within 200 steps).
  EXPECT_LT(right, 200);
  EXPECT_FALSE(testAgainstTarget(samples).passes(0.01));
}

TEST(MetropolisToy, KelemenMutationsOnAPrimarySampleVectorMatchTheTarget) {
  // One coordinate of a PrimarySampleVector; large steps with probability 0.3 as in relt's chains.
  std::vector<float> samples;
  for (int c = 0; c < 20000; ++c) {
    PrimarySampleVector v(hashKey(91, c));
    Rng rng(hashKey(92, c));
    v.setState(SampleStream::Camera, {0.0f});
    float u = 0.0f;
    for (int i = 0; i < 100; ++i) {
      v.startIteration(rng.uniform() < 0.3f);
      const float proposal = v.next(SampleStream::Camera);
      if (rng.uniform() < acceptance(target(u), target(proposal))) {
        v.accept();
        u = proposal;
      } else {
        v.reject();
      }
    }
    samples.push_back(u);
  }
  const test::ChiSquareResult r = testAgainstTarget(samples);
  EXPECT_TRUE(r.passes(0.01)) << r.describe();
}

TEST(MetropolisAcceptance, RejectsZeroAndNonFiniteProposalsAndLeavesZeroStates) {
  EXPECT_EQ(acceptance(1.0f, 0.0f), 0.0f);
  EXPECT_EQ(acceptance(1.0f, NAN), 0.0f);
  EXPECT_EQ(acceptance(1.0f, INFINITY), 0.0f);
  EXPECT_EQ(acceptance(0.0f, 0.5f), 1.0f);
  EXPECT_FLOAT_EQ(acceptance(2.0f, 1.0f), 0.5f);
  EXPECT_EQ(acceptance(1.0f, 3.0f), 1.0f);
}
