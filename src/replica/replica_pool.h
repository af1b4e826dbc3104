#pragma once
// Replica exchange light transport (`relt`): C = L ladders x M levels chains, chain c in ladder
// c / M starting at level c mod M. The ladders form up to kRoundGroups groups (ladder l in group
// l mod G) whose rounds the render loop staggers (RoundLoop). A rank hosts some chains (placement),
// steps a group's chains for a round, and contributes one message to that group's collective: the
// chains' targets under every level, its large-step sums, its stepping time and its elapsed time.
// From all messages every rank runs the same exchange per ladder of the group (a per-ladder stream
// keyed by seed, ladder and round) and updates the level labels; states stay where they are
// except when load balancing moves chains. The large-step sums, times and stop requests of a round
// are read back ReplicaSettings::normaliserLag rounds later, by every placement at the same point.
// Rank-agnostic: the image depends on (seed, L, M, steps, lag).
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "film/film.h"
#include "parallel/per_worker.h"
#include "replica/exchange.h"
#include "replica/family.h"
#include "replica/balance_window.h"
#include "replica/chain_hosting.h"
#include "replica/level_estimator.h"
#include "replica/load_balance.h"
#include "replica/normaliser_ledger.h"
#include "replica/replica_settings.h"
#include "replica/replica_chain.h"
#include "replica/round_tail.h"

namespace relt {

// The family's features (LevelFamily::featureCount per sample) of bootstrap samples first,
// first + stride, ... (others 0), for ranks to fill their share and sum.
std::vector<double> bootstrapFeatures(PssEvaluator& eval, const FamilySettings& family, uint64_t seed, int count,
                                      int first, int stride);

// What the ranks' messages of a group round decide together besides the exchanges.
struct RoundAgreement {
  double elapsed = 0.0;  // the largest elapsed time
  bool stop = false;     // some rank was asked to stop
  bool save = false;     // some rank was asked to save (write the image so far and a checkpoint)
  // Spread placement: elapsed and stop are those of this round's messages (every rank waits for
  // them anyway), not of the round read back lag rounds ago. Neither changes the image: a stop or
  // a time budget ends the render at a round that depends on timing in any case.
  bool fresh = false;
};

// What a checkpoint keeps of the bootstrap: the family's scale and the levels left out.
struct CheckpointBootstrap {
  double meanTarget = 0.0;
  uint64_t leftOut = 0;
};

class ReplicaPool {
 public:
  // `bootstrap` holds every bootstrap sample's features (bootstrapFeatures, summed over ranks).
  // One evaluator per worker thread of the rank (runRound deals the chains to them). The levels
  // the bootstrap finds idle (idleLevels) are left out of the ladder: settings().family.leftOut.
  ReplicaPool(PerWorker<PssEvaluator>& evals, const ReplicaSettings& settings, uint64_t seed,
              const std::vector<double>& bootstrap, int rank, int ranks);
  // A pool to restore() a checkpoint into: no bootstrap is taken again, the family's scale (the
  // bootstrap's mean target) and the levels left out come from the checkpoint (checkpointBootstrap;
  // `settings.family.leftOut` must be the checkpoint's).
  ReplicaPool(PerWorker<PssEvaluator>& evals, const ReplicaSettings& settings, uint64_t seed, double meanTarget,
              int rank, int ranks);
  static CheckpointBootstrap checkpointBootstrap(const std::vector<std::vector<uint64_t>>& parts);
  ReplicaPool(const ReplicaPool&) = delete;  // chains refer to family_
  ReplicaPool& operator=(const ReplicaPool&) = delete;

  const ReplicaSettings& settings() const { return settings_; }
  const LevelFamily& family() const { return family_; }
  const LevelEstimator& estimator() const { return estimator_; }
  int levels() const { return family_.levels(); }
  int chainCount() const { return settings_.ladders * levels(); }
  int groups() const { return int(pendingLarge_.size()); }
  int rankCount() const { return ranks_; }
  // The placement in use (auto resolved). Packed: every ladder lives whole on one rank, whose
  // exchanges only it decides; messages carry no targets and chains move a ladder at a time.
  Placement placement() const { return placement_; }
  bool localDecisions() const { return placement_ == Placement::Packed; }
  int groupOf(int chain) const { return (chain / levels()) % groups(); }
  // False when no bootstrap sample saw light: the image is black and no chain runs.
  bool active() const { return active_; }

