#pragma once
// Replica exchange light transport (`relt`): C = L ladders x M levels chains, chain c in ladder
// c / M starting at level c mod M. A rank hosts some chains (placement), steps them for a round,
// and contributes one message to the round's one collective: its chains' targets under every
// level, its large-step sums and its elapsed time. From all messages every rank runs the same
// exchange per ladder (a per-ladder stream keyed by seed, ladder and round) and updates every
// chain's level label; states never move. Rank-agnostic: the image depends on (seed, L, M, steps).
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "film/film.h"
#include "replica/exchange.h"
#include "replica/family.h"
#include "replica/level_estimator.h"
#include "replica/load_balance.h"
#include "replica/replica_settings.h"
#include "replica/replica_chain.h"

namespace relt {

// The family's features (LevelFamily::featureCount per sample) of bootstrap samples first,
// first + stride, ... (others 0), for ranks to fill their share and sum.
std::vector<double> bootstrapFeatures(PssEvaluator& eval, const FamilySettings& family, uint64_t seed, int count,
                                      int first, int stride);

class ReplicaPool {
 public:
  // `bootstrap` holds every bootstrap sample's features (bootstrapFeatures, summed over ranks).
  ReplicaPool(PssEvaluator& eval, const ReplicaSettings& settings, uint64_t seed, const std::vector<double>& bootstrap,
              int rank, int ranks);
  ReplicaPool(const ReplicaPool&) = delete;  // chains refer to family_
  ReplicaPool& operator=(const ReplicaPool&) = delete;

  const LevelFamily& family() const { return family_; }
  const LevelEstimator& estimator() const { return estimator_; }
  int levels() const { return family_.levels(); }
  int chainCount() const { return settings_.ladders * levels(); }
  // False when no bootstrap sample saw light: the image is black and no chain runs.
  bool active() const { return active_; }

  // Steps every hosted chain `steps` times. films: one, or one per level (per-level layers).
  void runRound(uint64_t steps, std::vector<Film>& films);
  // This rank's message for the round's collective (`roundSeconds`: time this rank spent in
  // runRound), and the length any rank's message has (it changes when chains move).
  std::vector<double> roundMessage(double elapsed, double roundSeconds);
  size_t messageLength(int rank) const;
  // Reads every rank's message (rank order): exchanges in every ladder, new level labels, new
  // normalisers, and after every balance window a new placement from the ranks' speeds
  // (moves planned). Returns the largest elapsed time of the messages.
  double finishRound(const std::vector<std::vector<double>>& messages, uint64_t round);

  // Chain migration after finishRound, the same plan on every rank: the sender exports each chain
  // it gives, the receiver imports it, then every rank commits (the placement changes).
  const std::vector<ChainMove>& plannedMoves() const { return moves_; }
  std::vector<uint64_t> exportChain(int chain);
  void importChain(int chain, const std::vector<uint64_t>& state);
  void commitMoves();
  uint64_t chainMoves() const { return chainMoves_; }  // chains moved so far
  int hostedCount(int rank) const { return int(hostedByRank_[size_t(rank)].size()); }

  // Diagnostics. Exchange tallies and round trips are the same on every rank; level counters
  // cover the hosted chains (the MPI layer sums them).
  const ExchangeTally& tally() const { return tally_; }
  const RoundTrips& roundTrips() const { return trips_; }
  std::vector<LevelCounters> hostedCounters() const;
  const std::vector<double>& normalisers() const { return estimator_.normalisers(); }
  int levelOf(int chain) const { return levelOf_[size_t(chain)]; }

 private:
  const std::vector<int>& hosted() const { return hostedByRank_[size_t(rank_)]; }

  ReplicaSettings settings_;
  uint64_t seed_;
  int rank_, ranks_;
  LevelFamily family_;
  LevelEstimator estimator_;
  LevelEvaluator evaluator_;
  bool active_ = false;
  std::vector<std::vector<int>> hostedByRank_;  // global chain ids each rank hosts (placement)
  std::vector<ReplicaChain> chains_;    // this rank's, in hosted() order
  std::vector<double> windowSeconds_;   // every rank's runRound time since the last placement decision
  std::vector<ChainMove> moves_;        // planned, not yet committed
  std::vector<std::pair<int, ReplicaChain>> imported_;
  std::vector<LevelCounters> departed_;  // counters of chains this rank gave away
  uint64_t chainMoves_ = 0;
  uint64_t balanceDecisions_ = 0;
  std::vector<int> levelOf_;            // every chain's level (kept identical on every rank)
  std::vector<double> bootstrapSum_;    // sum of q_k over the bootstrap
  double bootstrapCount_ = 0.0;
  std::vector<double> largeSum_;        // all ranks' large-step sums so far
  double largeCount_ = 0.0;
  LargeStepSums pendingLarge_;          // this rank's, since its last message
  uint64_t stepsPerChain_ = 0;          // steps every chain has taken (regularisation schedule)
  ExchangeTally tally_;
  RoundTrips trips_;
};

}  // namespace relt
