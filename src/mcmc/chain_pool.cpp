#include "mcmc/chain_pool.h"

namespace relt {

ChainPool::ChainPool(PssEvaluator* pss, MmltEvaluator* mmlt, const std::vector<double>& bootstrapTargets,
                     uint64_t seed, const PssmltSettings& settings, const std::vector<int>& chains)
    : pss_(pss), mmlt_(mmlt) {
  const Distribution1D bootstrap(bootstrapTargets);
  if (bootstrap.total() <= 0.0) return;  // nothing visible: no chains, the image stays black
  const MmltChainPlan plan =
      mmlt_ ? planMmltChains(bootstrapTargets, mmlt_->maxDepth(), settings.chains) : MmltChainPlan{};
  depthFilms_ = plan.stratified;
  const size_t depths = mmlt_ ? static_cast<size_t>(mmlt_->maxDepth()) : 0;
  // mmlt with a plan: a chain starts at one of its depth's bootstrap samples, in proportion to target.
  std::vector<Distribution1D> atDepth(depths);
  auto startsAtDepth = [&](int depth) -> const Distribution1D& {
    Distribution1D& dist = atDepth[static_cast<size_t>(depth - 1)];
    if (dist.empty()) {
      std::vector<double> masked(bootstrapTargets.size(), 0.0);
      for (size_t i = static_cast<size_t>(depth - 1); i < masked.size(); i += depths) masked[i] = bootstrapTargets[i];
      dist = Distribution1D(masked);
    }
    return dist;
  };
  chains_.reserve(chains.size());
  for (int c : chains) {
    McmcChain& chain = chains_.emplace_back(seed, c, settings);
    if (!mmlt_) {
      depth_.push_back(0);
      chain.start(*pss_, bootstrapKey(seed, chain.pickBootstrap(bootstrap)));
      continue;
    }
    int depth;
    size_t index;
    if (plan.stratified) {
      depth = plan.depth[static_cast<size_t>(c)];
      index = chain.pickBootstrap(startsAtDepth(depth));
    } else {
      index = chain.pickBootstrap(bootstrap);
      depth = mmltDepthOfBootstrap(index, mmlt_->maxDepth());
    }
    depth_.push_back(depth);
    chain.start([&](SampleSource& u, PathSample& out) { return (*mmlt_)(depth, u, out); }, bootstrapKey(seed, index));
  }
}

void ChainPool::run(const std::vector<uint64_t>& steps, Film& film) {
  if (depthFilms_ && films_.empty())
    films_.assign(static_cast<size_t>(mmlt_->maxDepth()), Film(film.width(), film.height()));
  for (size_t i = 0; i < chains_.size(); ++i) {
    McmcChain& chain = chains_[i];
    if (mmlt_) {
      const int depth = depth_[i];
      Film& target = depthFilms_ ? films_[static_cast<size_t>(depth - 1)] : film;
      auto atDepth = [&](SampleSource& u, PathSample& out) { return (*mmlt_)(depth, u, out); };
      for (uint64_t k = 0; k < steps[i]; ++k) chain.step(atDepth, target);
    } else {
      for (uint64_t k = 0; k < steps[i]; ++k) chain.step(*pss_, film);
    }
  }
}

void ChainPool::mergeDepthFilms(const std::vector<double>& weight, Film& into) const {
  for (size_t d = 0; d < films_.size(); ++d) into.addWeighted(films_[d], d < weight.size() ? weight[d] : 0.0);
}

ChainCounters ChainPool::counters() const {
  ChainCounters total;
  for (const McmcChain& c : chains_) total.add(c.counters());
  return total;
}

std::vector<ChainCounters> ChainPool::perDepth() const {
  if (!mmlt_) return {};
  std::vector<ChainCounters> d(static_cast<size_t>(mmlt_->maxDepth()));
  for (size_t i = 0; i < chains_.size(); ++i) d[static_cast<size_t>(depth_[i] - 1)].add(chains_[i].counters());
  return d;
}

}  // namespace relt
