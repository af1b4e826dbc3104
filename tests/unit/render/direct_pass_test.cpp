// The direct-emission pass of pssmlt and relt: its size on auto, the probe that drops it when no
// emitter is in view, and the doublings of a timed render (render/direct_pass.h, schedule/schedule.h).
// The other ranks are played by a job whose collectives the tests script (ScriptedJob).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "../scene/gltf_test_support.h"
#include "integrators/registry.h"
#include "parallel/local_job.h"
#include "render/direct_pass.h"
#include "schedule/schedule.h"
#include "scene/gltf_loader.h"
#include "scripted_job.h"
#include "test_support.h"

using namespace relt;
using relt::test::ScriptedJob;

namespace {

RenderSettings small(int directSpp) {
  RenderSettings s;
  selectIntegrator(s, "pssmlt");
  s.width = 12;
  s.height = 10;
  s.seed = 5;
  s.directSpp = directSpp;
  return s;
}

double filmSum(const Film& film) {
  double sum = 0.0;
  for (double v : film.data()) sum += v;
  return sum;
}

// cornell-box's light is in view; door-ajar's camera sees only what the light through the door reaches.
Scene withLightInView() { return loadGltf(test::sourcePath("scenes/cornell-box.gltf")); }
Scene withoutLightInView() { return loadGltf(test::sourcePath("scenes/door-ajar.gltf")); }

}  // namespace

TEST(DirectPassSize, AutoIsTwiceTheMutationsPerPixelAsAPowerOfTwoAndAtLeast16) {
  EXPECT_EQ(autoDirectSpp(16), 32);
  EXPECT_EQ(autoDirectSpp(64), 128);
  EXPECT_EQ(autoDirectSpp(90), 128);   // 180: nearer 128 than 256 on a log scale
  EXPECT_EQ(autoDirectSpp(100), 256);  // 200
  EXPECT_EQ(autoDirectSpp(1), kDirectMinSpp);
  EXPECT_EQ(autoDirectSpp(0.001), kDirectMinSpp);
  EXPECT_EQ(autoDirectSpp(1e6), 1 << 20);  // the option's ceiling
}

TEST(DirectPassSize, ATimedPassDoublesOnlyWhileItStaysWithinItsShareOfTheBudget) {
  EXPECT_TRUE(doubleDirectPass(0.01, 1.0));
  EXPECT_TRUE(doubleDirectPass(0.5 * kDirectBudgetShare * 10.0, 10.0));
  EXPECT_FALSE(doubleDirectPass(0.6 * kDirectBudgetShare * 10.0, 10.0));
}

TEST(DirectPass, RaysInTwoRangesSumToTheSameFilmAsInOne) {
  Renderer renderer(withLightInView(), small(8));
  Film whole(12, 10), parts(12, 10);
  renderer.renderDirect(0, 1, whole, 0, 8);
  renderer.renderDirect(0, 1, parts, 0, 3);
  renderer.renderDirect(0, 1, parts, 3, 8);
  ASSERT_GT(filmSum(whole), 0.0);
  EXPECT_EQ(whole.data(), parts.data());
}

TEST(DirectPass, AGivenCountIsTakenAsItIs) {
  Renderer renderer(withoutLightInView(), small(8));
  Film film(12, 10);
  LocalJob one;
  EXPECT_EQ(renderDirectPass(renderer, one, film).spp, 8);
  EXPECT_EQ(renderer.context().settings.specularChainsApart, true) << "asked for: kept even with nothing in view";
}

TEST(DirectPass, AutoWithAFixedBudgetTakesAutoDirectSpp) {
  RenderSettings s = small(kDirectSppAuto);
  s.mutationsPerPixel = 40;
  Renderer renderer(withLightInView(), s);
  Film film(12, 10), expected(12, 10);
  LocalJob one;
  EXPECT_EQ(renderDirectPass(renderer, one, film).spp, autoDirectSpp(40));
  EXPECT_EQ(renderer.context().settings.specularChainsApart, true);
  renderer.renderDirect(0, 1, expected, 0, uint32_t(autoDirectSpp(40)));
  EXPECT_EQ(film.data(), expected.data());
}

