// ReplicaPool's checkpoint part and its restore (see replica_pool.h).
#include <stdexcept>

#include "core/words.h"
#include "replica/replica_pool.h"

namespace relt {
namespace {

constexpr uint64_t kPartVersion = 4;
constexpr size_t kMeanTargetAt = 6;  // the word after the header, then the left-out levels

void writeCounters(WordWriter& w, const LevelCounters& c) {
  for (uint64_t v : {c.smallProposed, c.smallAccepted, c.largeProposed, c.largeAccepted, c.invalidProposals, c.nonFinite})
    w.u64(v);
  w.f64(c.largeTargetSum);
  w.f64(c.seconds);
}

LevelCounters readCounters(WordReader& in) {
  LevelCounters c;
  for (uint64_t* v : {&c.smallProposed, &c.smallAccepted, &c.largeProposed, &c.largeAccepted, &c.invalidProposals,
                      &c.nonFinite})
    *v = in.u64();
  c.largeTargetSum = in.f64();
  c.seconds = in.f64();
  return c;
}

void writeTally(WordWriter& w, const ExchangeTally& t) {
  for (const std::vector<uint64_t>* v : {&t.proposed, &t.accepted, &t.changed})
    for (uint64_t x : *v) w.u64(x);
  w.u64(t.rounds);
}

ExchangeTally readTally(WordReader& in, int m) {
  ExchangeTally t(m);
  for (std::vector<uint64_t>* v : {&t.proposed, &t.accepted, &t.changed})
    for (uint64_t& x : *v) x = in.u64();
  t.rounds = in.u64();
  return t;
}

// The chains of one old rank's part, each into its (still empty) record by global id.
void readChainRecords(WordReader& in, std::vector<std::vector<uint64_t>>& records) {
  for (uint64_t n = in.u64(); n > 0; --n) {
    const uint64_t c = in.u64();
    if (c >= records.size() || !records[c].empty()) throw std::runtime_error("the checkpoint's chains are not this render's");
    records[c] = in.block();
    if (records[c].empty()) throw std::runtime_error("truncated replica-chain state");
  }
}

}  // namespace

CheckpointBootstrap ReplicaPool::checkpointBootstrap(const std::vector<std::vector<uint64_t>>& parts) {
  if (parts.empty() || parts[0].size() <= kMeanTargetAt + 1 || parts[0][0] != kPartVersion)
    throw std::runtime_error("the checkpoint holds no replica state of this version");
  WordReader in(parts[0], kMeanTargetAt);
  CheckpointBootstrap out;
  out.meanTarget = in.f64();
  out.leftOut = in.u64();
  return out;
}

std::vector<uint64_t> ReplicaPool::checkpointPart() const {
  const int m = levels();
  WordWriter w;
  for (uint64_t v : {kPartVersion, uint64_t(m), uint64_t(groups()), uint64_t(chainCount()),
                     uint64_t(settings_.normaliserLag), uint64_t(localDecisions())})
    w.u64(v);
  const NormaliserLedger::State ledger = ledger_.state();
  w.f64(meanTarget_);
  w.u64(settings_.family.leftOut);
  w.f64(ledger.bootstrapSamples);
  w.u64(stepsPerChain_);
  w.u64(ledger.epoch);
  w.f64(family_.regularisationFloor());
  w.f64s(ledger.bootstrapSum);  // emptied when the regularisation moves
  w.f64(ledger.bootstrapCount);
  w.f64s(ledger.largeSum);
  w.f64(ledger.largeCount);
  w.f64s(estimator_.normalisers());
  writeTally(w, tally_);
  w.u64(trips_.total());
  for (const LevelCounters& c : hostedCounters()) writeCounters(w, c);
  // This rank's share of every round not read back yet, per group, oldest first.
  for (int g = 0; g < groups(); ++g) {
    const std::deque<PostedRound>& rounds = posted_[size_t(g)];
    w.u64(uint64_t(epochRead_[size_t(g)]));
    w.u64(rounds.size());
    for (const PostedRound& p : rounds) {
      w.f64s(p.large.sum);
      w.u64(p.large.count);
      w.u64(p.epoch);
    }
  }
  w.u64(hosting_.chains().size());
  for (int c : hosted()) {
    if (!hosting_.hosts(c)) continue;  // an inactive pool started no chains
    w.u64(uint64_t(c));
    w.block(travellingChain(c));
  }
  return w.words();
}

void ReplicaPool::restore(const std::vector<std::vector<uint64_t>>& parts) {
  const int m = levels();
  if (parts.empty()) throw std::runtime_error("the checkpoint holds no replica state");
  ExchangeTally tally(m);
  uint64_t trips = 0;
  std::vector<LevelCounters> counters(static_cast<size_t>(m));
  // posted[r][g]: old rank r's share of group g's rounds not read back, oldest first.
  std::vector<std::vector<std::vector<PostedRound>>> posted(parts.size());
  std::vector<std::vector<uint64_t>> records(static_cast<size_t>(chainCount()));  // travellingChain() of each
  for (size_t r = 0; r < parts.size(); ++r) {
    WordReader in(parts[r]);
    for (uint64_t v : {kPartVersion, uint64_t(m), uint64_t(groups()), uint64_t(chainCount()),
                       uint64_t(settings_.normaliserLag)})
      if (in.u64() != v) throw std::runtime_error("the checkpoint's ladders are not this render's");
    const bool local = in.u64() != 0;
    NormaliserLedger::State ledger;
    const double meanTarget = in.f64();
    const uint64_t leftOut = in.u64();
    ledger.bootstrapSamples = in.f64();
    if (meanTarget != meanTarget_ || leftOut != settings_.family.leftOut)
      throw std::runtime_error("the checkpoint's bootstrap is not this pool's");
    const uint64_t steps = in.u64();
    ledger.epoch = in.u64();
    const double floor = in.f64();
    ledger.bootstrapSum = in.f64s(size_t(m));
    ledger.bootstrapCount = in.f64();
    ledger.largeSum = in.f64s(size_t(m));
    ledger.largeCount = in.f64();
    const std::vector<double> b = in.f64s(size_t(m));
    const ExchangeTally t = readTally(in, m);
    const uint64_t partTrips = in.u64();
    if (r == 0) {  // the same on every rank
      stepsPerChain_ = steps;
      family_.restoreRegularisationFloor(float(floor));
      ledger_.restore(std::move(ledger));
      estimator_.setNormalisers(b);
    }
    // Tallies and trips: each rank's own ladders with local decisions, otherwise all on every rank.
    if (local || r == 0) {
      tally.add(t);
      trips += partTrips;
    }
    for (int k = 0; k < m; ++k) counters[size_t(k)].add(readCounters(in));
    for (int g = 0; g < groups(); ++g) {
      std::vector<PostedRound>& rounds = posted[r].emplace_back();
      epochRead_[size_t(g)] = char(in.u64() != 0);  // the same on every rank
      const uint64_t count = in.u64();
      // At most the lag of the round after the last one finished (it may have grown since the start).
      const uint64_t lag = normaliserLagAt(settings_.normaliserLag, settings_.normaliserLagGrowth,
                                           steps / uint64_t(settings_.exchangeInterval) + 2);
      if (count > lag || (r > 0 && count != posted[0][size_t(g)].size()))
        throw std::runtime_error("the checkpoint's pending rounds do not match");
      for (uint64_t i = 0; i < count; ++i) {
        PostedRound& p = rounds.emplace_back(PostedRound{LargeStepSums(m), 0, 0});
        p.large.sum = in.f64s(size_t(m));
        p.large.count = in.u64();
        p.epoch = in.u64();
      }
    }
    readChainRecords(in, records);
    if (!in.done()) throw std::runtime_error("the checkpoint's replica state has trailing data");
  }
  for (const std::vector<uint64_t>& rec : records)
    if (rec.empty()) throw std::runtime_error("the checkpoint misses chains");

  // Every chain's level, owed re-evaluation and phase as when it arrives by migration (the
  // phases of chains hosted elsewhere are never read with local decisions); only the hosted ones
  // are traced again.
  for (int c = 0; c < chainCount(); ++c) records[size_t(c)] = noteArrival(c, records[size_t(c)]);
  std::vector<ReplicaChain> chains;
  for (int c : hosted()) chains.emplace_back(records[size_t(c)], family_, evaluator());
  hosting_.setChains(std::move(chains));
  if (!localDecisions() || rank_ == 0) {
    tally_ = tally;
    trips_.addEarlier(trips);
  }
  if (rank_ == 0) departed_ = counters;  // the counters of everything before, counted once
  restorePendingRounds(posted);
}

// The rounds not read back: each rank's own shares with the same rank count, otherwise all on
// the root (the sums are the same up to rounding). At the checkpoint (roundDone) group 0 had just
// finished its round and every other group's last round was still being gathered; the rounds
// gathered before are held (spread) or still travelling (local decisions: posted again).
void ReplicaPool::restorePendingRounds(const std::vector<std::vector<std::vector<PostedRound>>>& posted) {
  const int m = levels();
  const bool same = posted.size() == size_t(ranks_);
  for (int g = 0; g < groups(); ++g) {
    const std::vector<PostedRound>& rounds = posted[0][size_t(g)];
    ungathered_[size_t(g)] = g > 0 && !rounds.empty() ? 1 : 0;
    posted_[size_t(g)].clear();
    held_[size_t(g)].clear();
    for (size_t i = 0; i < rounds.size(); ++i) {
      // Every rank's share (rank order), as its message's tail would have carried it.
      std::vector<LargeStepSums> shares(size_t(ranks_), LargeStepSums{m});
      for (size_t r = 0; r < posted.size(); ++r) {
        const LargeStepSums& from = posted[r][size_t(g)][i].large;
        LargeStepSums& into = shares[same ? r : 0];
        for (int k = 0; k < m; ++k) into.sum[size_t(k)] += from.sum[size_t(k)];
        into.count += from.count;
      }
      posted_[size_t(g)].push_back({shares[size_t(rank_)], rounds[i].epoch, placementVersion_[size_t(g)]});
      if (localDecisions() || i + ungathered_[size_t(g)] >= rounds.size()) continue;
      std::vector<std::vector<double>> tails;
      for (const LargeStepSums& s : shares) tails.push_back(tail(s, 0.0));
      held_[size_t(g)].push_back(std::move(tails));
    }
  }
}

std::vector<std::vector<double>> ReplicaPool::resumeMessages(int group, double elapsed) const {
  const std::deque<PostedRound>& rounds = posted_[size_t(group)];
  std::vector<std::vector<double>> out;
  for (size_t i = 0; i < rounds.size(); ++i) {
    const bool gathering = i + ungathered_[size_t(group)] >= rounds.size();
    if (!localDecisions() && !gathering) continue;  // held already
    std::vector<double> msg;
    if (active_ && !localDecisions()) appendTargets(group, msg);  // the round's exchange still needs the targets
    const std::vector<double> t = tail(rounds[i].large, elapsed);
    msg.insert(msg.end(), t.begin(), t.end());
    out.push_back(std::move(msg));
  }
  return out;
}

}  // namespace relt
