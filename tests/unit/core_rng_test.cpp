// Random streams: the streams of one key must be independent of each other, as every sample
// source draws its camera, light and connection numbers from streams 0, 1 and 2 of one key.
#include <gtest/gtest.h>

#include <array>

#include "core/rng.h"
#include "core/sample_source.h"

using namespace relt;

namespace {

// Chi-square of the joint 16 x 16 histogram of (a, b) pairs drawn for `count` keys.
template <class Draw>
double jointChiSquare(int count, Draw draw) {
  constexpr int kBins = 16;
  std::array<std::array<int, kBins>, kBins> histogram{};
  for (int i = 0; i < count; ++i) {
    const auto [a, b] = draw(hashKey(12345, uint64_t(i)));
    ++histogram[size_t(a * kBins)][size_t(b * kBins)];
  }
  const double expected = double(count) / (kBins * kBins);
  double chi = 0.0;
  for (const auto& row : histogram)
    for (int c : row) chi += (c - expected) * (c - expected) / expected;
  return chi;
}

// 255 degrees of freedom: the 1e-6 upper quantile is about 390.
constexpr double kChiSquareBound = 390.0;
constexpr int kKeys = 1 << 20;

}  // namespace

TEST(Rng, TheFirstNumbersOfTwoStreamsOfOneKeyAreIndependent) {
  for (uint64_t other = 1; other < 3; ++other) {
    const double chi = jointChiSquare(kKeys, [&](uint64_t key) {
      Rng a(key, 0), b(key, other);
      return std::pair{a.uniform(), b.uniform()};
    });
    EXPECT_LT(chi, kChiSquareBound) << "streams 0 and " << other;
  }
}

TEST(Rng, TheNthNumbersOfTwoStreamsOfOneKeyAreIndependent) {
  const double chi = jointChiSquare(kKeys, [](uint64_t key) {
    Rng a(key, 0), b(key, 1);
    for (int i = 0; i < 4; ++i) {
      a.uniform();
      b.uniform();
    }
    return std::pair{a.uniform(), b.uniform()};
  });
  EXPECT_LT(chi, kChiSquareBound);
}

// pt draws its film position from the camera stream and its light sample from the light stream.
TEST(IndependentSource, CameraAndLightStreamsAreIndependent) {
  const double chi = jointChiSquare(kKeys, [](uint64_t key) {
    IndependentSource source(key);
    const float camera = source.next(SampleStream::Camera);
    return std::pair{camera, source.next(SampleStream::Light)};
  });
  EXPECT_LT(chi, kChiSquareBound);
}

TEST(Rng, ConsecutiveKeysGiveIndependentFirstNumbers) {
  const double chi = jointChiSquare(kKeys, [](uint64_t key) {
    Rng a(key, 0), b(key + 1, 0);
    return std::pair{a.uniform(), b.uniform()};
  });
  EXPECT_LT(chi, kChiSquareBound);
}
