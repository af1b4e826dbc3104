#include "replica/chain_hosting.h"

#include <algorithm>
#include <stdexcept>

namespace relt {

ChainHosting::ChainHosting(int chains, int levels, int rank, int ranks, Placement placement)
    : rank_(rank), byRank_(size_t(ranks)), localIndex_(size_t(chains), -1) {
  for (int c = 0; c < chains; ++c) byRank_[size_t(chainRank(c, levels, ranks, placement))].push_back(c);
}

void ChainHosting::setChains(std::vector<ReplicaChain> chains) {
  if (chains.size() != hosted().size()) throw std::logic_error("a chain for every hosted id");
  chains_ = std::move(chains);
  reindex();
}

void ChainHosting::reindex() {
  std::fill(localIndex_.begin(), localIndex_.end(), -1);
  for (size_t i = 0; i < hosted().size(); ++i) localIndex_[size_t(hosted()[i])] = int(i);
}

void ChainHosting::commit(const std::vector<ChainMove>& moves) {
  std::vector<std::vector<int>> next = applyMoves(byRank_, moves);
  std::vector<ReplicaChain> chains;
  chains.reserve(next[size_t(rank_)].size());
  for (int id : next[size_t(rank_)]) {
    if (hosts(id)) {  // kept (the index is still the old one)
      chains.push_back(std::move(chain(id)));
      continue;
    }
    const auto in = std::find_if(received_.begin(), received_.end(), [id](const auto& p) { return p.first == id; });
    if (in == received_.end()) throw std::logic_error("a chain moved to this rank was not received");
    chains.push_back(std::move(in->second));
  }
  byRank_ = std::move(next);
  chains_ = std::move(chains);
  received_.clear();
  reindex();
}

}  // namespace relt
