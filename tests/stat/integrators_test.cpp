// Every independent-sample integrator against an analytic answer (furnace) and against each other
// (cornell-box), pbrt-v4 style: one fixture renders, one parameterised test per property.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "image/image.h"
#include "integrators/registry.h"
#include "integrators/relt/relt_settings.h"
#include "integrators/meb/meb_settings.h"
#include "integrators/vcm/vcm_settings.h"
#include "mcmc/pssmlt.h"
#include "render_fixture.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

using namespace relt;
using namespace relt::test;

namespace {

// spp doubles as mutations per pixel for the Markov-chain integrators.
RenderSettings settingsFor(const std::string& integrator, uint64_t seed, int spp, int size) {
  RenderSettings s;
  selectIntegrator(s, integrator);
  s.seed = seed;
  if (!unusedOptionReason("--mutations-per-pixel", *findIntegrator(integrator))) {  // its budget is mutations
    s.mutationsPerPixel = spp;
    s.chains = 64;
    if (integrator == "relt") replicaSettings(s).ladders = 8;
  } else {
    s.spp = spp;
  }
  s.width = s.height = size;
  return s;
}

class IntegratorTest : public ::testing::TestWithParam<std::string> {};

// Closed sphere, emission Le and albedo a everywhere, camera inside: with at most D segments every
// pixel is Le (1 - a^D) / (1 - a) (scenes/README.md).
void expectFurnaceWithinOnePercent(const RenderSettings& settings) {
  const std::string path = sourcePath("scenes/furnace.gltf");
  const Scene scene = loadGltf(path);
  const double le = 1.0, a = 0.5;
  const int depth = scene.defaults.maxDepth;
  const double expected = le * (1.0 - std::pow(a, depth)) / (1.0 - a);
  const Image image = renderInProcess(path, settings);
  EXPECT_NEAR(image.mean(), expected, 0.01 * expected);
}

// The furnace's pixel value with at most `depth` segments (scenes/README.md).
double furnaceValue(int depth) { return (1.0 - std::pow(0.5, depth)) / (1.0 - 0.5); }

}  // namespace

TEST_P(IntegratorTest, FurnaceMatchesAnalyticValueWithinOnePercent) {
  expectFurnaceWithinOnePercent(settingsFor(GetParam(), 7, 16, 32));
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, IntegratorTest,
                         ::testing::Values("pt", "bdpt", "pssmlt",
                                           "mmlt", "erpt", "relt", "vcm", "meb"),
                         [](const auto& info) { return info.param; });

// Two integrators estimate the same image: the mean and four regions agree within 4 standard
// errors, the errors coming from independent seeds (fixed, so the test is deterministic). Markov
// chain images have heavy-tailed errors (a chain that finds a bright path late), so their standard
// errors are estimated from 20 seeds rather than 10.
static void expectAgreement(const Scene& scene, const std::string& first, const std::string& second, int spp, int seeds,
                            const std::function<void(RenderSettings&)>& tweak = {}) {
  const int size = 48;
  struct Region {
    const char* name;
    int x0, y0, x1, y1;
  };
  const Region regions[] = {{"whole", 0, 0, size, size},
                            {"top-left", 0, 0, size / 2, size / 2},
                            {"top-right", size / 2, 0, size, size / 2},
                            {"bottom-left", 0, size / 2, size / 2, size},
                            {"bottom-right", size / 2, size / 2, size, size}};
  std::vector<double> values[2][5];
  const std::string integrators[2] = {first, second};
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < seeds; ++k) {
      RenderSettings settings = settingsFor(integrators[i], 1000 * (i + 1) + k, spp, size);
      if (tweak && i == 0) tweak(settings);
      const Image image = renderInProcess(scene, settings);
      for (int r = 0; r < 5; ++r)
        values[i][r].push_back(regionMean(image, regions[r].x0, regions[r].y0, regions[r].x1, regions[r].y1));
    }
  for (int r = 0; r < 5; ++r) {
    const Estimate a = meanAndStandardError(values[0][r]);
    const Estimate b = meanAndStandardError(values[1][r]);
    const double sigma = std::sqrt(a.stderror * a.stderror + b.stderror * b.stderror);
    EXPECT_GT(a.mean, 0.0);
    EXPECT_LT(std::abs(a.mean - b.mean), 4.0 * sigma)
        << regions[r].name << ": " << first << " " << a.mean << " +- " << a.stderror << ", "
        << second << " " << b.mean << " +- " << b.stderror;
  }
}

