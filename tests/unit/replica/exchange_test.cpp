// Exchange moves: their bookkeeping, and that each keeps every level's marginal distribution on a
// synthetic 1-D family (chi-square per level), while a deliberately wrong move is caught.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "chi_square.h"
#include "replica/exchange.h"
#include "toy_ladder.h"

using namespace relt;

TEST(SwapAcceptance, IsTheMetropolisRatioOfTheSwappedProducts) {
  TargetMatrix q(2);
  q(0, 0) = 4.0, q(1, 1) = 1.0, q(0, 1) = 1.0, q(1, 0) = 2.0;
  EXPECT_DOUBLE_EQ(swapAcceptance(q, 0, 1), 0.5);
  q(0, 1) = 3.0;
  EXPECT_DOUBLE_EQ(swapAcceptance(q, 0, 1), 1.0);
  q(1, 0) = 0.0;
  EXPECT_EQ(swapAcceptance(q, 0, 1), 0.0) << "never towards a zero target";
  q(1, 0) = 1.0, q(1, 1) = 0.0;
  EXPECT_EQ(swapAcceptance(q, 0, 1), 1.0) << "always away from a zero target";
  q(1, 0) = NAN;
  EXPECT_EQ(swapAcceptance(q, 0, 1), 0.0);
}

// Rows divided by their normalisers: acceptance ratios stay, and a row whose normaliser is not a
// positive number stays as it is.
TEST(TargetMatrix, NormalisedRowsKeepTheSwapAcceptance) {
  TargetMatrix q(3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) q(i, j) = 1.0 + i + 2.0 * j * j;
  TargetMatrix n = q;
  n.normaliseRows({4.0, 0.0, 0.5});
  EXPECT_DOUBLE_EQ(n(0, 2), q(0, 2) / 4.0);
  EXPECT_DOUBLE_EQ(n(1, 2), q(1, 2)) << "b = 0: left as it is";
  EXPECT_DOUBLE_EQ(n(2, 1), q(2, 1) * 2.0);
  for (auto [i, j] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}})
    EXPECT_NEAR(swapAcceptance(n, i, j), swapAcceptance(q, i, j), 1e-15);
}

namespace {
TargetMatrix ones(int m) {
  TargetMatrix q(m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) q(i, j) = 1.0;
  return q;
}
}  // namespace

TEST(ExchangeMoves, DeoSwapsEvenPairsOnEvenRoundsAndOddPairsOnOddRounds) {
  Rng rng(1);
  ExchangeTally tally(5);
  const ExchangeOptions deo{ExchangeMove::Deo};
  EXPECT_EQ(exchangeLevels(deo, ones(5), 0, rng, &tally), (std::vector<int>{1, 0, 3, 2, 4}));
  EXPECT_EQ(exchangeLevels(deo, ones(5), 1, rng, &tally), (std::vector<int>{0, 2, 1, 4, 3}));
  for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(tally.adjacentAcceptance(k), 1.0);
  EXPECT_EQ(tally.rounds, 2u);
  EXPECT_DOUBLE_EQ(tally.changeRate(0), 0.5);
}

TEST(ExchangeMoves, NeighbourSweepsThePairsFromTheTopDown) {
  // Every swap accepted: the top state travels to level 0, every other moves up by one.
  Rng rng(2);
  ExchangeTally tally(5);
  EXPECT_EQ(exchangeLevels({ExchangeMove::Neighbour}, ones(5), 0, rng, &tally), (std::vector<int>{4, 0, 1, 2, 3}));
  for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(tally.adjacentAcceptance(k), 1.0);
}

TEST(ExchangeMoves, NothingMovesWhenEveryExchangeWouldReachAZeroTarget) {
  TargetMatrix q(4);
  for (int i = 0; i < 4; ++i) q(i, i) = 1.0;  // each level's target is zero on the other states
  for (ExchangeMove m : {ExchangeMove::Neighbour, ExchangeMove::Deo, ExchangeMove::Permutation, ExchangeMove::Swap,
                         ExchangeMove::Eem}) {
    Rng rng(3);
    for (int round = 0; round < 20; ++round)
      EXPECT_EQ(exchangeLevels({m}, q, round, rng), (std::vector<int>{0, 1, 2, 3})) << exchangeMoveName(m);
  }
}

TEST(ExchangeMoves, NamesRoundTrip) {
  for (ExchangeMove m : {ExchangeMove::Neighbour, ExchangeMove::Deo, ExchangeMove::Permutation, ExchangeMove::Swap,
                         ExchangeMove::Eem})
    EXPECT_EQ(parseExchangeMove(exchangeMoveName(m)), m);
  EXPECT_FALSE(parseExchangeMove("bogus"));
}

TEST(RoundTrips, CountsBottomTopBottom) {
  RoundTrips trips(2, 4);
  for (int level : {2, 3, 0, 1, 3, 2, 0, 3, 0}) trips.visit(0, level);
  for (int level : {3, 0, 3}) trips.visit(1, level);
  EXPECT_EQ(trips.trips(0), 2u);
  EXPECT_EQ(trips.trips(1), 0u);
  EXPECT_EQ(trips.total(), 2u);
}

