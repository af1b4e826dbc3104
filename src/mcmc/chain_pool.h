#pragma once
// The Markov chains one rank owns (pssmlt or mmlt), kept alive between rounds so that a render can
// stop on a time budget or write snapshots at round boundaries. A chain's trajectory does not
// depend on how its steps are split into rounds, nor on the worker thread that steps it.
#include <vector>

#include "mcmc/mmlt.h"
#include "mcmc/pssmlt.h"
#include "film/splat_log.h"
#include "parallel/per_worker.h"

namespace relt {

class ChainPool {
 public:
  // Exactly one kind of evaluator: pssmlt chains (pss) or mmlt chains (mmlt; each at the depth of
  // its starting bootstrap sample). One evaluator per worker thread: run() steps chain i on
  // worker i mod workers.
  ChainPool(PerWorker<PssEvaluator>* pss, PerWorker<MmltEvaluator>* mmlt,
            const std::vector<double>& bootstrapTargets, uint64_t seed, const PssmltSettings& settings,
            const std::vector<int>& chains);

  // Advances chain i by steps[i] mutations (indices as in the `chains` given to the constructor).
  // Splats go to `film`, except for mmlt with a stratified plan: to one film per depth. With
  // several workers each takes the next chain when free and its splats are added in chain order
  // (runInOrder): the films are bit for bit those of one worker.
  void run(const std::vector<uint64_t>& steps, Film& film);
  // mmlt, stratified: adds weight[d] x depth d's film to `into` (see mmltDepthWeights); else nothing.
  void mergeDepthFilms(const std::vector<double>& weight, Film& into) const;
  size_t size() const { return chains_.size(); }
  // The global ids of the chains, in the order of `run`'s steps.
  const std::vector<int>& ids() const { return ids_; }

  // mmlt, stratified: depth d's film (index d - 1), made on all ranks alike even without chains, so
  // that checkpoints reduce the same films everywhere; else none.
  std::vector<Film>& depthFilms(int width, int height);

  // Checkpoints: every chain's global id, depth and state. restore() takes the chains this pool
  // holds from any old rank's part (the ranks then may have held other chains) and traces their
  // current paths again; it throws std::runtime_error if one is missing or the parts are malformed.
  std::vector<uint64_t> checkpointPart() const;
  void restore(const std::vector<std::vector<uint64_t>>& parts);

  ChainCounters counters() const;
  // mmlt: counters per path length (index depth - 1); empty for pssmlt.
  std::vector<ChainCounters> perDepth() const;

 private:
  PerWorker<PssEvaluator>* pss_;
  PerWorker<MmltEvaluator>* mmlt_;
  int workers() const { return mmlt_ ? mmlt_->size() : pss_->size(); }
  int maxDepth() const { return (*mmlt_)[0].maxDepth(); }
  // f(worker's evaluator of chain i): pssmlt's, or mmlt's at the chain's depth.
  template <class F>
  void withEvaluator(size_t i, int worker, F&& f);
  // The film chain i splats into.
  Film& filmOf(size_t i, Film& film);

  std::vector<int> ids_;  // global chain ids, as given to the constructor
  std::vector<McmcChain> chains_;
  std::vector<int> depth_;
  bool depthFilms_ = false;  // mmlt with a stratified plan
  std::vector<Film> films_;  // per depth - 1, sized on first use
  std::vector<SplatLog> logs_;  // with several workers: each chain's splats of a run, until their turn
};

}  // namespace relt
