#pragma once
// The Markov chains one rank owns (pssmlt or mmlt), kept alive between rounds so that a render can
// stop on a time budget or write snapshots at round boundaries. A chain's trajectory does not
// depend on how its steps are split into rounds.
#include <vector>

#include "mcmc/mmlt.h"
#include "mcmc/pssmlt.h"

namespace relt {

class ChainPool {
 public:
  // Exactly one evaluator: pssmlt chains (pss) or mmlt chains (mmlt; each at the depth of its
  // starting bootstrap sample).
  ChainPool(PssEvaluator* pss, MmltEvaluator* mmlt, const std::vector<double>& bootstrapTargets, uint64_t seed,
            const PssmltSettings& settings, const std::vector<int>& chains);

  // Advances chain i by steps[i] mutations (indices as in the `chains` given to the constructor).
  void run(const std::vector<uint64_t>& steps, Film& film);
  size_t size() const { return chains_.size(); }

  ChainCounters counters() const;
  // mmlt: counters per path length (index depth - 1); empty for pssmlt.
  std::vector<ChainCounters> perDepth() const;

 private:
  PssEvaluator* pss_;
  MmltEvaluator* mmlt_;
  std::vector<McmcChain> chains_;
  std::vector<int> depth_;
};

}  // namespace relt