// ---- Every move keeps each level's marginal ---------------------------------------------------
namespace {

constexpr int kLevels = 4;
double sigma(int level) { return 0.04 * std::sqrt(std::pow(50.0, level / 3.0)); }
// Two bumps, widened with the level as tempering widens a glossy lobe.
double toyTarget(int level, double u) {
  auto bump = [&](double c) { return std::exp(-0.5 * std::pow((u - c) / sigma(level), 2)); };
  return u >= 0.0 && u < 1.0 ? 0.7 * bump(0.25) + 0.3 * bump(0.75) : 0.0;
}

// Each level's target tabulated on a fine grid: exact starting states and expected histograms.
struct Tabulated {
  static constexpr int kCells = 20000;
  explicit Tabulated(int level) : cdf(kCells + 1, 0.0) {
    for (int c = 0; c < kCells; ++c) cdf[size_t(c + 1)] = cdf[size_t(c)] + toyTarget(level, (c + 0.5) / kCells);
    for (double& v : cdf) v /= cdf.back();
  }
  double sample(Rng& rng) const {
    const double xi = rng.uniformDouble();
    const size_t c = size_t(std::upper_bound(cdf.begin(), cdf.end(), xi) - cdf.begin()) - 1;
    return (double(std::min<size_t>(c, kCells - 1)) + rng.uniformDouble()) / kCells;
  }
  double mass(double a, double b) const { return cdf[size_t(std::lround(b * kCells))] - cdf[size_t(std::lround(a * kCells))]; }
  std::vector<double> cdf;
};

// Runs many independent ladders started in their exact product distribution for a few rounds of
// local mutations and exchanges; returns the smallest p-value of the per-level chi-square tests.
double worstLevelPValue(const test::ToyExchange& move, std::string* report) {
  std::vector<Tabulated> tables;
  for (int k = 0; k < kLevels; ++k) tables.emplace_back(k);
  const int ladders = 20000, rounds = 8, bins = 20;
  std::vector<std::vector<double>> hist(kLevels, std::vector<double>(bins, 0.0));
  auto targets = [](const test::ToyPoint& u, std::vector<double>& q) {
    for (int k = 0; k < kLevels; ++k) q[size_t(k)] = toyTarget(k, u[0]);
  };
  for (int l = 0; l < ladders; ++l) {
    Rng init(hashKey(41, l));
    std::vector<test::ToyPoint> starts;
    for (int k = 0; k < kLevels; ++k) starts.push_back({tables[size_t(k)].sample(init)});
    test::ToyLadder ladder(targets, test::kelemenProposal(0.0), starts, hashKey(42, l));
    for (int r = 0; r < rounds; ++r) {
      ladder.mutate();
      ladder.exchange(move);
    }
    for (int k = 0; k < kLevels; ++k)
      hist[size_t(k)][size_t(std::min(bins - 1, int(ladder.state(k)[0] * bins)))] += 1.0;
  }
  double worst = 1.0;
  for (int k = 0; k < kLevels; ++k) {
    std::vector<double> expected(bins);
    for (int b = 0; b < bins; ++b) expected[size_t(b)] = ladders * tables[size_t(k)].mass(double(b) / bins, double(b + 1) / bins);
    const test::ChiSquareResult r = test::chiSquareTest(hist[size_t(k)], expected);
    if (report) *report += "level " + std::to_string(k) + ": " + r.describe() + "\n";
    worst = std::min(worst, r.error.empty() ? r.pValue : 0.0);
  }
  return worst;
}

}  // namespace

class MarginalTest : public testing::TestWithParam<ExchangeMove> {};

TEST_P(MarginalTest, EveryLevelKeepsItsTarget) {
  std::string report;
  // 4 levels, one test each: a per-test threshold of 0.001 keeps false alarms near 0.4 %.
  EXPECT_GT(worstLevelPValue(test::standardExchange({GetParam()}), &report), 0.001) << report;
}

INSTANTIATE_TEST_SUITE_P(AllMoves, MarginalTest,
                         testing::Values(ExchangeMove::Neighbour, ExchangeMove::Deo, ExchangeMove::Permutation,
                                         ExchangeMove::Swap, ExchangeMove::Eem),
                         [](const testing::TestParamInfo<ExchangeMove>& info) {
                           return std::string(exchangeMoveName(info.param));
                         });

TEST(MarginalTest, AMoveThatIgnoresTheTargetsIsCaught) {
  // Always swapping the deo pairs, without the Metropolis test, mixes the levels' distributions.
  auto alwaysSwap = [](const TargetMatrix& q, uint64_t round, Rng&) {
    std::vector<int> from(static_cast<size_t>(q.levels()));
    for (int k = 0; k < q.levels(); ++k) from[size_t(k)] = k;
    for (int k = int(round % 2); k + 1 < q.levels(); k += 2) std::swap(from[size_t(k)], from[size_t(k + 1)]);
    return from;
  };
  EXPECT_LT(worstLevelPValue(alwaysSwap, nullptr), 1e-6);
}
