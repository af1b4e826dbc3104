// ERPT's proposed-mutations filter: pixel scaled by box-blurred / actual proposal count.
#include <gtest/gtest.h>

#include "mcmc/erpt.h"

using namespace relt;

TEST(ErptProposalFilter, UniformTallyLeavesTheImageAndAnOutlierIsScaledByExpectedOverActual) {
  Image image(5, 5);
  for (float& v : image.rgb) v = 1.0f;
  std::vector<double> tally(25, 4.0);
  applyProposalFilter(image, tally, 1);
  for (float v : image.rgb) EXPECT_FLOAT_EQ(v, 1.0f);

  tally[12] = 13.0;  // centre pixel: 9 more proposals than its neighbours
  applyProposalFilter(image, tally, 1);
  // Centre: 3x3 mean = (8 * 4 + 13) / 9 = 5, scale 5 / 13. A neighbour at the border of the window:
  // (x, y) = (1, 1) sees the centre too: mean 5, scale 5 / 4. A corner pixel (0, 0): 2x2 window of 4s.
  EXPECT_NEAR(image.rgb[3 * 12], 5.0 / 13.0, 1e-6);
  EXPECT_NEAR(image.rgb[3 * 6], 5.0 / 4.0, 1e-6);
  EXPECT_NEAR(image.rgb[0], 1.0, 1e-6);
}

TEST(ErptProposalFilter, PixelsWithoutProposalsAreLeftAlone) {
  Image image(3, 1);
  image.rgb = {1, 1, 1, 2, 2, 2, 3, 3, 3};
  applyProposalFilter(image, {0.0, 0.0, 0.0}, 1);
  EXPECT_EQ(image.rgb, (std::vector<float>{1, 1, 1, 2, 2, 2, 3, 3, 3}));
}
