// A camera sample stays on the pixel it was drawn for (camera/film_position.h): in float, pixel +
// offset can round up to the next pixel, and a pt sample of one row then lands in the next row,
// which may be another rank's or not yet rendered (a stop inside a pass showed it).
#include <gtest/gtest.h>

#include <cmath>

#include "camera/film_position.h"
#include "film/film.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

using namespace relt;

namespace {

constexpr float kLargestOffset = 1.0f - 0x1p-24f;  // the largest a uniform float in [0, 1) takes

}  // namespace

TEST(FilmPosition, AnOffsetBelowOneStaysOnItsPixel) {
  ASSERT_EQ(std::floor(365.0f + kLargestOffset), 366.0f) << "the rounding this guards against";
  for (int p = 0; p < 16384; ++p)
    for (float offset : {0.0f, 0.5f, 1.0f - 0x1p-16f, kLargestOffset}) {
      const float at = inPixel(p, offset);
      ASSERT_EQ(std::floor(at), float(p)) << p << " + " << offset;
      ASSERT_GE(at, float(p) + offset * 0.5f) << "moved more than the rounding";
    }
  const Vec2 corner = positionInPixel(1000, 700, Vec2(kLargestOffset, kLargestOffset));
  EXPECT_EQ(std::floor(corner.x), 1000.0f);
  EXPECT_EQ(std::floor(corner.y), 700.0f);
}

// Every row of a pt pass splats into that row only: the even rows of four passes leave the odd
// ones black. At 1024 x 768 about 24 of these samples round into the next row without the clamp.
TEST(FilmPosition, APtRowSplatsIntoThatRowOnly) {
  RenderSettings settings;
  settings.width = 1024;
  settings.height = 768;
  settings.maxDepth = 2;  // the furnace's light on every pixel, seen or reflected once
  settings.seed = 6;
  Renderer renderer(loadGltf(test::sourcePath("scenes/furnace.gltf")), settings);
  Film film(settings.width, settings.height);
  for (uint64_t pass = 0; pass < 4; ++pass)
    for (int row = 0; row < settings.height; row += 2) renderer.renderRow(RowEstimator::PathTracing, pass, row, film);
  const size_t rowSize = size_t(3) * settings.width;
  int litEven = 0, litOdd = 0;
  for (int row = 0; row < settings.height; ++row)
    for (size_t i = 0; i < rowSize; ++i)
      if (film.data()[row * rowSize + i] != 0.0) {
        (row % 2 ? litOdd : litEven)++;
        break;
      }
  EXPECT_EQ(litEven, settings.height / 2) << "an even row without light: the test would show nothing";
  EXPECT_EQ(litOdd, 0) << "rows with samples of the row above";
}