static void expectAgreementOnCornellBox(const std::string& first, const std::string& second, int spp, int seeds,
                                        const std::function<void(RenderSettings&)>& tweak = {}) {
  expectAgreement(loadGltf(sourcePath("scenes/cornell-box.gltf")), first, second, spp, seeds, tweak);
}

// pssmlt and relt estimate the directly seen emission apart by default (--direct-emission-spp
// auto); every other test of them here runs that way. Here the chains do it all, as with 0.
TEST(IntegratorAgreement, PssmltAndReltWithTheChainsDoingItAllAgreeWithBdptOnCornellBox) {
  const auto chainsOnly = [](RenderSettings& s) { s.directSpp = 0; };
  expectAgreementOnCornellBox("pssmlt", "bdpt", 16, 20, chainsOnly);
  expectAgreementOnCornellBox("relt", "bdpt", 16, 20, chainsOnly);
}

TEST(DirectEmission, ChainsDoingItAllMatchTheFurnaceWithinOnePercent) {
  for (const std::string& integrator : {"pssmlt", "relt"}) {
    RenderSettings s = settingsFor(integrator, 7, 16, 32);
    s.directSpp = 0;
    expectFurnaceWithinOnePercent(s);
  }
}

TEST(IntegratorAgreement, PtAndBdptAgreeOnCornellBox) {
  expectAgreementOnCornellBox("pt", "bdpt", 16, 10);
}

TEST(IntegratorAgreement, PssmltAndBdptAgreeOnCornellBox) {
  expectAgreementOnCornellBox("pssmlt", "bdpt", 16, 20);
}

TEST(IntegratorAgreement, ErptAndBdptAgreeOnCornellBox) {
  // erpt: 2 seeds per pixel, each redistributed by about 100 mutations.
  expectAgreementOnCornellBox("erpt", "bdpt", 2, 20);
}

// Glass resting 1 mm above a floor (scenes/glass-case.gltf): bdpt's subpaths and vcm's once took
// their directions between stored vertex positions, which the ray origins' offset tilts beside so
// narrow a gap, and were 1.4 % brighter than pt there (about 11 standard errors of this test).
TEST(IntegratorAgreement, PtAndBdptAgreeThroughGlassOnAFloor) {
  expectAgreement(loadGltf(sourcePath("scenes/glass-case.gltf")), "pt", "bdpt", 128, 20);
}

TEST(IntegratorAgreement, VcmConnectionsOnlyAndPtAgreeThroughGlassOnAFloor) {
  expectAgreement(loadGltf(sourcePath("scenes/glass-case.gltf")), "vcm", "pt", 128, 20,
                  [](RenderSettings& s) { s.own.get<VcmIntegratorSettings>().vcm.mode = VcmMode::Bpt; });
}

// The emission seen in the mirror and glass balls (scenes/mirror-balls.gltf) is left by pssmlt and
// vcm to the pass apart (path/specular_chain.h); with it they agree with pt, which finds it itself.
// The pass is asked for: on auto its probe sees none of that emission at 48 x 48 and leaves it in.
TEST(IntegratorAgreement, PssmltWithSpecularChainsApartAndPtAgreeOnMirrorBalls) {
  expectAgreement(loadGltf(sourcePath("scenes/mirror-balls.gltf")), "pssmlt", "pt", 16, 20,
                  [](RenderSettings& s) { s.directSpp = 64; });
}