TEST(DirectPass, AutoWithNoEmitterInViewHandsThatEmissionBackToTheChains) {
  Renderer renderer(withoutLightInView(), small(kDirectSppAuto));
  ASSERT_EQ(renderer.context().settings.specularChainsApart, true);
  Film film(12, 10);
  LocalJob one;
  const DirectPass pass = renderDirectPass(renderer, one, film);
  EXPECT_EQ(pass.spp, 0);
  EXPECT_EQ(renderer.context().settings.specularChainsApart, false);
  EXPECT_FALSE(directEmissionApart(renderer.settings()));
  EXPECT_EQ(filmSum(film), 0.0);
}

TEST(DirectPass, AutoOnAnotherRankSeeingTheEmitterKeepsThePass) {
  Renderer renderer(withoutLightInView(), small(kDirectSppAuto));
  ScriptedJob othersSeeIt;
  othersSeeIt.othersAdd = 1.0;
  Film film(12, 10);
  EXPECT_EQ(renderDirectPass(renderer, othersSeeIt, film).spp, autoDirectSpp(16));
  EXPECT_EQ(renderer.context().settings.specularChainsApart, true);
}

TEST(DirectPass, AutoWithATimeBudgetDoublesWhileTheSlowestRankStaysWithinTheShare) {
  RenderSettings s = small(kDirectSppAuto);
  s.seconds = 100.0;  // share: 6 s; the slowest rank's times at 16, 32 and 64 rays per pixel:
  ScriptedJob slowest;
  slowest.maxima = {1.0, 2.0, 4.0, 4.0};
  Renderer renderer(withLightInView(), s);
  Film film(12, 10);
  const DirectPass pass = renderDirectPass(renderer, slowest, film);
  EXPECT_EQ(pass.spp, 4 * kDirectMinSpp);  // 2 x 1 and 2 x 2 fit in 6 s, 2 x 4 does not
  EXPECT_EQ(pass.seconds, 4.0);
  EXPECT_TRUE(slowest.maxima.empty());
}

// A lamp seen far away covers a tenth of the only pixel. The probe sees it in some renders and not
// in others; the pass runs only where it did, so the pass must not reuse the probe's rays: they
// would make it too bright exactly there (1/16 (1 + 12 x 0.1) = 0.1375 on average for 16 rays).
// Over 600 seeds the pass's mean where it ran must be the covered fraction.
TEST(DirectPass, ThePassIsUnbiasedWhereTheProbeDecidedItRuns) {
  test::GltfBuilder b;
  const float h = float(std::sqrt(0.1) * 10.0 * std::tan(0.4));  // yfov 0.8: a tenth of the view
  const int lamp = b.material({{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}},
                               {"emissiveFactor", {1, 1, 1}}});
  const int mesh = b.triangleMesh({{-h, -h, -10}, {h, -h, -10}, {h, h, -10}, {-h, h, -10}}, {0, 1, 2, 0, 2, 3}, lamp);
  b.scene({b.node({{"mesh", mesh}}), b.node({{"camera", b.camera(0.8)}})});
  const std::string dir = test::makeTempDir("subpixel_lamp");
  const std::string path = dir + "/lamp.gltf";
  std::ofstream(path) << b.finish().dump();
  const Scene scene = loadGltf(path);
  double sum = 0.0, squares = 0.0;
  int ran = 0;
  const int seeds = 600;
  for (int seed = 1; seed <= seeds; ++seed) {
    RenderSettings s = small(kDirectSppAuto);
    s.width = s.height = 1;
    s.seed = uint64_t(seed);
    s.mutationsPerPixel = 8;  // autoDirectSpp: 16 rays
    Renderer renderer(scene, s);
    Film film(1, 1);
    LocalJob one;
    const DirectPass pass = renderDirectPass(renderer, one, film);
    if (pass.spp == 0) continue;
    ASSERT_EQ(pass.spp, 16);
    const double v = film.data()[1] / pass.spp;  // green
    sum += v;
    squares += v * v;
    ++ran;
  }
  ASSERT_GT(ran, seeds / 10) << "the probe should see the lamp in many renders";
  ASSERT_LT(ran, seeds * 9 / 10) << "and miss it in many";
  const double mean = sum / ran, error = std::sqrt((squares / ran - mean * mean) / (ran - 1));
  EXPECT_NEAR(mean, 0.1, 4.0 * error + 1e-4) << ran << " renders ran the pass";
}

