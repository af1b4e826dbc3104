// Film: box-filter splatting into floor(x), floor(y), off-film and non-finite samples, and resolve.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "film/film.h"
#include "render/renderer.h"

using namespace relt;

namespace {

// Sum of r, g, b of one pixel.
const double* pixel(const Film& film, int x, int y) { return &film.data()[3 * (size_t(y) * film.width() + x)]; }

double total(const Film& film) {
  double sum = 0.0;
  for (double v : film.data()) sum += v;
  return sum;
}

PathSample sampleOf(std::initializer_list<Splat> splats) {
  PathSample s;
  s.splats = splats;
  return s;
}

}  // namespace

// All values below are small binary fractions: every sum is exact, so the checks use ==.

TEST(Film, StartsBlackWithRowMajorLayout) {
  const Film film(5, 3);
  EXPECT_EQ(film.width(), 5);
  EXPECT_EQ(film.height(), 3);
  EXPECT_EQ(film.data().size(), 45u);
  EXPECT_EQ(total(film), 0.0);
  EXPECT_EQ(film.droppedSamples(), 0u);
}

TEST(Film, SplatLandsInFloorOfItsPosition) {
  Film film(5, 3);
  // Corners and interior of pixel (3, 1): every position in [3, 4) x [1, 2) belongs to it.
  for (const Vec2 p : {Vec2(3.0f, 1.0f), Vec2(3.5f, 1.25f), Vec2(3.999f, 1.999f)})
    film.addSplat(p, Color(1.0f, 2.0f, 4.0f), 1.0);
  const double* px = pixel(film, 3, 1);
  EXPECT_EQ(px[0], 3.0);
  EXPECT_EQ(px[1], 6.0);
  EXPECT_EQ(px[2], 12.0);
  EXPECT_EQ(total(film), 21.0);  // nothing leaked into a neighbour
}

TEST(Film, EachPixelOfANonSquareFilmIsAddressable) {
  // Distinct value per pixel at its centre: catches swapped x/y or a wrong row stride.
  Film film(4, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) film.addSplat(Vec2(x + 0.5f, y + 0.5f), Color(float(10 * y + x)), 1.0);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_EQ(pixel(film, x, y)[1], 10.0 * y + x) << x << "," << y;
}

TEST(Film, WeightScalesTheSplat) {
  Film film(2, 2);
  film.addSplat(Vec2(1.5f, 0.5f), Color(2.0f, 4.0f, 8.0f), 0.25);
  EXPECT_EQ(pixel(film, 1, 0)[0], 0.5);
  EXPECT_EQ(pixel(film, 1, 0)[1], 1.0);
  EXPECT_EQ(pixel(film, 1, 0)[2], 2.0);
}

TEST(Film, PositionsAtOrBeyondTheFarEdgesAreIgnored) {
  Film film(4, 3);
  for (const Vec2 p : {Vec2(4.0f, 1.0f), Vec2(1.0f, 3.0f), Vec2(4.5f, 3.5f), Vec2(-1.0f, 1.0f), Vec2(1.0f, -1.0f),
                       Vec2(-2.5f, -2.5f), Vec2(100.0f, 0.0f)})
    film.addSplat(p, Color(1.0f), 1.0);
  EXPECT_EQ(total(film), 0.0);
}

TEST(Film, PositionsJustLeftOrAboveTheFilmAreIgnored) {
  // floor(-0.5) = -1 is outside the film: a one-pixel box filter gives these splats to no pixel.
  Film film(4, 3);
  for (const Vec2 p : {Vec2(-0.5f, 1.5f), Vec2(1.5f, -0.5f), Vec2(-0.25f, -0.75f)}) film.addSplat(p, Color(1.0f), 1.0);
  EXPECT_EQ(total(film), 0.0);
}

TEST(Film, AddSampleAddsEverySplatScaledByWeight) {
  Film film(3, 2);
  const PathSample s = sampleOf({{Vec2(0.5f, 0.5f), Color(1.0f, 0.0f, 0.0f), PathClass::L1},
                                 {Vec2(2.5f, 1.5f), Color(0.0f, 2.0f, 0.0f), PathClass::L2},
                                 {Vec2(0.25f, 0.75f), Color(0.0f, 0.0f, 4.0f), PathClass::L4}});
  EXPECT_TRUE(film.addSample(s, 0.5));
  EXPECT_EQ(pixel(film, 0, 0)[0], 0.5);
  EXPECT_EQ(pixel(film, 0, 0)[2], 2.0);  // two splats of one sample share pixel (0, 0)
  EXPECT_EQ(pixel(film, 2, 1)[1], 1.0);
  EXPECT_EQ(total(film), 3.5);
  EXPECT_EQ(film.droppedSamples(), 0u);
}

TEST(Film, NonFiniteSampleIsDroppedWholeAndCounted) {
  Film film(3, 2);
  film.addSplat(Vec2(1.5f, 0.5f), Color(1.0f), 1.0);
  const std::vector<double> before = film.data();
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (const Color bad : {Color(nan, 0.0f, 0.0f), Color(0.0f, inf, 0.0f), Color(0.0f, 0.0f, -inf)}) {
    // A good splat first: it must not be added either (the sample is dropped whole).
    const PathSample s =
        sampleOf({{Vec2(1.5f, 0.5f), Color(1.0f), PathClass::L1}, {Vec2(0.5f, 1.5f), bad, PathClass::L2}});
    EXPECT_FALSE(film.addSample(s));
  }
  EXPECT_EQ(film.droppedSamples(), 3u);
  EXPECT_EQ(film.data(), before);
  // A finite sample afterwards is still accepted and not counted.
  EXPECT_TRUE(film.addSample(sampleOf({{Vec2(0.5f, 0.5f), Color(1.0f), PathClass::L1}})));
  EXPECT_EQ(film.droppedSamples(), 3u);
}

TEST(Film, PathSampleKeepsNonFiniteValuesSoTheFilmCanDropThem) {
  // PathSample::add skips black splats but must keep NaN ones, or the film could not count them.
  PathSample s;
  s.add(Vec2(0.5f), Color(0.0f), PathClass::L1);
  s.add(Vec2(0.5f), Color(std::numeric_limits<float>::quiet_NaN()), PathClass::L1);
  ASSERT_EQ(s.splats.size(), 1u);
  Film film(1, 1);
  EXPECT_FALSE(film.addSample(s));
  EXPECT_EQ(film.droppedSamples(), 1u);
}

TEST(Film, ResolveDividesSumsBySamplesPerPixel) {
  Film film(2, 1);
  for (int i = 0; i < 4; ++i) film.addSplat(Vec2(0.5f, 0.5f), Color(1.0f, 2.0f, 3.0f), 1.0);
  film.addSplat(Vec2(1.5f, 0.5f), Color(6.0f), 1.0);
  const Image image = Renderer::resolve(film, film.data(), 4.0);
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.height, 1);
  ASSERT_EQ(image.rgb.size(), 6u);
  const std::vector<float> expected = {1.0f, 2.0f, 3.0f, 1.5f, 1.5f, 1.5f};
  EXPECT_EQ(image.rgb, expected);
}

TEST(Film, ResolveWithZeroSamplesGivesBlackNotNaN) {
  Film film(1, 1);
  film.addSplat(Vec2(0.5f, 0.5f), Color(1.0f), 1.0);
  const Image image = Renderer::resolve(film, film.data(), 0.0);
  for (float v : image.rgb) EXPECT_EQ(v, 0.0f);
}
