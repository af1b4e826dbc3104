#pragma once
// The distributed part of pssmlt and mmlt: bootstrap shares, chain ownership, and the sums.
#include <functional>

#include "checkpoint/checkpoint_io.h"
#include "parallel/job.h"
#include "film/film.h"
#include "mcmc/mmlt.h"
#include "mcmc/pssmlt.h"
#include "render/renderer.h"

namespace relt {

struct PssmltOutcome {
  double normaliser = 0.0;        // b: mean target of the bootstrap samples
  uint64_t totalMutations = 0;    // over all chains and ranks
  ChainCounters counters;         // summed over ranks
  uint64_t bootstrapSamples = 0;
  std::vector<ChainCounters> perDepth;  // mmlt: summed over ranks, one entry per path length
  uint64_t rounds = 0;
};

// Chain counters summed over all ranks (collective).
ChainCounters sumOverRanks(Job& job, const ChainCounters& c);

// Root only: writes the image so far, given reduced film sums and the divisor for resolve().
using SnapshotWriter = std::function<void(const std::vector<double>& sums, double divisor)>;

// pssmlt: a chain's state is a bdpt sample of any length; mmlt: of one length and strategy.
enum class ChainKind : uint8_t { Pssmlt, Mmlt };

// Runs every chain this rank owns into `film` (not yet reduced), pssmlt or mmlt; collective.
// --time stops at a round boundary all ranks agree on; --snapshot-every calls `snapshot`;
// `plan` writes checkpoints; a render resumed from `resumed` (or null) continues it without
// running the bootstrap again (its targets are in the checkpoint).
PssmltOutcome runPssmlt(Job& job, Renderer& renderer, const RenderSettings& settings, ChainKind kind, Film& film,
                        const SnapshotWriter& snapshot, const CheckpointPlan& plan = {},
                        const Resumed* resumed = nullptr);

}  // namespace relt
