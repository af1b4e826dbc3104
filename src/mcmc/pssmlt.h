#pragma once
// Primary-sample-space MLT over BDPT (Kelemen et al. 2002; thesis digest §2, §3.2): many chains,
// each a Metropolis-Hastings walk on I(u) with Kelemen mutations and expected-value splatting,
// started from a bootstrap set (start-up bias elimination) that also estimates the normaliser b.
//
// Everything here is rank-agnostic: bootstrap sample i and chain c have their own random streams,
// keyed by (seed, i) and (seed, c), so any rank can compute any of them. The MPI layer decides who
// computes what (ownsChain, bootstrap stride) and sums the results.
#include <cstdint>
#include <vector>

#include "core/sampling.h"
#include "film/film.h"
#include "mcmc/metropolis.h"
#include "mcmc/pss_evaluator.h"
#include "parallel/per_worker.h"
#include "pss/chain_defaults.h"
#include "pss/primary_sample_vector.h"

namespace relt {

struct PssmltSettings {
  double mutationsPerPixel = kDefaultMutationsPerPixel;
  int chains = 256;
  float largeStepProbability = kDefaultLargeStepProbability;
  int bootstrap = kBootstrapPaths;
  KelemenSizes sizes;
};

uint64_t bootstrapKey(uint64_t seed, uint64_t index);
uint64_t chainKey(uint64_t seed, uint64_t chain);

// Targets of the bootstrap samples i = first, first + stride, ... (others left at 0), so that ranks
// can each fill their share and sum the vectors. `target(i, u, sample)` evaluates sample i on the
// independent source u keyed by bootstrapKey(seed, i).
template <class Target>
std::vector<double> bootstrapTargets(Target&& target, uint64_t seed, int count, int first, int stride) {
  std::vector<double> targets(static_cast<size_t>(count), 0.0);
  PathSample sample;
  for (int i = first; i < count; i += stride) {
    IndependentSource u(bootstrapKey(seed, static_cast<uint64_t>(i)));
    targets[static_cast<size_t>(i)] = target(static_cast<uint64_t>(i), u, sample);
  }
  return targets;
}
// pssmlt's bootstrap: I(u_i) for every sample.
std::vector<double> bootstrapTargets(PssEvaluator& eval, uint64_t seed, int count, int first, int stride);

// Chain c runs on rank c mod ranks; it makes an even share of all mutations.
inline bool ownsChain(int chain, int rank, int ranks) { return chain % ranks == rank; }
uint64_t chainMutations(uint64_t total, int chains, int chain);
// The chains a render runs: with a mutation budget smaller than the chain count the last chains
// would take no step, and mmlt's plan gives those whole path lengths, whose share of the image
// would then be lost (a length's weight needs its mutations); so at most one chain per mutation.
inline int chainsForBudget(int chains, bool timed, uint64_t totalMutations) {
  if (timed || totalMutations >= uint64_t(chains)) return chains;
  return int(totalMutations > 0 ? totalMutations : 1);
}

struct ChainCounters {
  uint64_t smallProposed = 0, smallAccepted = 0, largeProposed = 0, largeAccepted = 0;
  uint64_t invalidProposals = 0;  // zero or non-finite target: rejected, never splatted
  // Large steps are independent uniform samples: their targets refine the normaliser b
  // (thesis digest §2.6, Eq. 6.4).
  double largeTargetSum = 0.0;
  void add(const ChainCounters& o);
};

// One Metropolis-Hastings chain on a point of primary sample space. `Eval` is any callable
// (SampleSource&, PathSample&) -> target, e.g. PssEvaluator or MMLT's fixed-length evaluator.
class alignas(64) McmcChain {  // aligned: workers step neighbouring chains, which must share no cache line
 public:
  McmcChain(uint64_t seed, int chain, const PssmltSettings& settings);

  // Picks a bootstrap sample in proportion to its target (start-up bias elimination).
  size_t pickBootstrap(const Distribution1D& bootstrap) { return bootstrap.sample(rng_.uniform()); }
  // Starts at the point an independent source with `key` produces (a regenerated bootstrap sample).
  template <class Eval>
  void start(Eval&& eval, uint64_t key);
  // One step. Both states are splatted with their expected-value weights divided by their target;
  // the film then needs the factor b * filmArea / (total mutations).
  // `film`: a Film or a SplatLog (a worker's chain, added in chain order later).
  template <class Eval, class Sink>
  void step(Eval&& eval, Sink& film);

  const ChainCounters& counters() const { return counters_; }
  float target() const { return target_; }

  // Everything the chain continues from (checkpoints): random stream, point, counters.
  std::vector<uint64_t> serialize() const;
  // Continues a serialize()d chain bit for bit; the current path is traced again from the numbers
  // its state holds, so `eval` must be the one the chain ran with. Throws std::runtime_error on
  // malformed words.
  template <class Eval>
  void restore(Eval&& eval, const std::vector<uint64_t>& words);

 private:
  template <class Sink>
  void finishStep(bool large, float proposed, Sink& film);
  // restore() without the re-evaluation: the numbers the current path used.
  StreamValues restoreState(const std::vector<uint64_t>& words);

  PrimarySampleVector u_;
  Rng rng_;
  float pLarge_;
  PathSample current_, proposal_;
  float target_ = 0.0f;
  ChainCounters counters_;
};

template <class Eval>
void McmcChain::start(Eval&& eval, uint64_t key) {
  RecordingSource source(key);
  target_ = eval(source, current_);
  for (int s = 0; s < kSampleStreamCount; ++s)
    u_.setState(static_cast<SampleStream>(s), source.values(static_cast<SampleStream>(s)));
}

template <class Eval, class Sink>
void McmcChain::step(Eval&& eval, Sink& film) {
  const bool large = rng_.uniform() < pLarge_;
  u_.startIteration(large);
  finishStep(large, eval(u_, proposal_), film);
}

template <class Sink>
void McmcChain::finishStep(bool large, float proposed, Sink& film) {
  const float a = acceptance(target_, proposed);
  (large ? counters_.largeProposed : counters_.smallProposed)++;
  if (large) counters_.largeTargetSum += proposed;
  if (!(proposed > 0.0f)) ++counters_.invalidProposals;
  // Expected values (thesis digest §2.7): the current state with 1 - a, the proposal with a, each
  // over its own target (the density the chain samples it with, up to b). In double: a target
  // below 2^-126 (mmlt's long paths) is a subnormal float whose reciprocal overflows float.
  if (target_ > 0.0f && a < 1.0f) film.addSample(current_, (1.0 - double(a)) / double(target_));
  if (a > 0.0f) film.addSample(proposal_, double(a) / double(proposed));
  if (keepOrRevert(rng_.uniform() < a, u_, current_, proposal_)) {
    target_ = proposed;
    (large ? counters_.largeAccepted : counters_.smallAccepted)++;
  }
}

template <class Eval>
void McmcChain::restore(Eval&& eval, const std::vector<uint64_t>& words) {
  RecordingSource replay(0, restoreState(words));
  target_ = eval(replay, current_);
}

// b from the bootstrap targets and the large steps together (both are uniform samples of I).
double pooledNormaliser(double bootstrapSum, uint64_t bootstrapCount, const ChainCounters& chains);

// Film sums -> pixels: pixel = b * film area / N * sums, written as the divisor Renderer::resolve
// takes (its "samples per pixel"); 0 (black) when nothing was visible.
inline double pssmltResolveDivisor(uint64_t totalMutations, double normaliser, double filmArea) {
  return normaliser > 0.0 ? double(totalMutations) / (normaliser * filmArea) : 0.0;
}

}  // namespace relt