// A stop request is agreed on between chunks of every pixel's rays: the pass ends at the chunk it
// came in, every pixel with the same rays, the film that of those rays alone.
TEST(DirectPass, AStopRequestEndsThePassBetweenChunksWithEveryPixelAlike) {
  RenderSettings s = small(1 << 14);
  Renderer renderer(withLightInView(), s);
  Film film(12, 10);
  ScriptedJob stopsAtTheThird;
  stopsAtTheThird.stopAt = 3;
  const DirectPass pass = renderDirectPass(renderer, stopsAtTheThird, film);
  EXPECT_TRUE(pass.stopped);
  // Chunks of 4, then at most 4 times the last (each takes far less than the aimed 0.1 s): 4 + 16 + 64.
  EXPECT_EQ(pass.spp, 4 + 16 + 64);
  Film expected(12, 10);
  renderer.renderDirect(0, 1, expected, 0, uint32_t(pass.spp));
  EXPECT_EQ(film.data(), expected.data());
}

// A checkpoint keeps the pass so far: continued from its rays per pixel, the pass ends on the
// film of one that never stopped (each pixel's rays added in the same order).
TEST(DirectPass, AResumedPassEndsOnTheFilmOfOneThatNeverStopped) {
  RenderSettings s = small(256);
  Renderer whole(withLightInView(), s);
  Film expected(12, 10);
  LocalJob one;
  ASSERT_EQ(renderDirectPass(whole, one, expected).spp, 256);

  Renderer first(withLightInView(), s);
  Film film(12, 10);
  ScriptedJob stopsAtTheSecond;
  stopsAtTheSecond.stopAt = 2;
  const DirectPass stopped = renderDirectPass(first, stopsAtTheSecond, film);
  ASSERT_TRUE(stopped.stopped);
  ASSERT_EQ(stopped.spp, 4 + 16);

  Renderer resumed(withLightInView(), s);
  LocalJob again;
  const DirectPass pass = renderDirectPass(resumed, again, film, {stopped.spp, stopped.seconds});
  EXPECT_EQ(pass.spp, 256);
  EXPECT_FALSE(pass.stopped);
  EXPECT_EQ(film.data(), expected.data());
  EXPECT_EQ(resumed.context().settings.specularChainsApart, true) << "the chains still leave that emission to the pass";
}

// A timed pass stopped within a doubling (20 of 32 rays) first ends it, then doubles on the time
// the checkpoint's seconds and its own add up to.
TEST(DirectPass, AResumedTimedPassEndsTheDoublingItWasStoppedIn) {
  RenderSettings s = small(kDirectSppAuto);
  s.seconds = 100.0;  // share: 6 s
  ScriptedJob slowest;
  slowest.maxima = {2.0, 4.0, 4.0};
  Renderer renderer(withLightInView(), s);
  Film film(12, 10);
  renderer.renderDirect(0, 1, film, 0, 20);
  const DirectPass pass = renderDirectPass(renderer, slowest, film, {20, 1.5});
  EXPECT_EQ(pass.spp, 64);  // to 32, doubled at 2 s, not at 4 s
  EXPECT_EQ(pass.seconds, 4.0);
  EXPECT_TRUE(slowest.maxima.empty());
  Film expected(12, 10);
  renderer.renderDirect(0, 1, expected, 0, 64);
  EXPECT_EQ(film.data(), expected.data());
}

// A save request agreed between chunks is handed on with the pass so far; the pass goes on.
TEST(DirectPass, ASaveRequestIsHandedOnWithThePassSoFarAndThePassGoesOn) {
  Renderer renderer(withLightInView(), small(1 << 10));
  std::vector<std::pair<int, bool>> told;
  ScriptedJob savesAtTheSecond;
  savesAtTheSecond.saveAt = 2;
  Film film(12, 10);
  const DirectPass pass = renderDirectPass(renderer, savesAtTheSecond, film, {},
                                           [&](const DirectPass& sofar, bool save) { told.emplace_back(sofar.spp, save); });
  EXPECT_EQ(pass.spp, 1 << 10);
  EXPECT_FALSE(pass.stopped);
  ASSERT_GE(told.size(), 3u);
  EXPECT_EQ(told[0], std::make_pair(4, false));
  EXPECT_EQ(told[1], std::make_pair(4 + 16, true));
  EXPECT_FALSE(told[2].second);
  EXPECT_EQ(told.back().first, 1 << 10);
}
