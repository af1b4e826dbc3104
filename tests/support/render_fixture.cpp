#include "render_fixture.h"

#include <cmath>

#include "mcmc/erpt.h"
#include "mcmc/mmlt.h"
#include "mcmc/pssmlt.h"
#include "render/chain_settings.h"
#include "render/direct_pass.h"
#include "render/renderer.h"
#include "replica/replica_pool.h"
#include "replica/round_loop.h"
#include "replica/replica_schedule.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

namespace relt::test {

Image renderInProcess(const std::string& scene, RenderSettings settings) {
  settings.scenePath = scene;
  return renderInProcess(loadGltf(scene), settings);
}

Scene glossyRing() {
  Scene scene = loadGltf(sourcePath("scenes/ring.gltf"));
  for (Material& m : scene.materials)
    if (m.kind == MaterialKind::Conductor) m.alpha = 0.04f;
  return scene;
}

namespace {

// As the executable does it (integrators/render_driver.cpp): the directly seen emission first (every row
// here), then the chains, which it may hand that emission back to.
Image directEmission(Renderer& renderer) {
  const RenderSettings& s = renderer.settings();
  Film direct(s.width, s.height);
  const RankReduce one{[](double v) { return v; }, [](double v) { return v; }};
  const DirectPass pass = renderDirectPass(renderer, 0, 1, direct, one);
  return pass.spp > 0 ? Renderer::resolve(direct, direct.data(), pass.spp) : Image();
}

Image renderChainsOrSamples(Renderer& renderer);

}  // namespace

Image renderInProcess(Scene scene, RenderSettings settings) {
  Renderer renderer(std::move(scene), settings);
  const Image direct = directEmission(renderer);
  Image image = renderChainsOrSamples(renderer);
  if (!direct.rgb.empty()) image.add(direct);
  return image;
}

namespace {

Image renderChainsOrSamples(Renderer& renderer) {
  const RenderSettings& s = renderer.settings();
  Film film(s.width, s.height);
  if (s.integrator == Integrator::Relt) {
    // One process hosts every chain and runs the round loop of integrators/relt with a local transport.
    PerWorker<PssEvaluator> eval(s.threads, renderer.context(), s.width, s.height);
    const ReplicaSettings rs = effectiveReplicaSettings(s);
    ReplicaPool pool(eval, rs, s.seed, bootstrapFeatures(eval[0], rs.family, s.seed, rs.bootstrap, 0, 1), 0, 1);
    std::vector<Film> films(1, film);
    const double area = double(s.width) * s.height;
    const ReplicaSchedule schedule(area, pool.chainCount(), rs.exchangeInterval, std::nullopt,
                                   s.mutationsPerPixel.value_or(kDefaultMutationsPerPixel));
    LocalTransport transport;
    RoundLoopHooks hooks;
    hooks.elapsed = [] { return 0.0; };  // no timings: the placement of one rank never changes anyway
    const uint64_t rounds = runRoundLoop(pool, schedule, transport, films, hooks).rounds;
    pool.gatherWorkerFilms(films);
    return Renderer::resolve(films[0], films[0].data(), replicaResolveDivisor(schedule.stepsAfter(rounds), rs.ladders, area));
  }
  if (isMarkovChain(s.integrator)) {
    // One process plays every rank: all bootstrap samples, all chains (as integrators/pssmlt does).
    const PssmltSettings ps = pssmltSettings(s);
    const double area = double(s.width) * s.height;
    const auto total = static_cast<uint64_t>(std::llround(ps.mutationsPerPixel * area));
    std::vector<int> chains(static_cast<size_t>(ps.chains));
    for (int c = 0; c < ps.chains; ++c) chains[static_cast<size_t>(c)] = c;
    if (s.integrator == Integrator::Mmlt) {
      PerWorker<MmltEvaluator> mmlt(s.threads, renderer.context(), s.width, s.height);
      const std::vector<double> mt = mmltBootstrapTargets(mmlt[0], s.seed, ps.bootstrap, 0, 1);
      std::vector<ChainCounters> perDepth;
      runMmltChains(mmlt, mt, s.seed, ps, chains, total, film, &perDepth);
      const double b = mmltNormaliser(mt, s.maxDepth, perDepth);
      return Renderer::resolve(film, film.data(), pssmltResolveDivisor(total, b, area));
    }
    PerWorker<PssEvaluator> eval(s.threads, renderer.context(), s.width, s.height);
    const std::vector<double> targets = bootstrapTargets(eval[0], s.seed, ps.bootstrap, 0, 1);
    double sum = 0.0;
    for (double t : targets) sum += t;
    const ChainCounters counters = runChains(eval, targets, s.seed, ps, chains, total, film);
    const double b = pooledNormaliser(sum, targets.size(), counters);
    return Renderer::resolve(film, film.data(), pssmltResolveDivisor(total, b, area));
  }
  const int spp = s.spp.value_or(kDefaultSpp);
  if (s.integrator == Integrator::Erpt) {  // as integrators/erpt does, all work units here
    PtEvaluator eval(renderer.context(), s.width, s.height);
    const int bootstrap = kBootstrapPaths;
    const double b = erptBootstrapSum(eval, s.seed, bootstrap, 0, 1) / bootstrap;
    const ErptSettings es = erptSettings(s);
    for (int k = 0; k < spp; ++k)
      for (int row = 0; row < s.height; ++row) erptRow(eval, es, b, s.seed, static_cast<uint64_t>(k), row, 1.0, film);
    return Renderer::resolve(film, film.data(), spp);
  }
  for (int k = 0; k < spp; ++k)
    for (int row = 0; row < s.height; ++row) renderer.renderRow(static_cast<uint64_t>(k), row, film);
  return Renderer::resolve(film, film.data(), spp);
}

}  // namespace

double regionMean(const Image& image, int x0, int y0, int x1, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) sum += image.rgb[3 * (static_cast<size_t>(y) * image.width + x) + c];
  return sum / (3.0 * (x1 - x0) * (y1 - y0));
}

Estimate meanAndStandardError(const std::vector<double>& v) {
  Estimate e;
  for (double x : v) e.mean += x;
  e.mean /= static_cast<double>(v.size());
  double var = 0.0;
  for (double x : v) var += (x - e.mean) * (x - e.mean);
  var /= static_cast<double>(v.size() - 1);
  e.stderror = std::sqrt(var / static_cast<double>(v.size()));
  return e;
}

}  // namespace relt::test
