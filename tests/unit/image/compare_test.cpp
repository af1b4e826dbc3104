// Image comparison and averaging: RMSE and relative MSE against hand-computed values, pixel means; size mismatch is an error.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "image/compare.h"

using namespace relt;

TEST(CompareImages, RmseRelativeMseAndMeansMatchHandComputedValues) {
  Image a(2, 1), b(2, 1);
  a.rgb = {1, 1, 1, 0, 0, 0};
  b.rgb = {0, 0, 0, 0, 0, 3};
  const ImageComparison c = compareImages(a, b);
  // Squared errors: 1, 1, 1, 0, 0, 9 -> mean 2; relative: 3 x 1/0.01 + 9/9.01.
  EXPECT_NEAR(c.rmse, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(c.relMse, (300.0 + 9.0 / 9.01) / 6.0, 1e-9);
  EXPECT_NEAR(c.meanA, 0.5, 1e-12);
  EXPECT_NEAR(c.meanB, 0.5, 1e-12);
  const Image d = signedDifference(a, b);
  EXPECT_EQ(d.rgb, (std::vector<float>{1, 1, 1, 0, 0, -3}));
  EXPECT_EQ(compareImages(a, a).rmse, 0.0);
}

TEST(CompareImages, DifferentSizesAreAnInputErrorNamingBoth) {
  try {
    compareImages(Image(2, 2), Image(3, 2), "x.exr", "ref.exr");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("x.exr"), std::string::npos) << m;
    EXPECT_NE(m.find("ref.exr"), std::string::npos) << m;
  }
}

TEST(AverageImages, MeanPixelByPixel) {
  Image a(2, 1), b(2, 1), c(2, 1);
  a.rgb = {1, 2, 3, 0, 0, 0};
  b.rgb = {3, 2, 1, 0, 0, 6};
  c.rgb = {2, 2, 2, 3, 0, 0};
  EXPECT_EQ(averageImages({a, b, c}, {}).rgb, (std::vector<float>{2, 2, 2, 1, 0, 2}));
  EXPECT_EQ(averageImages({a}, {}).rgb, a.rgb);
}

TEST(AverageImages, WeightedMeanCombinesRendersOfUnequalTime) {
  Image a(1, 1), b(1, 1);
  a.rgb = {1, 4, 0};
  b.rgb = {4, 1, 3};
  // 2 s and 1 s: the mean of a 3 s render.
  EXPECT_EQ(averageImages({a, b}, {}, {2.0, 1.0}).rgb, (std::vector<float>{2, 3, 1}));
  EXPECT_EQ(averageImages({a, b}, {}, {5.0, 5.0}).rgb, averageImages({a, b}, {}).rgb);
}

TEST(AverageImages, WeightsThatDoNotFitTheImagesAreAnInputError) {
  const Image a(1, 1), b(1, 1);
  EXPECT_THROW(averageImages({a, b}, {}, {1.0}), InputError);
  EXPECT_THROW(averageImages({a, b}, {}, {1.0, 0.0}), InputError);
  EXPECT_THROW(averageImages({a, b}, {}, {1.0, -2.0}), InputError);
  EXPECT_THROW(averageImages({a, b}, {}, {1.0, std::nan("")}), InputError);
}

TEST(AverageImages, ASizeDifferentFromTheFirstIsAnInputErrorNamingBoth) {
  try {
    averageImages({Image(2, 2), Image(2, 2), Image(2, 3)}, {"a.exr", "b.exr", "c.exr"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("c.exr"), std::string::npos) << m;
    EXPECT_NE(m.find("a.exr"), std::string::npos) << m;
    EXPECT_NE(m.find("2x3"), std::string::npos) << m;
  }
  EXPECT_THROW(averageImages({}, {}), InputError);
}
