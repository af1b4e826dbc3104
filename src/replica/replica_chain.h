#pragma once
// One Markov chain of a ladder (DESIGN §3.2): a point of primary sample space, the level it
// currently holds, its traced path and that path's targets under every level. A step is a
// Metropolis-Hastings step on q_level with Kelemen mutations; both states are splatted through the
// level estimator with expected-value weights. Levels change only between rounds, by exchanges.
#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/rng.h"
#include "core/sampling.h"
#include "film/splat_log.h"
#include "mcmc/pss_evaluator.h"
#include "mcmc/pssmlt.h"
#include "pss/primary_sample_vector.h"
#include "replica/level_estimator.h"
#include "replica/tempered_targets.h"

namespace relt {

// What a ladder's chains count per level (summed over chains by level held at the time). Invalid
// proposals: zero target at the chain's level, or a non-finite path.
struct LevelCounters : ChainCounters {
  uint64_t nonFinite = 0;  // proposals with a NaN or infinite splat (dropped, never splatted)
  double seconds = 0.0;    // time spent stepping at this level
  void add(const LevelCounters& o);
};

// Large steps are uniform samples of primary sample space: they refine every level's b.
struct LargeStepSums {
  explicit LargeStepSums(int levels = 0) : sum(size_t(levels), 0.0) {}
  // One large step's targets of every level.
  void addLargeStep(const double* q) {
    for (size_t k = 0; k < sum.size(); ++k) sum[k] += q[k];
    ++count;
  }
  std::vector<double> sum;
  uint64_t count = 0;
};

// Where a chain's steps go: splats straight into a film and large steps into the sums.
struct DirectOutput {
  Film& film;
  LargeStepSums& large;
  void addSplat(const Vec2& p, const Color& value, double weight) { film.addSplat(p, value, weight); }
  void addLargeStep(const std::vector<double>& q) { large.addLargeStep(q.data()); }
};

// The same kept in order (a worker thread's chain), for replayInto to add once its turn comes: the
// film and the sums then get exactly what DirectOutput would have given them.
struct alignas(64) ChainLog {  // aligned: neighbouring chains' logs are written by different workers
  SplatLog splats;
  std::vector<double> largeSteps;  // each large step's targets of every level, one after another
  void addSplat(const Vec2& p, const Color& value, double weight) { splats.addSplat(p, value, weight); }
  void addLargeStep(const std::vector<double>& q) { largeSteps.insert(largeSteps.end(), q.begin(), q.end()); }
  void replayInto(Film& film, LargeStepSums& large) const {
    splats.replayInto(film);
    for (size_t i = 0; i < largeSteps.size(); i += large.sum.size()) large.addLargeStep(&largeSteps[i]);
  }
  void clear() {
    splats.clear();
    largeSteps.clear();
  }
};

// Evaluates one point of primary sample space: the path's splats and every level's target.
// Targets are all 0 when the path is not finite (never accepted, never splatted); returns false then.
class LevelEvaluator {
 public:
  LevelEvaluator(PssEvaluator& eval, const LevelFamily& family);
  bool operator()(SampleSource& u, PathSample& out, double* q) const;
  // The same, giving the family's features of the path instead (LevelFamily::features).
  bool features(SampleSource& u, PathSample& out, double* f) const;
  const LevelFamily& family() const { return family_; }

 private:
  // Both are the worker's own scratch, changed by every evaluation.
  PssEvaluator& eval_;
  mutable std::optional<TemperedTargets> tempered_;  // the tempered family only
  const LevelFamily& family_;
};

// The random-stream key of chain c of a render.
uint64_t replicaChainKey(uint64_t seed, int chain);

class alignas(64) ReplicaChain {  // aligned: workers step neighbouring chains, which must share no cache line
 public:
  // `key` seeds the chain's mutations and decisions (replicaChainKey for a render's chains).
  ReplicaChain(uint64_t key, int level, const LevelFamily& family);
  // A chain continued from serialize() on another rank: the same future steps, bit for bit (the
  // current path is traced again from the state). Counters start at zero.
  ReplicaChain(const std::vector<uint64_t>& serialized, const LevelFamily& family, const LevelEvaluator& eval);
  std::vector<uint64_t> serialize() const;
  // The level a serialized chain holds.
  static int serializedLevel(const std::vector<uint64_t>& serialized) { return int(serialized.at(2)); }

  // Picks a bootstrap sample in proportion to its level's target (start-up bias elimination).
  size_t pickBootstrap(const Distribution1D& bootstrap) { return bootstrap.sample(rng_.uniform()); }
  // Picks one of `count` states uniformly (a population-annealing particle).
  size_t pickUniform(size_t count) { return rng_.below(static_cast<uint32_t>(count)); }
  // Starts at the point an independent source with `key` produces (a regenerated bootstrap sample),
  // or at `prefix` (a given state) continued by that source where the path needs more numbers.
  void start(const LevelEvaluator& eval, uint64_t key, const StreamValues& prefix = {});
  // `steps` Metropolis steps at the current level, splatted through the estimator into `out`
  // (DirectOutput or ChainLog), its large steps' targets too.
  template <class Output>
  void run(uint64_t steps, const LevelEvaluator& eval, const LevelEstimator& estimator, Output& out);
  // Evaluates the current state again (the targets changed: regularisation).
  void refresh(const LevelEvaluator& eval);
  // `steps` Metropolis steps that splat nothing (population annealing).
  void explore(uint64_t steps, const LevelEvaluator& eval);
  // The current point of primary sample space.
  StreamValues state() const;

  int level() const { return level_; }
  void setLevel(int level);
  // Every level's target on the current state.
  const double* targets() const { return current_.q.data(); }
  const std::vector<LevelCounters>& counters() const { return counters_; }

 private:
  struct State {
    PathSample path;
    std::vector<double> q;
  };
  // estimator and out null: nothing is splatted or summed.
  template <class Output>
  void step(const LevelEvaluator& eval, const LevelEstimator* estimator, Output* out);

  const LevelFamily& family_;
  PrimarySampleVector u_;
  Rng rng_;
  int level_;
  State current_, proposal_;
  std::vector<LevelCounters> counters_;
};

}  // namespace relt
