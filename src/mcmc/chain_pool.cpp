#include "mcmc/chain_pool.h"

namespace relt {

ChainPool::ChainPool(PssEvaluator* pss, MmltEvaluator* mmlt, const std::vector<double>& bootstrapTargets,
                     uint64_t seed, const PssmltSettings& settings, const std::vector<int>& chains)
    : pss_(pss), mmlt_(mmlt) {
  const Distribution1D bootstrap(bootstrapTargets);
  if (bootstrap.total() <= 0.0) return;  // nothing visible: no chains, the image stays black
  chains_.reserve(chains.size());
  for (int c : chains) {
    McmcChain& chain = chains_.emplace_back(seed, c, settings);
    const size_t index = chain.pickBootstrap(bootstrap);
    const int depth = mmlt_ ? mmltDepthOfBootstrap(index, mmlt_->maxDepth()) : 0;
    depth_.push_back(depth);
    if (mmlt_)
      chain.start([&](SampleSource& u, PathSample& out) { return (*mmlt_)(depth, u, out); }, bootstrapKey(seed, index));
    else
      chain.start(*pss_, bootstrapKey(seed, index));
  }
}

void ChainPool::run(const std::vector<uint64_t>& steps, Film& film) {
  for (size_t i = 0; i < chains_.size(); ++i) {
    McmcChain& chain = chains_[i];
    if (mmlt_) {
      const int depth = depth_[i];
      auto atDepth = [&](SampleSource& u, PathSample& out) { return (*mmlt_)(depth, u, out); };
      for (uint64_t k = 0; k < steps[i]; ++k) chain.step(atDepth, film);
    } else {
      for (uint64_t k = 0; k < steps[i]; ++k) chain.step(*pss_, film);
    }
  }
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
