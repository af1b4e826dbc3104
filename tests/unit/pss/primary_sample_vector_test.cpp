// The lazy primary-sample vector: small steps move every used coordinate a little, large steps
// redraw them, rejection restores the previous state bit for bit, and a state serialises exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "pss/primary_sample_vector.h"

using namespace relt;

namespace {

std::vector<float> draw(PrimarySampleVector& v, SampleStream s, int n) {
  std::vector<float> out;
  for (int i = 0; i < n; ++i) out.push_back(v.next(s));
  return out;
}

double circularDistance(float a, float b) {
  const double d = std::abs(double(a) - b);
  return std::min(d, 1.0 - d);
}

}  // namespace

TEST(PrimarySampleVector, SmallStepMovesEachCoordinateByAtMostS2) {
  PrimarySampleVector v(1);
  const std::vector<float> start = draw(v, SampleStream::Camera, 8);
  v.startIteration(false);
  const std::vector<float> moved = draw(v, SampleStream::Camera, 8);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NE(moved[i], start[i]);
    EXPECT_LE(circularDistance(moved[i], start[i]), KelemenSizes{}.s2 * 1.0001);
  }
}

TEST(PrimarySampleVector, StreamsAreIndependentLists) {
  PrimarySampleVector v(2);
  draw(v, SampleStream::Camera, 5);
  draw(v, SampleStream::Light, 2);
  EXPECT_EQ(v.coordinates(SampleStream::Camera).size(), 5u);
  EXPECT_EQ(v.coordinates(SampleStream::Light).size(), 2u);
  EXPECT_EQ(v.coordinates(SampleStream::Connection).size(), 0u);
}

TEST(PrimarySampleVector, RejectRestoresTheStateExactly) {
  PrimarySampleVector v(3);
  draw(v, SampleStream::Camera, 6);
  draw(v, SampleStream::Light, 3);
  v.startIteration(false);
  draw(v, SampleStream::Camera, 6);
  v.accept();
  const auto camera = v.coordinates(SampleStream::Camera);
  const auto light = v.coordinates(SampleStream::Light);
  const uint64_t iteration = v.iteration(), lastLarge = v.lastLargeStep();
  for (bool large : {false, true}) {
    v.startIteration(large);
    draw(v, SampleStream::Camera, 9);  // touches 6 old coordinates and creates 3
    draw(v, SampleStream::Connection, 2);
    v.reject();
    ASSERT_EQ(v.iteration(), iteration);
    ASSERT_EQ(v.lastLargeStep(), lastLarge);
    ASSERT_EQ(v.coordinates(SampleStream::Camera).size(), camera.size());
    ASSERT_EQ(v.coordinates(SampleStream::Connection).size(), 0u);
    for (size_t i = 0; i < camera.size(); ++i) {
      EXPECT_EQ(v.coordinates(SampleStream::Camera)[i].value, camera[i].value);
      EXPECT_EQ(v.coordinates(SampleStream::Camera)[i].modified, camera[i].modified);
    }
    for (size_t i = 0; i < light.size(); ++i) EXPECT_EQ(v.coordinates(SampleStream::Light)[i].value, light[i].value);
  }
}

TEST(PrimarySampleVector, LargeStepRedrawsCoordinatesLazily) {
  PrimarySampleVector v(4);
  const std::vector<float> start = draw(v, SampleStream::Light, 4);
  v.startIteration(true);
  draw(v, SampleStream::Light, 2);  // only the first two are used by this proposal
  v.accept();
  // The other two are redrawn when next used, then carry the small steps since.
  v.startIteration(false);
  v.startIteration(false);
  const std::vector<float> later = draw(v, SampleStream::Light, 4);
  for (int i = 2; i < 4; ++i) {
    EXPECT_EQ(v.coordinates(SampleStream::Light)[i].modified, v.iteration());
    // With overwhelming probability a fresh uniform lands farther than 3 small steps away.
    EXPECT_GT(circularDistance(later[i], start[i]), 3 * KelemenSizes{}.s2) << i;
  }
}

