// Non-finite numbers reaching the path builders (a poisoned sample source hands out NaN and
// infinities now and then): every sample whose splats are not all finite is counted and dropped
// by the film, the image stays finite, and the Markov chains' evaluator gives such a path the
// target 0, so a chain never accepts it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "film/film.h"
#include "mcmc/pss_evaluator.h"
#include "path/path_tracer.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

using namespace relt;

namespace {

// Independent numbers, but every `period`-th one (over all streams) is NaN, +Inf or -Inf in turn.
class PoisonedSource final : public SampleSource {
 public:
  PoisonedSource(uint64_t key, int period) : source_(key), period_(period) {}
  float next(SampleStream stream) override {
    const float u = source_.next(stream);
    if (++count_ % period_ != 0) return u;
    const float bad[3] = {std::numeric_limits<float>::quiet_NaN(), INFINITY, -INFINITY};
    return bad[(count_ / period_) % 3];
  }

 private:
  IndependentSource source_;
  int period_;
  uint64_t count_ = 0;
};

struct Tally {
  uint64_t samples = 0, nonFinite = 0;
};

template <class Trace>
Tally traceAll(const Renderer& renderer, Film& film, Trace&& trace) {
  Tally run;
  PathSample sample;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      for (int i = 0; i < 4; ++i) {
        PoisonedSource source(hashKey(11, uint64_t(y * film.width() + x), uint64_t(i)), 5 + (x + y) % 7);
        sample.clear();
        trace(Vec2(x + 0.5f, y + 0.5f), source, sample);
        ++run.samples;
        run.nonFinite += !sample.finite();
        film.addSample(sample);
      }
  return run;
}

void expectFiniteAndCounted(const Film& film, const Tally& run) {
  for (double v : film.data()) ASSERT_TRUE(std::isfinite(v));
  EXPECT_EQ(film.droppedSamples(), run.nonFinite);
  EXPECT_LT(run.nonFinite, run.samples);
}

Renderer makeRenderer() {
  RenderSettings s;
  s.width = 24;
  s.height = 24;
  s.maxDepth = 8;
  return Renderer(loadGltf(test::sourcePath("scenes/glass-cube.gltf")), s);
}

}  // namespace

TEST(NanInjection, PathTracerSamplesWithNonFiniteSplatsAreDroppedAndCounted) {
  Renderer renderer = makeRenderer();
  Film film(24, 24);
  const Tally run = traceAll(renderer, film, [&](const Vec2& p, SampleSource& u, PathSample& out) {
    tracePath(renderer.context(), p, u, out);
  });
  expectFiniteAndCounted(film, run);
  EXPECT_GT(run.nonFinite, 0u) << "the poison reaches the path tracer's splats, or this test tests nothing";
}

TEST(NanInjection, BdptSamplesWithNonFiniteSplatsAreDroppedAndCounted) {
  Renderer renderer = makeRenderer();
  Bdpt bdpt(renderer.context());
  Film film(24, 24);
  const Tally run = traceAll(renderer, film, [&](const Vec2& p, SampleSource& u, PathSample& out) {
    bdpt.trace(p, u, out);
  });
  // bdpt absorbs this poison (a non-finite ray hits nothing, a non-finite density fails its
  // comparisons); what it does produce must still be finite or dropped.
  expectFiniteAndCounted(film, run);
}

TEST(NanInjection, MarkovChainTargetOfANonFinitePathIsZero) {
  Renderer renderer = makeRenderer();
  PssEvaluator eval(renderer.context(), 24, 24);
  uint64_t nonFinite = 0;
  for (uint64_t i = 0; i < 4000; ++i) {
    PoisonedSource source(hashKey(12, i), 5 + int(i % 7));
    PathSample path;
    const float target = eval(source, path);
    if (!path.finite()) {
      ++nonFinite;
      EXPECT_EQ(target, 0.0f);
    }
    EXPECT_TRUE(std::isfinite(target));
    // A path the Markov chains see is all-finite or has target 0.
    EXPECT_TRUE(path.finite() || target == 0.0f);
  }
  // A non-finite path planted directly: target 0.
  PathSample planted;
  planted.add(Vec2(1.0f, 1.0f), Color(1.0f), PathClass::L1);
  planted.add(Vec2(2.0f, 1.0f), Color(NAN, 0.0f, 0.0f), PathClass::L2);
  EXPECT_EQ(planted.target(), 0.0f);
}
