// A chain's expected-value splats must stay finite however small its targets: a path of 144
// segments in the furnace (albedo 0.5) has a contribution of about 2^-143, a subnormal float,
// whose reciprocal overflows float. Each step adds one unit of luminance to the film.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "film/film.h"
#include "mcmc/pssmlt.h"

using namespace relt;

namespace {

// Every point of primary sample space maps to one splat of grey value v in pixel (0, 0).
struct ConstantTarget {
  float v;
  float operator()(SampleSource& u, PathSample& out) const {
    out.clear();
    u.next(SampleStream::Camera);
    out.add(Vec2(0.5f, 0.5f), Color(v, v, v), PathClass::L1);
    return out.target();
  }
};

double filmLuminance(const Film& film) {
  const auto& d = film.data();
  return 0.2126 * d[0] + 0.7152 * d[1] + 0.0722 * d[2];
}

}  // namespace

TEST(ChainWeights, SubnormalTargetsGiveFiniteSplatsOfOneUnitPerStep) {
  for (float v : {1.0f, 1e-30f, 2e-39f, 1e-42f}) {
    PssmltSettings settings;
    McmcChain chain(3, 0, settings);
    const ConstantTarget eval{v};
    chain.start(eval, 11);
    ASSERT_GT(chain.target(), 0.0f) << v;
    Film film(1, 1);
    const int steps = 200;
    for (int k = 0; k < steps; ++k) chain.step(eval, film);
    for (double x : film.data()) ASSERT_TRUE(std::isfinite(x)) << "value " << v;
    // Subnormal values carry few significant bits, so their luminance is exact only to a few %.
    EXPECT_NEAR(filmLuminance(film), steps, (v < FLT_MIN ? 0.1 : 1e-4) * steps) << "value " << v;
    EXPECT_EQ(film.droppedSamples(), 0u);
  }
}

// The film is the last line before a pixel: a weight that is not finite drops the sample (counted).
TEST(ChainWeights, FilmDropsASampleWithANonFiniteWeight) {
  Film film(1, 1);
  PathSample s;
  s.add(Vec2(0.5f, 0.5f), Color(1.0f, 1.0f, 1.0f), PathClass::L1);
  EXPECT_FALSE(film.addSample(s, INFINITY));
  EXPECT_FALSE(film.addSample(s, NAN));
  EXPECT_TRUE(film.addSample(s, 2.0));
  EXPECT_EQ(film.droppedSamples(), 2u);
  EXPECT_DOUBLE_EQ(film.data()[0], 2.0);
}
