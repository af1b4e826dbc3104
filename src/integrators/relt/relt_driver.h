#pragma once
// The distributed part of replica exchange light transport: bootstrap shares, the round loop with
// its one collective (the job's gather of every rank's round message), snapshots. All decisions are
// taken by src/replica from the gathered data; this layer only moves it.
#include <vector>

#include "checkpoint/checkpoint_io.h"
#include "parallel/job.h"
#include "film/film.h"
#include "integrators/pssmlt/pssmlt_driver.h"
#include "render/renderer.h"
#include "replica/replica_pool.h"

namespace relt {

struct ReltOutcome {
  uint64_t rounds = 0;
  uint64_t stepsPerChain = 0;
  int ladders = 0, levels = 0;
  std::vector<std::string> levelNames;
  std::vector<std::string> leftOutNames;   // levels the bootstrap found idle (idleLevels)
  std::vector<double> normalisers;          // b_k at the end
  std::vector<LevelCounters> perLevel;      // summed over ranks
  ExchangeTally tally;
  uint64_t roundTrips = 0;
  Placement placement = Placement::Spread;  // in use (auto resolved)
  uint64_t chainMoves = 0;                  // chains moved between ranks by load balancing
  std::vector<int> chainsPerRank;           // placement at the end
  std::vector<double> stepMean, stepDeviation;  // per rank: seconds stepping a group for a round
  std::vector<double> nonFinitePerRank;         // per rank: proposals with NaN/Inf splats (dropped)
  std::vector<double> finishMean;               // per rank: seconds in a group round's finishRound
  std::vector<std::vector<double>> stepTrace;   // per rank (root only): seconds stepping each group round
  uint64_t bootstrapSamples = 0;
  double resolveDivisor = 0.0;              // film sums -> pixels
  double loopSeconds = 0.0;                 // the round loop (agreed elapsed time)
  std::vector<double> roundCollectiveSeconds;  // per rank: inside the round loop's collectives
};

// Renders every chain this rank hosts into `films`, which it sizes: one film, or one per level
// with --per-level (their sum is the image); not yet reduced. Continues `resumed` if given and
// writes checkpoints as the plan says. Collective.
ReltOutcome runRelt(Job& job, Renderer& renderer, const RenderSettings& settings,
                    std::vector<Film>& films, const SnapshotWriter& snapshot, const CheckpointPlan& plan,
                    const Resumed* resumed);

}  // namespace relt
