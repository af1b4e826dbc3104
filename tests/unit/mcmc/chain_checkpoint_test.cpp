// Chains continued from their checkpoint state take the same steps as the chains that never
// stopped, bit for bit: McmcChain::serialize/restore (the current path traced again from the
// numbers of its state) and ChainPool's parts, restored into a pool that holds other chains than
// the ones that wrote them (a resume on another rank count).
#include <gtest/gtest.h>

#include "mcmc/chain_pool.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "test_support.h"
#include "integrators/registry.h"

using namespace relt;

namespace {

RenderSettings small(const std::string& integrator) {
  RenderSettings s;
  selectIntegrator(s, integrator);
  s.scenePath = test::sourcePath("scenes/cornell-box.gltf");
  s.width = 16;
  s.height = 12;
  s.seed = 7;
  return s;
}

void expectSame(const Film& a, const Film& b) {
  EXPECT_TRUE(a.data() == b.data()) << "films differ";
  double sum = 0.0;
  for (double v : a.data()) sum += v;
  EXPECT_GT(sum, 0.0);
}

void expectSame(const ChainCounters& a, const ChainCounters& b) {
  EXPECT_EQ(a.smallProposed, b.smallProposed);
  EXPECT_EQ(a.smallAccepted, b.smallAccepted);
  EXPECT_EQ(a.largeAccepted, b.largeAccepted);
  EXPECT_EQ(a.invalidProposals, b.invalidProposals);
  EXPECT_EQ(a.largeTargetSum, b.largeTargetSum);
}

}  // namespace

TEST(ChainCheckpoint, ARestoredChainContinuesBitForBit) {
  Renderer renderer(loadGltf(small("pssmlt").scenePath), small("pssmlt"));
  PssEvaluator eval(renderer.context(), 16, 12);
  PssmltSettings settings;
  const std::vector<double> targets = bootstrapTargets(eval, 7, 1000, 0, 1);
  McmcChain chain(7, 3, settings);
  chain.start(eval, bootstrapKey(7, chain.pickBootstrap(Distribution1D(targets))));
  Film before(16, 12), a(16, 12), b(16, 12);
  for (int k = 0; k < 200; ++k) chain.step(eval, before);
  McmcChain restored(99, 0, settings);  // another chain's streams: all of them are overwritten
  restored.restore(eval, chain.serialize());
  EXPECT_EQ(restored.target(), chain.target());
  for (int k = 0; k < 300; ++k) {
    chain.step(eval, a);
    restored.step(eval, b);
  }
  expectSame(a, b);
  expectSame(chain.counters(), restored.counters());
  EXPECT_THROW(restored.restore(eval, {1, 2, 3}), std::runtime_error);
}

// mmlt with a stratified plan (a film per depth): chains written by two "ranks" (even and odd ids)
// and restored into one pool continue as the pool that ran them all.
TEST(ChainCheckpoint, ChainPoolPartsRestoreIntoAnyOwnership) {
  const RenderSettings s = small("mmlt");
  Renderer renderer(loadGltf(s.scenePath), s);
  PerWorker<MmltEvaluator> eval(1, renderer.context(), 16, 12);
  PssmltSettings settings;
  settings.chains = 24;
  const std::vector<double> targets = mmltBootstrapTargets(eval[0], 7, 2000, 0, 1);
  std::vector<int> all, even, odd;
  for (int c = 0; c < settings.chains; ++c) (c % 2 ? odd : even).push_back(c), all.push_back(c);
  ChainPool whole(nullptr, &eval, targets, 7, settings, all), evens(nullptr, &eval, targets, 7, settings, even),
      odds(nullptr, &eval, targets, 7, settings, odd), resumed(nullptr, &eval, targets, 7, settings, all);
  Film film(16, 12);
  whole.run(std::vector<uint64_t>(all.size(), 40), film);
  evens.run(std::vector<uint64_t>(even.size(), 40), film);
  odds.run(std::vector<uint64_t>(odd.size(), 40), film);
  resumed.restore({evens.checkpointPart(), odds.checkpointPart()});
  std::vector<Film>& wholeDepths = whole.depthFilms(16, 12);
  ASSERT_FALSE(wholeDepths.empty()) << "a stratified plan";
  for (Film& f : wholeDepths) f = Film(16, 12);  // both continue from empty films
  Film a(16, 12), b(16, 12);
  whole.run(std::vector<uint64_t>(all.size(), 60), a);
  resumed.run(std::vector<uint64_t>(all.size(), 60), b);
  const std::vector<Film>& resumedDepths = resumed.depthFilms(16, 12);
  Film mergedA(16, 12), mergedB(16, 12);
  whole.mergeDepthFilms(std::vector<double>(wholeDepths.size(), 1.0), mergedA);
  resumed.mergeDepthFilms(std::vector<double>(resumedDepths.size(), 1.0), mergedB);
  expectSame(mergedA, mergedB);
  expectSame(whole.counters(), resumed.counters());
  EXPECT_THROW(resumed.restore({evens.checkpointPart()}), std::runtime_error) << "the odd chains are missing";
}
