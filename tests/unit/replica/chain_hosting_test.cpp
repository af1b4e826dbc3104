// Which rank hosts which chain, and chains moving between ranks: the mover's side and the
// receiver's commit the same moves.
#include <gtest/gtest.h>

#include <stdexcept>

#include "replica/chain_hosting.h"

using namespace relt;

namespace {

// Two relaxed levels (chains need a family to refer to).
const LevelFamily& twoLevels() {
  static const LevelFamily family(FamilySettings{.kind = FamilyKind::Relaxed, .levels = 2}, 1.0);
  return family;
}

// The hosted chains of `hosting`, as made: chain c at level c % 2.
void startChains(ChainHosting& hosting) {
  std::vector<ReplicaChain> chains;
  for (int c : hosting.hosted()) chains.emplace_back(replicaChainKey(1, c), c % 2, twoLevels());
  hosting.setChains(std::move(chains));
}

}  // namespace

TEST(ChainHosting, SpreadPlacesChainCOnRankCModP) {
  const ChainHosting hosting(6, 2, 1, 3, Placement::Spread);
  EXPECT_EQ(hosting.hostedBy(0), (std::vector<int>{0, 3}));
  EXPECT_EQ(hosting.hosted(), (std::vector<int>{1, 4}));
  EXPECT_FALSE(hosting.hosts(1)) << "no chain is there before they are set";
}

TEST(ChainHosting, AMovedChainLeavesItsSenderAndJoinsItsReceiverAtTheEnd) {
  ChainHosting sender(4, 2, 0, 2, Placement::Spread), receiver(4, 2, 1, 2, Placement::Spread);
  startChains(sender);
  startChains(receiver);
  const std::vector<ChainMove> moves = {{2, 0, 1}};
  receiver.receive(2, std::move(sender.chain(2)));
  sender.commit(moves);
  receiver.commit(moves);
  EXPECT_EQ(sender.hosted(), (std::vector<int>{0}));
  EXPECT_FALSE(sender.hosts(2));
  EXPECT_EQ(sender.chains().size(), 1u);
  EXPECT_EQ(receiver.hosted(), (std::vector<int>{1, 3, 2}));
  ASSERT_TRUE(receiver.hosts(2));
  EXPECT_EQ(receiver.chain(2).level(), 0);
  EXPECT_EQ(receiver.chain(3).level(), 1);
}

TEST(ChainHosting, CommittingAMoveToThisRankWithoutItsChainIsRefused) {
  ChainHosting receiver(4, 2, 1, 2, Placement::Spread);
  startChains(receiver);
  EXPECT_THROW(receiver.commit({{2, 0, 1}}), std::logic_error);
}