TEST(IntegratorAgreement, VcmWithSpecularChainsApartAndPtAgreeOnMirrorBalls) {
  expectAgreement(loadGltf(sourcePath("scenes/mirror-balls.gltf")), "vcm", "pt", 64, 10,
                  [](RenderSettings& s) {
                    s.own.get<VcmIntegratorSettings>().vcm.mode = VcmMode::Bpt;
                    s.directSpp = 64;
                  });
}

// vcm with connections only is bdpt's estimator (unbiased); with merging it is biased by its
// radius, which at the default (one pixel footprint, shrinking) is below these tests' error on
// cornell-box's diffuse walls.
TEST(IntegratorAgreement, VcmConnectionsOnlyAndBdptAgreeOnCornellBox) {
  expectAgreementOnCornellBox("vcm", "bdpt", 16, 10,
                              [](RenderSettings& s) { s.own.get<VcmIntegratorSettings>().vcm.mode = VcmMode::Bpt; });
}

TEST(IntegratorAgreement, VcmAndBdptAgreeOnCornellBox) {
  expectAgreementOnCornellBox("vcm", "bdpt", 16, 10);
}

// vcm against the long bdpt reference (scenes/references/cornell-box.exr, 3811 samples per pixel,
// so a tile's mean there has a standard error below 0.1 % of it, left out), tile by tile (64 x 64).
// Merging blurs the light by about the radius; a tile's mean moves by that where light crosses its
// border and where merges reach around the box's corners onto the next wall. The bound on that
// bias: 1 % of the tile's mean, stated before the test first ran. At two pixel footprints (the
// default then; one since) it failed in one tile, (64, 64), the ceiling's and back wall's corners
// with the left wall: +1.7 % (0.12231 +- 0.00017 against 0.12028, the 15 other tiles within the
// bound; with connections only every tile was within 4 standard errors). So the tested radius is
// half a footprint, where the bias, as r^2, is 16 times smaller than at two (4 times smaller than at
// the default). Each tile within the bound plus 4 standard errors of vcm's mean (10 seeds).
// Tile by tile against the long bdpt reference (its standard error left out, as above): within
// 1 % (merging's bias at half a pixel footprint, as bounded for vcm) plus 4 standard errors of the
// mean of 10 seeds.
static void expectCornellBoxReferenceWithinBiasBound(const std::string& integrator,
                                                     const std::function<void(RenderSettings&)>& halfFootprint) {
  const Image reference = readExr(sourcePath("scenes/references/cornell-box.exr"));
  const Scene scene = loadGltf(sourcePath("scenes/cornell-box.gltf"));
  const int size = reference.width, tiles = 4, tile = size / tiles;
  ASSERT_EQ(reference.height, size);
  std::vector<double> values[tiles * tiles];
  for (int k = 0; k < 10; ++k) {
    RenderSettings settings = settingsFor(integrator, 3000 + k, 4, size);
    halfFootprint(settings);
    const Image image = renderInProcess(scene, settings);
    for (int t = 0; t < tiles * tiles; ++t) {
      const int x0 = (t % tiles) * tile, y0 = (t / tiles) * tile;
      values[t].push_back(regionMean(image, x0, y0, x0 + tile, y0 + tile));
    }
  }
  for (int t = 0; t < tiles * tiles; ++t) {
    const int x0 = (t % tiles) * tile, y0 = (t / tiles) * tile;
    const double expected = regionMean(reference, x0, y0, x0 + tile, y0 + tile);
    const Estimate e = meanAndStandardError(values[t]);
    EXPECT_GT(e.mean, 0.0);
    EXPECT_LT(std::abs(e.mean - expected), 0.01 * expected + 4.0 * e.stderror)
        << "tile (" << x0 << ", " << y0 << "): " << integrator << " " << e.mean << " +- " << e.stderror
        << ", reference " << expected;
  }
}

