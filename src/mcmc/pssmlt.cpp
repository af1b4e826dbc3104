#include "mcmc/pssmlt.h"

#include "core/words.h"

#include "mcmc/chain_pool.h"
#include "mcmc/metropolis.h"

namespace relt {
namespace {
constexpr uint64_t kBootstrapPurpose = 0xb007;
constexpr uint64_t kChainPurpose = 0xc4a1;
}  // namespace

uint64_t bootstrapKey(uint64_t seed, uint64_t index) { return hashKey(seed, kBootstrapPurpose, index); }
uint64_t chainKey(uint64_t seed, uint64_t chain) { return hashKey(seed, kChainPurpose, chain); }

std::vector<double> bootstrapTargets(PssEvaluator& eval, uint64_t seed, int count, int first, int stride) {
  return bootstrapTargets([&](uint64_t, SampleSource& u, PathSample& out) { return eval(u, out); }, seed, count, first,
                          stride);
}

uint64_t chainMutations(uint64_t total, int chains, int chain) {
  const uint64_t n = static_cast<uint64_t>(chains);
  return total / n + (static_cast<uint64_t>(chain) < total % n ? 1 : 0);
}

void ChainCounters::add(const ChainCounters& o) {
  smallProposed += o.smallProposed;
  smallAccepted += o.smallAccepted;
  largeProposed += o.largeProposed;
  largeAccepted += o.largeAccepted;
  invalidProposals += o.invalidProposals;
  largeTargetSum += o.largeTargetSum;
}

double pooledNormaliser(double bootstrapSum, uint64_t bootstrapCount, const ChainCounters& chains) {
  const double n = double(bootstrapCount) + double(chains.largeProposed);
  return n > 0.0 ? (bootstrapSum + chains.largeTargetSum) / n : 0.0;
}

McmcChain::McmcChain(uint64_t seed, int chain, const PssmltSettings& settings)
    : u_(chainKey(seed, static_cast<uint64_t>(chain)), settings.sizes),
      rng_(chainKey(seed, static_cast<uint64_t>(chain)), 1),
      pLarge_(settings.largeStepProbability) {}

std::vector<uint64_t> McmcChain::serialize() const {
  WordWriter w;
  w.u64(rng_.state());
  w.u64(rng_.increment());
  const ChainCounters& c = counters_;
  for (uint64_t v : {c.smallProposed, c.smallAccepted, c.largeProposed, c.largeAccepted, c.invalidProposals}) w.u64(v);
  w.f64(c.largeTargetSum);
  w.block(u_.serialize());
  return std::move(w.words());
}

StreamValues McmcChain::restoreState(const std::vector<uint64_t>& words) {
  WordReader in(words);
  const uint64_t state = in.u64(), increment = in.u64();
  rng_.restore(state, increment);
  ChainCounters& c = counters_;
  for (uint64_t* v : {&c.smallProposed, &c.smallAccepted, &c.largeProposed, &c.largeAccepted, &c.invalidProposals})
    *v = in.u64();
  c.largeTargetSum = in.f64();
  u_ = PrimarySampleVector::deserialize(in.block());
  if (!in.done()) throw std::runtime_error("trailing data after a chain's state");
  StreamValues values;  // every number the current path used (and maybe more: it reads a prefix)
  for (int s = 0; s < kSampleStreamCount; ++s)
    for (const PrimarySampleVector::Coordinate& x : u_.coordinates(static_cast<SampleStream>(s)))
      values[size_t(s)].push_back(x.value);
  return values;
}

}  // namespace relt
