#pragma once
// Population annealing down a ladder (Kitaoka et al. 2009 Sec. 4.3, Alg. 2): starting states for
// every level that follow its target more closely than a one-time resampling of the bootstrap when
// the levels differ much. Particles are resampled from the bootstrap in proportion to the top
// (flattest) level's target; then, level by level from the top down, they take a few Metropolis
// steps of that level, become its starting states, and are reweighted by q_{k-1} / q_k and
// resampled for the next level. Every rank runs it whole with the same keys, so all agree without
// shipping states; the cost is particles x levels x (mutations + 1) path evaluations per rank.
#include <cstdint>
#include <vector>

#include "replica/replica_chain.h"
#include "replica/replica_settings.h"

namespace relt {

// starts[k] = level k's particles. bootstrapTargets[k][i] = q_k of bootstrap sample i.
std::vector<std::vector<StreamValues>> annealedStarts(const LevelEvaluator& eval, const LevelFamily& family,
                                                      const std::vector<std::vector<double>>& bootstrapTargets,
                                                      uint64_t seed, const AnnealingSettings& settings);

}  // namespace relt
