// Kelemen small step: log-uniform size in (s1, s2], either sign, wrapped into [0, 1), symmetric.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "pss/kelemen.h"

using namespace relt;

namespace {

// Signed displacement on the circle [0, 1), in (-1/2, 1/2].
double displacement(double from, double to) {
  double d = to - from;
  if (d > 0.5) d -= 1.0;
  if (d <= -0.5) d += 1.0;
  return d;
}

}  // namespace

TEST(KelemenSmallStep, SizeIsLogUniformBetweenS1AndS2WithEitherSign) {
  const KelemenSizes sizes;
  Rng rng(3);
  int up = 0;
  const int n = 100000, bins = 10;
  int hist[bins] = {};
  for (int i = 0; i < n; ++i) {
    const float u = 0.25f + 0.5f * rng.uniform();  // away from the wrap
    const double d = displacement(u, kelemenSmallStep(u, rng.uniform(), sizes));
    const double size = std::abs(d);
    ASSERT_GE(size, sizes.s1 * 0.999);
    ASSERT_LE(size, sizes.s2 * 1.001);
    up += d > 0.0;
    // log-uniform: log(size / s1) / log(s2 / s1) is uniform on [0, 1]
    const double t = std::log(size / sizes.s1) / std::log(double(sizes.s2) / sizes.s1);
    ++hist[std::min(bins - 1, std::max(0, static_cast<int>(t * bins)))];
  }
  // Binomial counts: 4 standard deviations of n p (1 - p).
  EXPECT_NEAR(up, n / 2, 4.0 * std::sqrt(n * 0.25));
  for (int b = 0; b < bins; ++b) EXPECT_NEAR(hist[b], n / bins, 4.0 * std::sqrt(n * 0.1 * 0.9)) << b;
}

TEST(KelemenSmallStep, WrapsAroundTheUnitInterval) {
  const KelemenSizes sizes;
  // xi = 0 is the largest step up (s2), xi = 1/2 the largest step down.
  EXPECT_NEAR(kelemenSmallStep(0.995f, 0.0f, sizes), 0.995f + sizes.s2 - 1.0f, 1e-6f);
  EXPECT_NEAR(kelemenSmallStep(0.005f, 0.5f, sizes), 0.005f - sizes.s2 + 1.0f, 1e-6f);
  // xi just below 1/2 is the smallest step up (s1).
  EXPECT_NEAR(kelemenSmallStep(0.5f, 0.4999999f, sizes), 0.5f + sizes.s1, 1e-6f);
  Rng rng(11);
  for (int i = 0; i < 100000; ++i) {
    const float v = kelemenSmallStep(i % 2 ? rng.uniform() * 1e-3f : 1.0f - rng.uniform() * 1e-3f, rng.uniform(), sizes);
    ASSERT_GE(v, 0.0f);
    ASSERT_LT(v, 1.0f);
  }
}

TEST(KelemenSmallStep, IsSymmetric) {
  // Symmetry q(u -> v) = q(v -> u): the displacement histogram is mirror-symmetric, tested bin by
  // bin (counts of +d and -d differ by no more than 4 standard deviations of their difference).
  const KelemenSizes sizes;
  Rng rng(7);
  const int bins = 16, n = 400000;
  std::vector<int> pos(bins, 0), neg(bins, 0);
  for (int i = 0; i < n; ++i) {
    const float u = rng.uniform();
    const double d = displacement(u, kelemenSmallStep(u, rng.uniform(), sizes));
    const int b = std::min(bins - 1, static_cast<int>(std::abs(d) / sizes.s2 * bins));
    (d > 0.0 ? pos : neg)[b]++;
  }
  for (int b = 0; b < bins; ++b) {
    const double sd = std::sqrt(double(pos[b] + neg[b]));
    EXPECT_NEAR(pos[b], neg[b], 4.0 * sd + 1.0) << "bin " << b;
  }
}

TEST(KelemenSmallStep, PrecomputedStepMatchesTheReference) {
  // The chains' fast step (polynomial 2^x) against the libm one: same kernel to 2e-5 relative in dv.
  for (const KelemenSizes sizes : {KelemenSizes{}, KelemenSizes{1.0f / 512.0f, 1.0f / 32.0f}}) {
    const KelemenStep fast(sizes);
    for (int i = 0; i < 10000; ++i) {
      const float u = 0.3f + 0.4f * (i % 97) / 97.0f, xi = (i + 0.5f) / 10000.0f;
      const float ref = kelemenSmallStep(u, xi, sizes), got = fast(u, xi);
      ASSERT_NEAR(got, ref, 2e-5f * std::abs(ref - u) + 1e-7f) << u << " " << xi;
    }
  }
  for (float e = -20.0f; e <= 0.0f; e += 0.01f) ASSERT_NEAR(exp2NonPositive(e), std::exp2(e), 2e-5f * std::exp2(e));
}
