#include <gtest/gtest.h>

#include <cmath>

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