  // Steps every hosted chain of `group` `steps` times, on the rank's worker threads. films: one,
  // or one per level (per-level layers). `progress`, if given, runs on the calling thread after
  // each chain it stepped (the MPI layer moves pending messages). The films and the large-step
  // sums come out the same, bit for bit, whatever the number of workers.
  void runRound(int group, uint64_t steps, std::vector<Film>& films, const std::function<void()>& progress = {});
  // This rank's message for the group's collective (`roundSeconds`: time this rank spent in
  // runRound), and the length rank `rank`'s message has (it changes when chains move).
  // `stop`: this rank was asked to stop (a signal); every rank then ends after this round.
  std::vector<double> roundMessage(int group, double elapsed, double roundSeconds, bool stop = false, bool save = false);
  size_t messageLength(int group, int rank) const;
  // Ends the group's round `round`: exchanges in its ladders (targets from `messages`, every rank's
  // message of this round in rank order, or with local decisions from the hosted chains) and new
  // level labels; then reads back the group's dueReadBacks(group, round) oldest rounds (spread:
  // held since their messages arrived; local decisions: `readBacks`, their collectives, oldest
  // first): large-step sums into the normalisers, and after every balance window a new placement
  // of the group's chains from the ranks' speeds (moves planned). Returns the largest elapsed time
  // read back so far and whether a rank asked to stop in the messages read back.
  RoundAgreement finishRound(int group, const std::vector<std::vector<double>>& messages, uint64_t round,
                             const std::vector<std::vector<std::vector<double>>>& readBacks = {});
  // How many of the group's posted rounds its finishRound of round `round` reads back: the ones at
  // least the lag old (normaliserLagAt: the lag may grow with the round), or, in the first round
  // of the group after the regularisation moved, every one posted (the normalisers must describe
  // the new targets at once, as with a lag of 1). With local decisions the loop waits for that
  // many collectives; spread waits for this round's (targets).
  size_t dueReadBacks(int group, uint64_t round) const;
  // Rounds of the group posted and not read back yet (lag - 1 between rounds once running), and
  // read back so far by this pool (since it was made or restored).
  size_t unread(int group) const { return posted_[size_t(group)].size(); }
  // How often the regularisation moved the targets, and the samples the normalisers now rest on
  // (bootstrap and large steps, both under the current targets).
  uint64_t regularisationMoves() const { return ledger_.epoch(); }
  double normaliserSamples() const { return ledger_.samples(); }
  uint64_t roundsReadBack(int group) const { return readBackCount_[size_t(group)]; }
  // Collectives still pending when the loop ends.
  size_t inFlight(int group) const;

  // Chain migration after finishRound, the same plan on every rank: the sender exports each chain
  // it gives, the receiver imports it, then every rank commits (the placement changes).
  const std::vector<ChainMove>& plannedMoves() const { return moves_; }
  std::vector<uint64_t> exportChain(int chain);
  void importChain(int chain, const std::vector<uint64_t>& state);
  void commitMoves();
  uint64_t chainMoves() const { return chainMoves_; }  // chains moved so far
  int hostedCount(int rank) const { return int(hosting_.hostedBy(rank).size()); }

  // Checkpoints, taken where group 0 has just finished a round and every other group's collective
  // of the round before is pending (RoundLoopHooks::roundDone). This rank's part: its chains by
  // global id, the sums every rank shares, its share of the pending messages and its counters.
  // restore() reads every rank's part of a checkpoint written with any number of ranks and puts
  // the render back where it was; the round loop then posts resumeMessages() again
  // (RoundLoopStart). Placement and load-balance windows start afresh (the image does not depend
  // on them).
  std::vector<uint64_t> checkpointPart() const;
  void restore(const std::vector<std::vector<uint64_t>>& parts);
  // After restore(): this rank's messages of the group's rounds whose collectives were pending,
  // oldest first, for the loop to post again (`elapsed`: the resumed elapsed time).
  std::vector<std::vector<double>> resumeMessages(int group, double elapsed) const;
  uint64_t stepsPerChain() const { return stepsPerChain_; }

  // Diagnostics. Exchange tallies and round trips are the same on every rank (with local
  // decisions: of the hosted ladders only, the MPI layer sums them); level counters cover the
  // hosted chains (the MPI layer sums them).
  const ExchangeTally& tally() const { return tally_; }
  const RoundTrips& roundTrips() const { return trips_; }
  std::vector<LevelCounters> hostedCounters() const;
  const std::vector<double>& normalisers() const { return estimator_.normalisers(); }
  int levelOf(int chain) const { return levelOf_[size_t(chain)]; }  // with local decisions: hosted chains only
  bool hosts(int chain) const { return hosting_.hosts(chain); }

