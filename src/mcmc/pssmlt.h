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
#include "mcmc/pss_evaluator.h"
#include "pss/primary_sample_vector.h"

namespace relt {

struct PssmltSettings {
  double mutationsPerPixel = 16.0;
  int chains = 256;
  float largeStepProbability = 0.3f;
  int bootstrap = 100000;
  KelemenSizes sizes;
};

uint64_t bootstrapKey(uint64_t seed, uint64_t index);
uint64_t chainKey(uint64_t seed, uint64_t chain);

// Targets I(u_i) of the bootstrap samples i = first, first + stride, ... (others left at 0), so
// that ranks can each fill their share and sum the vectors.
std::vector<double> bootstrapTargets(PssEvaluator& eval, uint64_t seed, int count, int first, int stride);

// Chain c runs on rank c mod ranks; it makes an even share of all mutations.
inline bool ownsChain(int chain, int rank, int ranks) { return chain % ranks == rank; }
uint64_t chainMutations(uint64_t total, int chains, int chain);

struct ChainCounters {
  uint64_t smallProposed = 0, smallAccepted = 0, largeProposed = 0, largeAccepted = 0;
  uint64_t invalidProposals = 0;  // zero or non-finite target: rejected, never splatted
  void add(const ChainCounters& o);
};

class PssmltChain {
 public:
  PssmltChain(uint64_t seed, int chain, const PssmltSettings& settings);

  // Picks the starting bootstrap sample in proportion to its target and regenerates it.
  void start(PssEvaluator& eval, const Distribution1D& bootstrap, uint64_t seed);
  // One Metropolis-Hastings step. Both states are splatted with their expected-value weights
  // divided by their target; the film then needs the factor b * filmArea / (total mutations).
  void step(PssEvaluator& eval, Film& film);

  const ChainCounters& counters() const { return counters_; }
  float target() const { return target_; }

 private:
  PrimarySampleVector u_;
  Rng rng_;
  float pLarge_;
  PathSample current_, proposal_;
  float target_ = 0.0f;
  ChainCounters counters_;
};

// Film sums -> pixels: pixel = b * film area / N * sums, written as the divisor Renderer::resolve
// takes (its "samples per pixel"); 0 (black) when nothing was visible.
inline double pssmltResolveDivisor(uint64_t totalMutations, double normaliser, double filmArea) {
  return normaliser > 0.0 ? double(totalMutations) / (normaliser * filmArea) : 0.0;
}

// Runs `mutations` steps of every chain in `chains` on one film (what one rank does).
ChainCounters runChains(PssEvaluator& eval, const std::vector<double>& bootstrapTargets, uint64_t seed,
                        const PssmltSettings& settings, const std::vector<int>& chains, uint64_t totalMutations,
                        Film& film);

}  // namespace relt
