// The synthetic replica-exchange benchmark of thesis Sec. 5.3.7, scenario 1 (thesis digest §6.2):
// a 2-D mixture of 50 narrow Gaussians on [0,1]^2, 8 levels with covariances scaled by T
// (log-spaced 1..2500, the analogue of roughening by sqrt(T)), Kelemen small and large steps with
// p_large 0.3, 10 000 samples of the level-0 chain after 1 000 of burn-in. Plain Metropolis misses
// a large share of the modes (thesis Table 5.1: 55 %); with any exchange move none should be missed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "replica/exchange.h"
#include "toy_ladder.h"

using namespace relt;

namespace {

constexpr int kModes = 50, kLevels = 8, kBurnIn = 1000, kSamples = 10000, kSeeds = 10;

struct Mode {
  double cx, cy;
  double a, b, c;  // inverse covariance [[a, b], [b, c]]
  double norm;     // 1 / (2 pi sqrt(det))
};

std::vector<Mode> randomMixture(uint64_t seed) {
  Rng rng(seed, 17);
  std::vector<Mode> modes;
  for (int m = 0; m < kModes; ++m) {
    Mode d;
    d.cx = 0.05 + 0.9 * rng.uniformDouble();
    d.cy = 0.05 + 0.9 * rng.uniformDouble();
    // Glossy lobes: standard deviations 0.002..0.01, random orientation.
    const double s1 = 0.002 * std::pow(5.0, rng.uniformDouble()), s2 = 0.002 * std::pow(5.0, rng.uniformDouble());
    const double t = 3.14159265358979 * rng.uniformDouble(), ct = std::cos(t), st = std::sin(t);
    const double i1 = 1.0 / (s1 * s1), i2 = 1.0 / (s2 * s2);
    d.a = ct * ct * i1 + st * st * i2;
    d.b = ct * st * (i1 - i2);
    d.c = st * st * i1 + ct * ct * i2;
    d.norm = 1.0 / (2.0 * 3.14159265358979 * s1 * s2);
    modes.push_back(d);
  }
  return modes;
}

double temperature(int level) { return std::pow(2500.0, level / double(kLevels - 1)); }

double mahalanobis2(const Mode& d, double x, double y) {
  const double dx = x - d.cx, dy = y - d.cy;
  return d.a * dx * dx + 2.0 * d.b * dx * dy + d.c * dy * dy;
}

struct RunResult {
  double missedShare = 0.0;
  double changeRate = 0.0;  // exchanges: share of rounds after which level 0 held another state
};

// One run: `levels` chains (1 = plain Metropolis), exchanges after every sweep when levels > 1.
RunResult run(const std::vector<Mode>& modes, int levels, const ExchangeOptions& options, uint64_t seed) {
  auto targets = [&](const test::ToyPoint& u, std::vector<double>& q) {
    std::fill(q.begin(), q.end(), 0.0);
    if (u[0] < 0.0 || u[0] >= 1.0 || u[1] < 0.0 || u[1] >= 1.0) return;
    for (const Mode& d : modes) {
      const double r2 = mahalanobis2(d, u[0], u[1]);
      for (int k = 0; k < levels; ++k) {
        const double t = temperature(k);
        q[size_t(k)] += d.norm / t * std::exp(-0.5 * r2 / t);
      }
    }
  };
  Rng init(seed, 5);
  std::vector<test::ToyPoint> starts;
  for (int k = 0; k < levels; ++k) starts.push_back({init.uniformDouble(), init.uniformDouble()});
  test::ToyLadder ladder(targets, test::kelemenProposal(0.3), starts, hashKey(seed, 6));
  const test::ToyExchange exchange = test::standardExchange(options);
  std::vector<bool> visited(kModes, false);
  uint64_t changed = 0;
  for (int i = 0; i < kBurnIn + kSamples; ++i) {
    ladder.mutate();
    if (levels > 1) changed += ladder.exchange(exchange)[0] != 0;
    if (i < kBurnIn) continue;
    // The sample belongs to the mode of highest density there.
    const test::ToyPoint& u = ladder.state(0);
    int best = 0;
    double bestDensity = -1.0;
    for (int m = 0; m < kModes; ++m) {
      const double p = modes[size_t(m)].norm * std::exp(-0.5 * mahalanobis2(modes[size_t(m)], u[0], u[1]));
      if (p > bestDensity) bestDensity = p, best = m;
    }
    visited[size_t(best)] = true;
  }
  RunResult r;
  r.missedShare = double(std::count(visited.begin(), visited.end(), false)) / kModes;
  r.changeRate = double(changed) / double(kBurnIn + kSamples);
  return r;
}

RunResult averageOverSeeds(int levels, const ExchangeOptions& options) {
  RunResult mean;
  for (int s = 0; s < kSeeds; ++s) {
    const RunResult r = run(randomMixture(1000 + s), levels, options, 2000 + s);
    mean.missedShare += r.missedShare / kSeeds;
    mean.changeRate += r.changeRate / kSeeds;
  }
  return mean;
}

}  // namespace

TEST(SyntheticMixture, PlainMetropolisMissesManyModes) {
  const RunResult r = averageOverSeeds(1, {});
  std::printf("plain Metropolis: %.1f %% of modes missed\n", 100.0 * r.missedShare);
  EXPECT_GT(r.missedShare, 0.25);
}

class MixtureExchangeTest : public testing::TestWithParam<ExchangeMove> {};

TEST_P(MixtureExchangeTest, MissesNoMode) {
  const RunResult r = averageOverSeeds(kLevels, {GetParam()});
  std::printf("%s: %.2f %% of modes missed, level 0 changed state after %.0f %% of exchanges\n",
              exchangeMoveName(GetParam()), 100.0 * r.missedShare, 100.0 * r.changeRate);
  EXPECT_EQ(r.missedShare, 0.0);
}

INSTANTIATE_TEST_SUITE_P(AllMoves, MixtureExchangeTest,
                         testing::Values(ExchangeMove::Neighbour, ExchangeMove::Deo, ExchangeMove::Permutation,
                                         ExchangeMove::Swap, ExchangeMove::Eem),
                         [](const testing::TestParamInfo<ExchangeMove>& info) {
                           return std::string(exchangeMoveName(info.param));
                         });