// vcm against the long bdpt reference (scenes/references/cornell-box.exr, 3811 samples per pixel,
// so a tile's mean there has a standard error below 0.1 % of it, left out), tile by tile (64 x 64).
// Merging blurs the light by about the radius; a tile's mean moves by that where light crosses its
// border and where merges reach around the box's corners onto the next wall. The bound on that
// bias: 1 % of the tile's mean, stated before the test first ran. At two pixel footprints (the
// default then; one since) it failed in one tile, (64, 64), the ceiling's and back wall's corners
// with the left wall: +1.7 % (0.12231 +- 0.00017 against 0.12028, the 15 other tiles within the
// bound; with connections only every tile was within 4 standard errors). So the tested radius is
// half a footprint, where the bias, as r^2, is 16 times smaller than at two (4 times smaller than at
// the default). Each tile within the bound plus 4 standard errors of vcm's mean (10 seeds).
TEST(IntegratorAgreement, VcmMatchesTheCornellBoxReferenceWithinItsBiasBound) {
  expectCornellBoxReferenceWithinBiasBound("vcm", [](RenderSettings& s) { s.own.get<VcmIntegratorSettings>().vcm.radius = 0.5; });
}

// meb has vcm's techniques and radius, so the same bias bound; its chains add only variance.
TEST(IntegratorAgreement, MebMatchesTheCornellBoxReferenceWithinItsBiasBound) {
  expectCornellBoxReferenceWithinBiasBound("meb", [](RenderSettings& s) { s.own.get<MebIntegratorSettings>().meb.vcm.radius = 0.5; });
}

// meb and vcm at the same radius have the same expectation: merging's bias is theirs alike (at
// 48 x 48 a pixel footprint is 5 times wider than at 256 x 256, and both are about 2.6 % bright
// in the top-left quarter against bdpt), so what differs is only meb's chains: their start-up
// and normalisers.
TEST(IntegratorAgreement, MebAndVcmAgreeOnCornellBox) {
  expectAgreementOnCornellBox("meb", "vcm", 16, 20);
}

TEST(IntegratorAgreement, MmltAndBdptAgreeOnCornellBox) {
  expectAgreementOnCornellBox("mmlt", "bdpt", 64, 20);
}

// Replica exchange: both families with the default exchange (deo), kitaoka with permutations,
// relaxed with population annealing.
TEST(IntegratorAgreement, ReltRelaxedAndBdptAgreeOnCornellBox) {
  expectAgreementOnCornellBox("relt", "bdpt", 16, 20,
                              [](RenderSettings& s) { replicaSettings(s).family.kind = FamilyKind::Relaxed; });
}

TEST(IntegratorAgreement, ReltDefaultAndBdptAgreeOnCornellBox) {  // kitaoka, deo
  expectAgreementOnCornellBox("relt", "bdpt", 16, 20);
}

TEST(IntegratorAgreement, ReltKitaokaWithPermutationsAndBdptAgreeOnCornellBox) {
  expectAgreementOnCornellBox("relt", "bdpt", 16, 20, [](RenderSettings& s) {
    replicaSettings(s).family.kind = FamilyKind::Kitaoka;
    replicaSettings(s).exchange.move = ExchangeMove::Permutation;
  });
}

TEST(IntegratorAgreement, ReltRelaxedWithPopulationAnnealingAndBdptAgreeOnCornellBox) {
  expectAgreementOnCornellBox("relt", "bdpt", 16, 20, [](RenderSettings& s) {
    replicaSettings(s).family.kind = FamilyKind::Relaxed;
    replicaSettings(s).init = InitKind::Annealing;
    replicaSettings(s).annealing.particles = 1024;
  });
}

TEST(IntegratorAgreement, ReltTemperedAndBdptAgreeOnCornellBox) {
  expectAgreementOnCornellBox("relt", "bdpt", 16, 20,
                              [](RenderSettings& s) { replicaSettings(s).family.kind = FamilyKind::Tempered; });
}

