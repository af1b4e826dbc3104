#pragma once
// Where relt's chains live: which rank hosts which chain (the placement, the same on every rank),
// this rank's chains by global id, and their migration between ranks (each chain received before
// every rank commits the same moves).
#include <utility>
#include <vector>

#include "replica/load_balance.h"
#include "replica/replica_chain.h"
#include "replica/replica_settings.h"

namespace relt {

class ChainHosting {
 public:
  // `chains` chains of ladders of `levels`, placed over `ranks` ranks (chainRank); none started.
  ChainHosting(int chains, int levels, int rank, int ranks, Placement placement);

  // The global ids of the chains rank r hosts, in order; this rank's.
  const std::vector<int>& hostedBy(int rank) const { return byRank_[size_t(rank)]; }
  const std::vector<int>& hosted() const { return byRank_[size_t(rank_)]; }
  bool hosts(int chain) const { return localIndex_[size_t(chain)] >= 0; }
  // This rank's chains in hosted() order, and one of them by global id.
  std::vector<ReplicaChain>& chains() { return chains_; }
  const std::vector<ReplicaChain>& chains() const { return chains_; }
  ReplicaChain& chain(int id) { return chains_[size_t(localIndex_[size_t(id)])]; }
  const ReplicaChain& chain(int id) const { return chains_[size_t(localIndex_[size_t(id)])]; }
  // This rank's chains, started, in hosted() order.
  void setChains(std::vector<ReplicaChain> chains);

  // Migration: a chain this rank is to host once the moves are committed.
  void receive(int id, ReplicaChain chain) { received_.emplace_back(id, std::move(chain)); }
  // The moves applied, on every rank: a rank keeps its remaining chains in order and appends the
  // ones it received (applyMoves).
  void commit(const std::vector<ChainMove>& moves);

 private:
  void reindex();  // localIndex_ from hosted()

  int rank_;
  std::vector<std::vector<int>> byRank_;
  std::vector<int> localIndex_;  // every chain's index in chains_, -1 if hosted elsewhere
  std::vector<ReplicaChain> chains_;
  std::vector<std::pair<int, ReplicaChain>> received_;
};

}  // namespace relt
