#pragma once
// Multiplexed MLT (Hachisuka et al. 2014; thesis digest §3.3): a chain lives at one path length
// (depth, in segments); the first number of its connection stream picks one BDPT strategy (s, t)
// of that length, and the target is that strategy's MIS-weighted contribution times the number
// of strategies. Subpaths have exact lengths, so BDPT runs without Russian roulette.
//
// The state space is the union over depths: bootstrap sample i has depth 1 + i mod D, chains
// start at bootstrap samples picked in proportion to their target (so chains spread over depths
// in proportion to each depth's normaliser b_d), and b = sum over d of b_d.
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

// Per-depth acceptance counters are kept too (stats.json reports them).
ChainCounters runMmltChains(MmltEvaluator& eval, const std::vector<double>& bootstrapTargets, uint64_t seed,
                            const PssmltSettings& settings, const std::vector<int>& chains, uint64_t totalMutations,
                            Film& film, std::vector<ChainCounters>* perDepth = nullptr);

}  // namespace relt