TEST(IntegratorAgreement, ReltTemperedAndBdptAgreeOnGlossyRing) {
  expectAgreement(glossyRing(), "relt", "bdpt", 16, 20,
                  [](RenderSettings& s) { replicaSettings(s).family.kind = FamilyKind::Tempered; });
}

// With regularisation no level targets I itself: the MIS over levels must still be unbiased.
TEST(IntegratorAgreement, ReltTemperedWithRegularisationAndBdptAgreeOnGlossyRing) {
  expectAgreement(glossyRing(), "relt", "bdpt", 16, 20, [](RenderSettings& s) {
    replicaSettings(s).family.kind = FamilyKind::Tempered;
    replicaSettings(s).family.regularisation = 0.1;
    replicaSettings(s).family.regularisationDecay = 0.1;  // fast enough to move during the test's render
  });
}

// (The parameterised furnace test above runs relt's default, kitaoka.)
TEST(ReltFurnace, RelaxedFamilyMatchesAnalyticValueWithinOnePercent) {
  RenderSettings s = settingsFor("relt", 7, 16, 32);
  replicaSettings(s).family.kind = FamilyKind::Relaxed;
  expectFurnaceWithinOnePercent(s);
}

TEST(ReltFurnace, TemperedFamilyMatchesAnalyticValueWithinOnePercent) {
  RenderSettings s = settingsFor("relt", 7, 16, 32);
  replicaSettings(s).family.kind = FamilyKind::Tempered;
  expectFurnaceWithinOnePercent(s);
}

// mmlt with 200 segments at most, the reported case: past about 127 segments a path's contribution
// (2^-(d-1)) is a subnormal float, past 145 it is 0 (those lengths get no chain, and carry less
// than 2^-144 of the image). Their chains' splats overflowed: every pixel NaN. The image must be
// the analytic value: each seed within 1 % (the furnace tolerance above) and the mean of the seeds
// within 4 standard errors, the standard error estimated from the seeds' spread (about 0.15 %;
// the bootstrap gives each of the 200 lengths only 500 samples, so b varies by about 0.3 %).
TEST(MmltFurnace, DeepMaxDepthWithFewChainsPerLengthMatchesAnalyticValue) {
  const std::string path = sourcePath("scenes/furnace.gltf");
  const double expected = furnaceValue(200);
  std::vector<double> means;
  for (uint64_t seed : {1, 2, 3, 4}) {
    RenderSettings s = settingsFor("mmlt", seed, 64, 32);
    s.chains = 256;  // one or two chains for most of the 144 lengths with a target
    s.maxDepth = 200;
    const Image image = renderInProcess(path, s);
    means.push_back(image.mean());
    EXPECT_NEAR(image.mean(), expected, 0.01 * expected) << "seed " << seed;
  }
  const Estimate e = meanAndStandardError(means);
  EXPECT_LT(std::abs(e.mean - expected), 4.0 * e.stderror) << e.mean << " +- " << e.stderror << " against " << expected;
}

// A mutation budget smaller than the chain count (8x8 pixels, 1 mutation per pixel, 256 chains):
// the last chains would take no step, and mmlt's plan gives them the longest lengths, whose share
// of the furnace (lengths 5-8: 6 %) was then lost. In the furnace the image mean is the sum of the
// lengths' normalisers, so one seed shows it.
TEST(MmltFurnace, ABudgetBelowTheChainCountKeepsEveryLength) {
  for (uint64_t seed : {1, 2}) {
    RenderSettings s = settingsFor("mmlt", seed, 1, 8);
    s.chains = 256;
    const Image image = renderInProcess(sourcePath("scenes/furnace.gltf"), s);
    EXPECT_NEAR(image.mean(), furnaceValue(8), 0.01 * furnaceValue(8)) << "seed " << seed;
  }
  EXPECT_EQ(chainsForBudget(256, false, 64), 64);
  EXPECT_EQ(chainsForBudget(256, true, 64), 256) << "a timed render has no such budget";
  EXPECT_EQ(chainsForBudget(256, false, 0), 1);
}
