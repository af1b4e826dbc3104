#include "mcmc/mmlt.h"

#include <algorithm>

#include "mcmc/chain_pool.h"

namespace relt {

float MmltEvaluator::operator()(int depth, SampleSource& u, PathSample& out) {
  out.clear();
  const int n = mmltStrategies(depth);
  const int pick = std::min(n - 1, static_cast<int>(u.next(SampleStream::Connection) * n));
  const int t = depth == 1 ? 2 : pick + 1;
  const int s = depth + 1 - t;
  const float x = u.next(SampleStream::Camera), y = u.next(SampleStream::Camera);
  if (!bdpt_.traceStrategy(s, t, Vec2(x * width_, y * height_), u, out)) return 0.0f;
  for (Splat& sp : out.splats) sp.value *= static_cast<float>(n);
  return out.target();
}

std::vector<double> mmltBootstrapTargets(MmltEvaluator& eval, uint64_t seed, int count, int first, int stride) {
  auto atItsDepth = [&](uint64_t i, SampleSource& u, PathSample& out) {
    return eval(mmltDepthOfBootstrap(i, eval.maxDepth()), u, out);
  };
  return bootstrapTargets(atItsDepth, seed, count, first, stride);
}

double mmltNormaliser(const std::vector<double>& targets, int maxDepth, const std::vector<ChainCounters>& perDepth) {
  std::vector<double> sum(static_cast<size_t>(maxDepth), 0.0), count(static_cast<size_t>(maxDepth), 0.0);
  for (size_t i = 0; i < targets.size(); ++i) {
    const size_t d = static_cast<size_t>(mmltDepthOfBootstrap(i, maxDepth) - 1);
    sum[d] += targets[i];
    count[d] += 1.0;
  }
  double b = 0.0;
  for (size_t d = 0; d < sum.size(); ++d)
    b += pooledNormaliser(sum[d], static_cast<uint64_t>(count[d]), d < perDepth.size() ? perDepth[d] : ChainCounters{});
  return b;
}

ChainCounters runMmltChains(MmltEvaluator& eval, const std::vector<double>& bootstrapTargets, uint64_t seed,
                            const PssmltSettings& settings, const std::vector<int>& chains, uint64_t totalMutations,
                            Film& film, std::vector<ChainCounters>* perDepth) {
  ChainPool pool(nullptr, &eval, bootstrapTargets, seed, settings, chains);
  pool.run(chainSteps(chains, totalMutations, settings.chains, pool.size()), film);
  if (perDepth) {
    *perDepth = pool.perDepth();
    if (perDepth->empty()) perDepth->assign(static_cast<size_t>(eval.maxDepth()), ChainCounters{});
  }
  return pool.counters();
}

}  // namespace relt
