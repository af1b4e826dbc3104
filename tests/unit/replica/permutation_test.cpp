// The importance-sampled permutation (thesis App. 5.C): drawn permutations follow
// prod_i Q(i, o[i]) / sum over all M! permutations, identity included, checked by chi-square
// against brute force for M = 4 and 5.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "chi_square.h"
#include "replica/permutation.h"

using namespace relt;

namespace {

TargetMatrix randomMatrix(int m, uint64_t seed, bool withZeros) {
  Rng rng(seed);
  TargetMatrix q(m);
  for (int i = 0; i < m; ++i)
    for (int k = 0; k < m; ++k) {
      // Targets spanning several orders of magnitude, as tempered levels give.
      q(i, k) = std::exp(6.0 * (rng.uniformDouble() - 0.5));
      if (withZeros && i != k && rng.uniform() < 0.25f) q(i, k) = 0.0;
    }
  return q;
}

// Brute force: every permutation with its normalised product.
std::map<std::vector<int>, double> bruteForce(const TargetMatrix& q) {
  std::vector<int> o(static_cast<size_t>(q.levels()));
  std::iota(o.begin(), o.end(), 0);
  std::map<std::vector<int>, double> p;
  double total = 0.0;
  do {
    double w = 1.0;
    for (int i = 0; i < q.levels(); ++i) w *= q(i, o[size_t(i)]);
    p[o] = w;
    total += w;
  } while (std::next_permutation(o.begin(), o.end()));
  for (auto& [perm, w] : p) w /= total;
  return p;
}

void checkSampler(int m, uint64_t seed, bool withZeros) {
  const TargetMatrix q = randomMatrix(m, seed, withZeros);
  const PermutationSampler sampler(q);
  const auto exact = bruteForce(q);
  std::map<std::vector<int>, double> counts;
  Rng rng(seed, 9);
  const int draws = 200000;
  for (int n = 0; n < draws; ++n) counts[sampler.sample(rng)] += 1.0;
  std::vector<double> observed, expected;
  for (const auto& [perm, p] : exact) {
    EXPECT_NEAR(sampler.probability(perm), p, 1e-12 + 1e-9 * p);
    observed.push_back(counts.count(perm) ? counts.at(perm) : 0.0);
    expected.push_back(p * draws);
    if (p == 0.0) EXPECT_EQ(observed.back(), 0.0) << "a permutation of zero product was drawn";
  }
  std::vector<int> identity(static_cast<size_t>(m));
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_GT(counts[identity], 0.0) << "the identity belongs to the proposal set";
  const test::ChiSquareResult r = test::chiSquareTest(observed, expected);
  EXPECT_TRUE(r.passes(0.001)) << r.describe();
}

}  // namespace

TEST(PermutationSampler, FourLevelsMatchBruteForce) { checkSampler(4, 11, false); }
TEST(PermutationSampler, FiveLevelsMatchBruteForce) { checkSampler(5, 12, false); }
TEST(PermutationSampler, ZeroTargetsAreNeverDrawn) { checkSampler(5, 13, true); }

TEST(PermutationSampler, WrongProbabilitiesFailTheSameTest) {
  // A sampler that ignores the matrix (uniform permutations) must be caught by the harness.
  const TargetMatrix q = randomMatrix(4, 11, false);
  const auto exact = bruteForce(q);
  std::map<std::vector<int>, double> counts;
  Rng rng(5);
  const int draws = 200000;
  for (int n = 0; n < draws; ++n) {
    std::vector<int> o = {0, 1, 2, 3};
    for (int i = 3; i > 0; --i) std::swap(o[size_t(i)], o[rng.below(uint32_t(i + 1))]);
    counts[o] += 1.0;
  }
  std::vector<double> observed, expected;
  for (const auto& [perm, p] : exact) {
    observed.push_back(counts[perm]);
    expected.push_back(p * draws);
  }
  EXPECT_FALSE(test::chiSquareTest(observed, expected).passes(0.001));
}

TEST(PermutationSampler, SurvivesTargetsOfVeryDifferentScales) {
  TargetMatrix q(8);
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 8; ++k) q(i, k) = std::pow(10.0, -30.0 * i + (i == k ? 0.0 : -1.0));
  const PermutationSampler sampler(q);
  Rng rng(3);
  for (int n = 0; n < 100; ++n) {
    std::vector<int> o = sampler.sample(rng);
    std::sort(o.begin(), o.end());
    for (int k = 0; k < 8; ++k) ASSERT_EQ(o[size_t(k)], k) << "not a permutation";
  }
}

TEST(PermutationSampler, RejectsLaddersBeyondTwelveLevels) {
  EXPECT_THROW(PermutationSampler{TargetMatrix(13)}, std::invalid_argument);
}
