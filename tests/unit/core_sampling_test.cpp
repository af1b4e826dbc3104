#include <gtest/gtest.h>

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
