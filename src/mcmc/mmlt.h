#pragma once
// Multiplexed MLT (Hachisuka et al. 2014; thesis digest §3.3): a chain lives at one path length
// (depth, in segments); the first number of its connection stream picks one BDPT strategy (s, t)
// of that length, and the target is that strategy's MIS-weighted contribution times the number
// of strategies. Subpaths have exact lengths, so BDPT runs without Russian roulette.
//
// The state space is the union over depths: bootstrap sample i has depth 1 + i mod D, and
// b = sum over d of b_d. Chains are spread over depths in proportion to b_d by a fixed plan
// (planMmltChains), not at random: with a random spread (pbrt-v4's, picking each chain's start in
// proportion to its target), each depth's share of the image is the random share of chains it
// drew, an error that no amount of running reduces (on cornell-box the directly seen light,
// depth 1, came out 4-20 % too bright in 10 s renders).
#include <cstdint>
#include <vector>

#include "mcmc/pssmlt.h"

namespace relt {

// Strategies for paths of `depth` segments with a pinhole camera (t >= 1, and (1,1) unused).
inline int mmltStrategies(int depth) { return depth == 1 ? 1 : depth + 1; }
inline int mmltDepthOfBootstrap(uint64_t index, int maxDepth) { return 1 + static_cast<int>(index % maxDepth); }

class MmltEvaluator {
 public:
  MmltEvaluator(const PathContext& ctx, int width, int height)
      : bdpt_(ctx, false), width_(width), height_(height), maxDepth_(ctx.settings.maxDepth) {}

  // Splats of one strategy at `depth` (scaled by the strategy count) and their target.
  float operator()(int depth, SampleSource& u, PathSample& out);
  int maxDepth() const { return maxDepth_; }

 private:
  Bdpt bdpt_;
  int width_, height_, maxDepth_;
};

struct MmltBootstrap {
  std::vector<double> targets;  // per bootstrap index (depth from mmltDepthOfBootstrap)
  double normaliser = 0.0;      // b = sum over depths of the mean target at that depth
};

// Targets of bootstrap samples first, first + stride, ... (others 0), as for pssmlt.
std::vector<double> mmltBootstrapTargets(MmltEvaluator& eval, uint64_t seed, int count, int first, int stride);
// b = sum over depths of b_d, each from that depth's bootstrap targets pooled with the large steps
// of the chains at that depth (perDepth may be empty: bootstrap only).
double mmltNormaliser(const std::vector<double>& targets, int maxDepth, const std::vector<ChainCounters>& perDepth = {});
// Weight of depth d's film (stratified plan): (b_d / b) (N / N_d) with N_d the steps taken at depth d
// and N all steps, so that the usual resolve (b area / N) gives each depth b_d area / N_d.
std::vector<double> mmltDepthWeights(const std::vector<double>& targets, int maxDepth,
                                     const std::vector<ChainCounters>& perDepth);

// Which depth each chain runs at: n_d chains at depth d, by largest remainder of C b_d / b with at
// least one for every depth with b_d > 0 (b_d: the bootstrap mean at depth d). Each depth's chains
// splat into a film of their own, and the films are added with weights from each depth's own
// normaliser and step count (mmltDepthWeights), so a depth's share of the image is estimated
// from all its large steps rather than fixed by the bootstrap. With fewer chains than such depths
// `stratified` is false: chains pick their starts in proportion to their targets over all depths
// and splat into one film, as in pbrt-v4.
struct MmltChainPlan {
  bool stratified = false;
  std::vector<int> depth;  // per chain index (stratified only)
};
MmltChainPlan planMmltChains(const std::vector<double>& bootstrapTargets, int maxDepth, int chains);

}  // namespace relt
