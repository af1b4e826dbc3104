#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/rng.h"

#include "core/sampling.h"

using namespace relt;

TEST(Distribution1D, SamplesInProportionToWeightsAndSkipsZeros) {
  Distribution1D d({1.0, 0.0, 3.0});
  EXPECT_FLOAT_EQ(d.pmf(0), 0.25f);
  EXPECT_FLOAT_EQ(d.pmf(1), 0.0f);
  int counts[3] = {0, 0, 0};
  const int n = 40000;
  for (int i = 0; i < n; ++i) counts[d.sample((i + 0.5f) / n)]++;
  EXPECT_EQ(counts[1], 0);
  EXPECT_NEAR(counts[0] / double(n), 0.25, 1e-3);
  EXPECT_NEAR(counts[2] / double(n), 0.75, 1e-3);
}

TEST(Distribution1D, RemappedNumberIsUniformWithinTheChosenBin) {
  Distribution1D d({1.0, 1.0});
  float r = -1.0f;
  EXPECT_EQ(d.sample(0.75f, &r), 1u);
  EXPECT_NEAR(r, 0.5f, 1e-6f);
}

TEST(Distribution1D, BranchlessSearchPicksTheUpperBoundEntry) {
  // Reference: the first entry whose upper CDF bound exceeds u * total (std::upper_bound),
  // stepped back over zero weights. Sizes 1-40, zeros included, u on and between CDF bounds.
  Rng rng(7);
  for (int n = 1; n <= 40; ++n) {
    std::vector<double> w(size_t(n), 0.0);
    for (double& x : w) x = rng.uniform() < 0.25f ? 0.0 : rng.uniform();
    w[rng.below(uint32_t(n))] = 1.0;
    const Distribution1D d(w);
    std::vector<double> cdf(1, 0.0);
    for (double x : w) cdf.push_back(cdf.back() + x);
    std::vector<float> us = {0.0f, 0x1.fffffep-1f};
    for (int i = 0; i < 200; ++i) us.push_back(rng.uniform());
    for (double c : cdf) us.push_back(static_cast<float>(c / cdf.back()));
    for (float u : us) {
      if (!(u < 1.0f)) continue;
      const double target = double(u) * cdf.back();
      size_t expected = std::min(size_t(std::upper_bound(cdf.begin() + 1, cdf.end(), target) - cdf.begin() - 1), w.size() - 1);
      while (w[expected] == 0.0 && expected > 0) --expected;
      EXPECT_EQ(d.sample(u), expected) << "n " << n << " u " << u;
    }
  }
  // A target exactly on a bound belongs to the entry above it.
  const Distribution1D exact({1.0, 1.0, 2.0});
  EXPECT_EQ(exact.sample(0.25f), 1u);
  EXPECT_EQ(exact.sample(0.5f), 2u);
  // Without any weight the pick is still an index of the table (the first).
  const Distribution1D none({0.0, 0.0, 0.0});
  for (float u : {0.0f, 0.5f, 0x1.fffffep-1f}) EXPECT_EQ(none.sample(u), 0u);
}

TEST(Warps, PolynomialCosSinMatchesLibmOnTheQuarterPiRange) {
  // Taylor truncation error is below 3e-7 on |x| <= pi/4; allow float round-off on top.
  for (int i = 0; i <= 10000; ++i) {
    const float x = -kPi / 4.0f + (kPi / 2.0f) * i / 10000.0f;
    const Vec2 cs = cosSinQuarterPi(x);
    EXPECT_NEAR(cs.x, std::cos(static_cast<double>(x)), 5e-7) << x;
    EXPECT_NEAR(cs.y, std::sin(static_cast<double>(x)), 5e-7) << x;
  }
}

TEST(Warps, ConcentricDiskMatchesShirleyChiuWithLibmTrigonometry) {
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const Vec2 u((i + 0.37f) / 64.0f, (j + 0.61f) / 64.0f);
      const double ox = 2.0 * u.x - 1.0, oy = 2.0 * u.y - 1.0;
      double r, theta;
      if (std::abs(ox) > std::abs(oy)) {
        r = ox;
        theta = kPi / 4.0 * (oy / ox);
      } else {
        r = oy;
        theta = kPi / 2.0 - kPi / 4.0 * (ox / oy);
      }
      const Vec2 d = concentricDisk(u);
      EXPECT_NEAR(d.x, r * std::cos(theta), 1e-6) << u.x << " " << u.y;
      EXPECT_NEAR(d.y, r * std::sin(theta), 1e-6) << u.x << " " << u.y;
    }
}