TEST(PrimarySampleVector, MissedSmallStepsAreCaughtUp) {
  // A coordinate skipped for k iterations receives k + 1 small steps: its spread grows like sqrt(k).
  double spreadNear = 0.0, spreadFar = 0.0;
  for (uint64_t key = 0; key < 400; ++key) {
    PrimarySampleVector v(100 + key);
    const float start = v.next(SampleStream::Camera);
    for (int i = 0; i < 49; ++i) v.startIteration(false);  // the coordinate is not used
    v.startIteration(false);
    spreadFar += circularDistance(v.next(SampleStream::Camera), start);
    PrimarySampleVector w(100 + key);
    const float s = w.next(SampleStream::Camera);
    w.startIteration(false);
    spreadNear += circularDistance(w.next(SampleStream::Camera), s);
  }
  // 50 steps of mean size ~0.0056: mean distance ~sqrt(50) * 0.0057 * 0.8; one step: ~0.0056.
  EXPECT_GT(spreadFar / spreadNear, 4.0);
  EXPECT_LT(spreadFar / spreadNear, 10.0);
}

TEST(PrimarySampleVector, SerialisedStateContinuesBitForBit) {
  PrimarySampleVector a(5, KelemenSizes{1.0f / 512.0f, 1.0f / 32.0f});
  draw(a, SampleStream::Camera, 7);
  for (int i = 0; i < 10; ++i) {
    a.startIteration(i % 3 == 0);
    draw(a, SampleStream::Camera, 3 + i % 5);
    draw(a, SampleStream::Light, 2);
    i % 2 ? a.accept() : a.reject();
  }
  PrimarySampleVector b = PrimarySampleVector::deserialize(a.serialize());
  for (int i = 0; i < 20; ++i) {
    const bool large = i % 4 == 1;
    a.startIteration(large);
    b.startIteration(large);
    ASSERT_EQ(draw(a, SampleStream::Camera, 9), draw(b, SampleStream::Camera, 9));
    ASSERT_EQ(draw(a, SampleStream::Connection, 3), draw(b, SampleStream::Connection, 3));
  }
  std::vector<uint64_t> truncated = a.serialize();
  truncated.pop_back();
  EXPECT_THROW(PrimarySampleVector::deserialize(truncated), std::runtime_error);
}

TEST(PrimarySampleVector, StartsFromGivenValues) {
  PrimarySampleVector v(6);
  v.setState(SampleStream::Camera, {0.1f, 0.2f, 0.3f});
  EXPECT_EQ(draw(v, SampleStream::Camera, 3), (std::vector<float>{0.1f, 0.2f, 0.3f}));
  v.startIteration(false);
  EXPECT_NEAR(v.next(SampleStream::Camera), 0.1f, KelemenSizes{}.s2 * 1.0001f);
}

TEST(PrimarySampleVector, CatchUpDisplacementIsSymmetricWithTheVarianceOfTheMissedSteps) {
  // For gaps applied step by step (4) and in one normal draw (100): mean 0 within 4 standard errors,
  // variance n sigma^2 within 4 standard errors of the sample variance (about 3 % here).
  const KelemenStep step{KelemenSizes{}};
  for (int gap : {4, 100}) {
    const int n = 20000;
    double sum = 0.0, sum2 = 0.0, sum4 = 0.0;
    for (int k = 0; k < n; ++k) {
      PrimarySampleVector v(hashKey(300, gap, k));
      v.setState(SampleStream::Light, {0.5f});
      for (int i = 0; i < gap; ++i) v.startIteration(false);
      const double d = v.next(SampleStream::Light) - 0.5;
      sum += d;
      sum2 += d * d;
      sum4 += d * d * d * d;
    }
    const double mean = sum / n, var = sum2 / n, expected = gap * double(step.sigma()) * step.sigma();
    EXPECT_NEAR(mean, 0.0, 4.0 * std::sqrt(var / n)) << gap;
    const double varError = std::sqrt((sum4 / n - var * var) / n);
    EXPECT_NEAR(var, expected, 4.0 * varError) << gap;
  }
}
