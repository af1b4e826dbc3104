#include "mcmc/mmlt.h"

#include <algorithm>
#include <cmath>

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

namespace {

// b_d for every depth: bootstrap targets at that depth pooled with the large steps taken there.
std::vector<double> depthNormalisers(const std::vector<double>& targets, int maxDepth,
                                     const std::vector<ChainCounters>& perDepth) {
  std::vector<double> sum(static_cast<size_t>(maxDepth), 0.0), count(static_cast<size_t>(maxDepth), 0.0);
  for (size_t i = 0; i < targets.size(); ++i) {
    const size_t d = static_cast<size_t>(mmltDepthOfBootstrap(i, maxDepth) - 1);
    sum[d] += targets[i];
    count[d] += 1.0;
  }
  std::vector<double> b(sum.size());
  for (size_t d = 0; d < sum.size(); ++d)
    b[d] = pooledNormaliser(sum[d], static_cast<uint64_t>(count[d]), d < perDepth.size() ? perDepth[d] : ChainCounters{});
  return b;
}

}  // namespace

double mmltNormaliser(const std::vector<double>& targets, int maxDepth, const std::vector<ChainCounters>& perDepth) {
  double b = 0.0;
  for (double bd : depthNormalisers(targets, maxDepth, perDepth)) b += bd;
  return b;
}

std::vector<double> mmltDepthWeights(const std::vector<double>& targets, int maxDepth,
                                     const std::vector<ChainCounters>& perDepth) {
  const std::vector<double> bd = depthNormalisers(targets, maxDepth, perDepth);
  double b = 0.0, steps = 0.0;
  for (size_t d = 0; d < bd.size(); ++d) {
    b += bd[d];
    if (d < perDepth.size()) steps += double(perDepth[d].smallProposed + perDepth[d].largeProposed);
  }
  std::vector<double> w(bd.size(), 0.0);
  for (size_t d = 0; d < bd.size() && d < perDepth.size(); ++d) {
    const double nd = double(perDepth[d].smallProposed + perDepth[d].largeProposed);
    if (nd > 0.0 && b > 0.0) w[d] = bd[d] / b * steps / nd;
  }
  return w;
}

MmltChainPlan planMmltChains(const std::vector<double>& targets, int maxDepth, int chains) {
  const size_t depths = static_cast<size_t>(maxDepth);
  std::vector<double> share = depthNormalisers(targets, maxDepth, {});  // bootstrap means b_d
  double b = 0.0;
  for (double bd : share) b += bd;
  MmltChainPlan plan;
  const auto lit = static_cast<int>(std::count_if(share.begin(), share.end(), [](double x) { return x > 0.0; }));
  if (!(b > 0.0) || chains < lit) return plan;
  for (double& x : share) x /= b;
  // One chain for every lit depth; the other R = C - lit in proportion to how far each depth's
  // quota C share_d exceeds that one chain, whole parts first, then one each by largest remainder.
  const int spare = chains - lit;
  std::vector<double> excess(depths, 0.0);
  double excessSum = 0.0;
  for (size_t d = 0; d < depths; ++d)
    if (share[d] > 0.0) excessSum += excess[d] = std::max(0.0, share[d] * chains - 1.0);
  std::vector<int> n(depths, 0);
  std::vector<std::pair<double, size_t>> remainders;  // (remainder, depth), largest first
  int given = 0;
  for (size_t d = 0; d < depths; ++d) {
    if (!(share[d] > 0.0)) continue;
    const double extra = spare * (excessSum > 0.0 ? excess[d] / excessSum : share[d]);
    n[d] = 1 + static_cast<int>(extra);
    given += n[d];
    remainders.emplace_back(extra - std::floor(extra), d);
  }
  std::stable_sort(remainders.begin(), remainders.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  for (size_t k = 0; given < chains && k < remainders.size(); ++k, ++given) ++n[remainders[k].second];
  plan.stratified = true;
  for (size_t d = 0; d < depths; ++d) plan.depth.insert(plan.depth.end(), static_cast<size_t>(n[d]), static_cast<int>(d) + 1);
  return plan;
}

}  // namespace relt
