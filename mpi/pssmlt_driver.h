#pragma once
// The distributed part of pssmlt and mmlt: bootstrap shares, chain ownership, and the sums.
#include "comm.h"
#include "film/film.h"
#include "mcmc/mmlt.h"
#include "mcmc/pssmlt.h"
#include "render/renderer.h"

namespace relt::mpi {

struct PssmltOutcome {
  double normaliser = 0.0;        // b: mean target of the bootstrap samples
  uint64_t totalMutations = 0;    // over all chains and ranks
  ChainCounters counters;         // summed over ranks
  uint64_t bootstrapSamples = 0;
  std::vector<ChainCounters> perDepth;  // mmlt: summed over ranks, one entry per path length
};

// Runs every chain this rank owns into `film` (not yet reduced), pssmlt or mmlt; collective.
PssmltOutcome runPssmlt(const Session& session, Renderer& renderer, const RenderSettings& settings, Film& film);

}  // namespace relt::mpi
