// Image comparison: RMSE and relative MSE against hand-computed values, size mismatch is an error.
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