 private:
  // The bootstrap's normalisers and every hosted chain's first state (resampled or annealed).
  void startFromBootstrap(const std::vector<double>& bootstrap);
  const LevelEvaluator& evaluator() const { return evaluators_[0]; }  // the calling thread's
  template <class Output>
  void stepChain(size_t i, uint64_t steps, int worker, Output& out);
  // The film hosted chain i splats into: the one film, or its level's.
  Film& filmOf(size_t i, std::vector<Film>& films) const;
  const std::vector<int>& hosted() const { return hosting_.hosted(); }
  // The targets of the group's hosted chains, in order, appended to a round message.
  void appendTargets(int group, std::vector<double>& message) const;
  // The moves that give each rank chains of the group in proportion to its measured speed.
  std::vector<ChainMove> balanceMoves(int group) const;
  void exchange(int group, const std::vector<std::vector<double>>& messages, uint64_t round);
  // Reads back every rank's message tail (large-step sums and count, seconds, stop, elapsed) of the
  // group's oldest round not read back yet.
  void readBack(int group, const std::vector<std::vector<double>>& tails, RoundAgreement& agreed);
  // A message's tail (replica/round_tail.h): its last levels() + 4 numbers (4 when inactive).
  std::vector<double> messageTail(const std::vector<double>& message) const;
  std::vector<double> tail(const LargeStepSums& large, double elapsed) const;
  // A round's large-step part of its tail (the sums only while active).
  RoundTail tailOf(const LargeStepSums& large) const;
  // A hosted chain as it travels to another rank or into a checkpoint: ReplicaChain::serialize(),
  // then whether it owes a re-evaluation under targets that moved since its group last ran (which
  // draws from its stream), then its round-trip phase.
  std::vector<uint64_t> travellingChain(int chain) const;
  // Notes such a record's level, owed re-evaluation and phase; returns its serialized chain.
  std::vector<uint64_t> noteArrival(int chain, const std::vector<uint64_t>& travelling);

  ReplicaSettings settings_;
  uint64_t seed_;
  int rank_, ranks_;
  LevelFamily family_;
  LevelEstimator estimator_;
  std::vector<LevelEvaluator> evaluators_;  // per worker thread
  std::vector<ChainLog> logs_;  // with several workers: each chain's round, kept until its turn
  bool active_ = false;
  Placement placement_;
  ChainHosting hosting_;                // which rank hosts which chain; this rank's chains
  BalanceWindows windows_;              // when to decide a group's placement again, and the speeds measured
  std::vector<ChainMove> moves_;        // planned, not yet committed
  std::vector<LevelCounters> departed_;  // counters of chains this rank gave away
  uint64_t chainMoves_ = 0;
  std::vector<uint64_t> epochOf_;       // every chain's: the epoch its state was last evaluated in
  std::vector<int> levelOf_;            // every chain's level (kept identical on every rank)
  NormaliserLedger ledger_;             // what the normalisers rest on, and the targets' epoch
  double meanTarget_ = 0.0;             // the bootstrap's mean target: the family's scale
  std::vector<LargeStepSums> pendingLarge_;  // per group: this rank's, since the group's last message
  // This rank's large-step sums in a posted message, and the epoch they were taken in.
  struct PostedRound {
    LargeStepSums large;
    uint64_t epoch = 0;
    uint64_t placement = 0;  // the group's placement version it was stepped in
  };
  std::vector<std::deque<PostedRound>> posted_;  // per group: rounds posted, not read back, oldest first
  // restore(): the rounds not read back at the checkpoint, posted[r][g] per old rank r and group g.
  void restorePendingRounds(const std::vector<std::vector<std::vector<PostedRound>>>& posted);
  // Spread: per group, every rank's message tail of the rounds gathered but not read back yet.
  std::vector<std::deque<std::vector<std::vector<double>>>> held_;
  double agreedElapsed_ = 0.0;  // the largest elapsed time read back so far
  std::vector<char> epochRead_;  // per group: a round of the current epoch has been read back
  // Per group: how often its chains moved. Stepping times of rounds stepped before the last move
  // describe the old placement and stay out of the balance window (with a lag they would be read
  // after the move and ask for it again).
  std::vector<uint64_t> placementVersion_;
  std::vector<uint64_t> readBackCount_;  // per group
  // After restore(): per group, how many of posted_'s rounds were still being gathered at the
  // checkpoint (their messages go out again with targets for spread placement).
  std::vector<size_t> ungathered_;
  uint64_t stepsPerChain_ = 0;          // steps every chain has taken (regularisation schedule)
  ExchangeTally tally_;
  RoundTrips trips_;
};

}  // namespace relt
