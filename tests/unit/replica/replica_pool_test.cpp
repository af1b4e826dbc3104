// A rank's replica pool and the round protocol, with ranks simulated in one process: one rank and
// two ranks (each with its share of chains, exchanging messages) give the same levels and image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <optional>

#include "render/renderer.h"
#include "replica/replica_pool.h"
#include "replica/round_loop.h"
#include "scene/gltf_loader.h"
#include "test_support.h"
#include "integrators/registry.h"

using namespace relt;

namespace {

struct Fixture {
  explicit Fixture(const char* scene = "scenes/cornell-box.gltf", int width = 16, int height = 12) {
    RenderSettings s;
    selectIntegrator(s, "relt");
    s.width = width;
    s.height = height;
    renderer = std::make_unique<Renderer>(loadGltf(test::sourcePath(scene)), s);
    eval = std::make_unique<PerWorker<PssEvaluator>>(1, renderer->context(), width, height);
    settings.ladders = 3;
    settings.family.kind = FamilyKind::Relaxed;
    settings.family.levels = 5;
    settings.exchange.move = ExchangeMove::Permutation;
    settings.bootstrap = 4000;
  }
  // Every bootstrap sample's features with seed 5, as one rank holds them after the allreduce.
  std::vector<double> bootstrap() const { return bootstrapFeatures((*eval)[0], settings.family, 5, settings.bootstrap, 0, 1); }
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<PerWorker<PssEvaluator>> eval;
  ReplicaSettings settings;
};

// The round loop's part of a group's finish, for pools playing the ranks of one render: spread
// passes this round's messages (its exchanges need the targets), local decisions the collectives
// of the rounds whose sums are due (ReplicaPool::dueReadBacks).
class Collectives {
 public:
  explicit Collectives(int groups) : inFlight_(size_t(groups)) {}
  void post(int group, std::vector<std::vector<double>> messages) {
    inFlight_[size_t(group)].push_back(std::move(messages));
  }
  // Finishes the group's round on every pool; the first pool's agreement.
  RoundAgreement finish(const std::vector<ReplicaPool*>& pools, int group, uint64_t round) {
    std::deque<std::vector<std::vector<double>>>& q = inFlight_[size_t(group)];
    std::vector<std::vector<double>> messages;
    std::vector<std::vector<std::vector<double>>> readBacks;
    for (size_t i = pools[0]->localDecisions() ? pools[0]->dueReadBacks(group, round) : 1; i > 0; --i) {
      (pools[0]->localDecisions() ? readBacks.emplace_back() : messages) = std::move(q.front());
      q.pop_front();
    }
    RoundAgreement first;
    for (size_t i = 0; i < pools.size(); ++i) {
      const RoundAgreement agreed = pools[i]->finishRound(group, messages, round, readBacks);
      if (i == 0) first = agreed;
    }
    return first;
  }

 private:
  std::vector<std::deque<std::vector<std::vector<double>>>> inFlight_;
};

double sum(const std::vector<Film>& films) {
  double s = 0.0;
  for (const Film& f : films)
    for (double v : f.data()) s += v;
  return s;
}

}  // namespace

TEST(ReplicaPool, TwoSimulatedRanksGiveTheLevelsAndImageOfOne) {
  for (Placement placement : {Placement::Spread, Placement::Packed}) {
    Fixture fx;
    fx.settings.placement = placement;
    const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
    ReplicaPool one(*fx.eval, fx.settings, 5, lum, 0, 1);
    ReplicaPool a(*fx.eval, fx.settings, 5, lum, 0, 2), b(*fx.eval, fx.settings, 5, lum, 1, 2);
    ASSERT_TRUE(one.active());
    std::vector<Film> f1(1, Film(16, 12)), fa(1, Film(16, 12)), fb(1, Film(16, 12));
    ASSERT_EQ(one.groups(), 2) << "odd and even ladders";
    Collectives c1(2), c2(2);
    const uint64_t lag = uint64_t(fx.settings.normaliserLag);
    for (uint64_t r = 0; r < lag + 4; ++r) {
      for (int g = 0; g < 2; ++g) {
        one.runRound(g, 4, f1);
        c1.post(g, {one.roundMessage(g, 0.0, 0.0)});
        c1.finish({&one}, g, r);
        a.runRound(g, 4, fa);
        b.runRound(g, 4, fb);
        const std::vector<std::vector<double>> messages = {a.roundMessage(g, 1.0, 0.0), b.roundMessage(g, 2.0, 0.0)};
        EXPECT_EQ(messages[0].size(), a.messageLength(g, 0));
        EXPECT_EQ(messages[1].size(), a.messageLength(g, 1));
        c2.post(g, messages);
        // Spread reads the elapsed times of the round's own messages; with local decisions they
        // arrive with the sums, lag rounds late.
        const bool spread = placement == Placement::Spread;
        const RoundAgreement agreed = c2.finish({&a, &b}, g, r);
        EXPECT_EQ(agreed.fresh, spread);
        EXPECT_EQ(agreed.elapsed, spread || r + 1 >= lag ? 2.0 : 0.0) << "the largest elapsed time";
      }
      // Packed: each rank knows the levels of its own ladders only.
      for (int c = 0; c < one.chainCount(); ++c) {
        ASSERT_NE(a.hosts(c), b.hosts(c)) << "every chain on exactly one rank";
        if (placement == Placement::Spread || a.hosts(c)) ASSERT_EQ(one.levelOf(c), a.levelOf(c)) << "chain " << c << " round " << r;
        if (placement == Placement::Spread || b.hosts(c)) ASSERT_EQ(one.levelOf(c), b.levelOf(c));
      }
    }
    // Every ladder's levels are a permutation of 0..M-1.
    for (int ladder = 0; ladder < 3; ++ladder) {
      std::vector<int> levels;
      for (int c = ladder * 5; c < ladder * 5 + 5; ++c) levels.push_back(one.levelOf(c));
      std::sort(levels.begin(), levels.end());
      EXPECT_EQ(levels, (std::vector<int>{0, 1, 2, 3, 4}));
    }
    EXPECT_GT(one.tally().rounds, 0u);
    const double s1 = sum(f1), s2 = sum(fa) + sum(fb);
    EXPECT_GT(s1, 0.0);
    EXPECT_NEAR(s1, s2, 1e-9 * s1) << placementName(placement);
    for (size_t k = 0; k < one.normalisers().size(); ++k)
      EXPECT_NEAR(one.normalisers()[k], a.normalisers()[k], 1e-12 * one.normalisers()[k]);
  }
}

TEST(ReplicaPool, ChainsMovedToAFasterRankContinueAsIfTheyHadStayed) {
  // Rank 1 reports three times rank 0's stepping time: chains move to rank 0 (a state exported,
  // imported, traced again), each group's after each of its first rounds (the first windows are
  // short), then every 2 rounds (2 groups x 2 x 3 s >= the 10 s window). Spread moves single
  // chains; packed moves whole ladders (8 ladders: two per group per rank, one can go). Levels,
  // image and counters stay those of one rank.
  for (Placement placement : {Placement::Spread, Placement::Packed}) {
    Fixture fx;
    fx.settings.ladders = placement == Placement::Packed ? 8 : 4;
    fx.settings.placement = placement;
    fx.settings.balanceWindow = 10.0;
    const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
    ReplicaPool one(*fx.eval, fx.settings, 5, lum, 0, 1);
    ReplicaPool a(*fx.eval, fx.settings, 5, lum, 0, 2), b(*fx.eval, fx.settings, 5, lum, 1, 2);
    std::vector<Film> f1(1, Film(16, 12)), fa(1, Film(16, 12)), fb(1, Film(16, 12));
    Collectives c1(one.groups()), c2(one.groups());
    // The stepping times arrive lag rounds late; then 10 rounds of balancing.
    for (uint64_t r = 0; r < uint64_t(fx.settings.normaliserLag) + 9; ++r) {
      for (int g = 0; g < one.groups(); ++g) {
        one.runRound(g, 4, f1);
        c1.post(g, {one.roundMessage(g, 0.0, 1.0)});
        c1.finish({&one}, g, r);
        a.runRound(g, 4, fa);
        b.runRound(g, 4, fb);
        c2.post(g, {a.roundMessage(g, 0.0, 1.0), b.roundMessage(g, 0.0, 3.0)});
        c2.finish({&a, &b}, g, r);
        ASSERT_EQ(a.plannedMoves(), b.plannedMoves());
        EXPECT_TRUE(one.plannedMoves().empty()) << "one rank never moves chains";
        for (const ChainMove& m : a.plannedMoves()) {
          ASSERT_EQ(m.from, 1);
          ASSERT_EQ(a.groupOf(m.chain), g) << "only the finished group's chains move";
          a.importChain(m.chain, b.exportChain(m.chain));
        }
        a.commitMoves();
        b.commitMoves();
      }
      for (int c = 0; c < one.chainCount(); ++c) {
        const ReplicaPool& host = a.hosts(c) ? a : b;
        ASSERT_EQ(one.levelOf(c), host.levelOf(c)) << "chain " << c;
        if (placement == Placement::Packed)
          ASSERT_EQ(host.hosts(c), host.hosts(c - c % 5)) << "a ladder stays whole";
      }
    }
    EXPECT_GT(a.chainMoves(), 0u) << placementName(placement);
    EXPECT_EQ(a.hostedCount(0) + a.hostedCount(1), one.chainCount());
    EXPECT_GE(a.hostedCount(0), 2 * a.hostedCount(1)) << "rank 0 is three times as fast";
    EXPECT_EQ(a.hostedCount(0), b.hostedCount(0));
    const double s1 = sum(f1), s2 = sum(fa) + sum(fb);
    EXPECT_NEAR(s1, s2, 1e-9 * s1);
    uint64_t m1 = 0, m2 = 0, acc1 = 0, acc2 = 0;
    auto count = [](const ReplicaPool& p, uint64_t& proposed, uint64_t& accepted) {
      for (const LevelCounters& c : p.hostedCounters()) {
        proposed += c.smallProposed + c.largeProposed;
        accepted += c.smallAccepted + c.largeAccepted;
      }
    };
    count(one, m1, acc1);
    count(a, m2, acc2);
    count(b, m2, acc2);
    EXPECT_EQ(m1, m2);
    EXPECT_EQ(acc1, acc2) << "moved chains take the same decisions";
    if (placement == Placement::Packed) {
      EXPECT_EQ(one.roundTrips().total(), a.roundTrips().total() + b.roundTrips().total())
          << "round trips counted by each ladder's host, the trip's phase travelling with the chain";
      EXPECT_EQ(one.tally().rounds, a.tally().rounds + b.tally().rounds);
    }
  }
}

TEST(ReplicaPool, AutoPlacementPacksBeyondEightRanksWhenEveryRankCanHoldTwoLadders) {
  EXPECT_EQ(resolvePlacement(Placement::Auto, 32, 16), Placement::Packed);
  EXPECT_EQ(resolvePlacement(Placement::Auto, 32, 17), Placement::Spread);
  EXPECT_EQ(resolvePlacement(Placement::Auto, 32, 8), Placement::Spread);
  EXPECT_EQ(resolvePlacement(Placement::Auto, 1, 1), Placement::Spread);
  EXPECT_EQ(resolvePlacement(Placement::Spread, 64, 2), Placement::Spread);
  EXPECT_EQ(resolvePlacement(Placement::Packed, 2, 8), Placement::Packed);
}

TEST(ReplicaPool, ADarkSceneRunsNoChains) {
  Fixture fx;
  const std::vector<double> dark(size_t(fx.settings.bootstrap) * kPathClassCount, 0.0);
  ReplicaPool pool(*fx.eval, fx.settings, 5, dark, 0, 1);
  EXPECT_FALSE(pool.active());
  EXPECT_EQ(pool.messageLength(0, 0), 4u);
}

// A stop request (a signal on some rank) ends the loop after the round every group has finished,
// with the steps of the rounds done and nothing more; without one the budget decides.
TEST(RoundLoop, AStopRequestEndsTheLoopAfterTheCurrentRound) {
  for (Placement placement : {Placement::Spread, Placement::Packed})
  for (int askAt : {0, 7, 1000}) {
    Fixture fx;
    fx.settings.placement = placement;
    const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
    const ReplicaSchedule schedule(16.0 * 12.0, 15, 4, std::nullopt, 64.0);  // 820 steps per chain
    ReplicaPool pool(*fx.eval, fx.settings, 5, lum, 0, 1);
    std::vector<Film> films(1, Film(16, 12));
    LocalTransport transport;
    int posts = 0;
    RoundLoopHooks hooks;
    hooks.elapsed = [] { return 0.0; };
    hooks.stop = [&] { return posts++ >= askAt; };  // spread: asked at every post
    const RoundLoopResult r = runRoundLoop(pool, schedule, transport, films, hooks);
    if (askAt == 1000) {
      EXPECT_FALSE(r.stopped);
      EXPECT_EQ(r.rounds, 205u);  // 820 steps / 4 per round
    } else {
      EXPECT_TRUE(r.stopped);
      // Spread: post p is group p % 2's message of round p / 2 and carries the stop, read at the
      // end of that group's round. Group 0's round is then the last; group 1's message is read
      // after group 0 stepped one more round. Local decisions read their messages back lag rounds
      // late (here 32), so the request travels apart (RoundTransport::requests): asked once a
      // round, after group 0's, and acted on there, not a lag later.
      const uint64_t expected = placement == Placement::Spread ? uint64_t(askAt / 2 + 1 + askAt % 2) : uint64_t(askAt + 1);
      EXPECT_EQ(r.rounds, expected) << askAt << " " << placementName(placement);
    }
    EXPECT_GT(sum(films), 0.0);
  }
}

// Two pools playing ranks 0 and 1 of one render, stepped one group round at a time with stepping
// times the test chooses; planned moves are carried out between them as the MPI layer would.
struct TwoRanks {
  TwoRanks(Fixture& fx, const std::vector<double>& lum)
      : a(*fx.eval, fx.settings, 5, lum, 0, 2), b(*fx.eval, fx.settings, 5, lum, 1, 2), c(a.groups()) {}
  int hostedInGroup(int rank, int g) const {
    int n = 0;
    for (int ch = 0; ch < a.chainCount(); ++ch) n += a.groupOf(ch) == g && (rank == 0 ? a.hosts(ch) : b.hosts(ch));
    return n;
  }
  // Group g's round r with the two ranks' stepping seconds; true if chains moved.
  bool round(uint64_t r, int g, double seconds0, double seconds1) {
    a.runRound(g, 1, fa);
    b.runRound(g, 1, fb);
    c.post(g, {a.roundMessage(g, 0.0, seconds0), b.roundMessage(g, 0.0, seconds1)});
    c.finish({&a, &b}, g, r);
    EXPECT_EQ(a.plannedMoves(), b.plannedMoves());
    const bool moved = !a.plannedMoves().empty();
    for (const ChainMove& m : a.plannedMoves())
      (m.to == 0 ? a : b).importChain(m.chain, (m.to == 0 ? b : a).exportChain(m.chain));
    a.commitMoves();
    b.commitMoves();
    return moved;
  }
  ReplicaPool a, b;
  std::vector<Film> fa{1, Film(16, 12)}, fb{1, Film(16, 12)};
  Collectives c;
};

// With the normaliser lag the stepping times of a round arrive lag rounds late: those stepped
// before chains last moved describe the old placement and must not ask for the move again. Rank 1
// takes three times as long per chain (times in proportion to the chains it hosts): a quarter of
// each group's chains end there after one decision per group, and nothing moves afterwards.
TEST(ReplicaPool, BalancingUnderALagMovesOnceForOneSpeedDifference) {
  Fixture fx;
  fx.settings.ladders = 8;  // 40 chains, 20 per group, 10 per rank and group at the start
  fx.settings.placement = Placement::Spread;
  fx.settings.balanceWindow = 1.0;
  const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
  TwoRanks t(fx, lum);
  for (uint64_t r = 0; r < uint64_t(fx.settings.normaliserLag) + 60; ++r)
    for (int g = 0; g < t.a.groups(); ++g) t.round(r, g, 0.01 * t.hostedInGroup(0, g), 0.03 * t.hostedInGroup(1, g));
  for (int g = 0; g < t.a.groups(); ++g) EXPECT_EQ(t.hostedInGroup(0, g), 15) << "group " << g;
  EXPECT_EQ(t.a.chainMoves(), 10u) << "5 chains per group, moved once";
}

// A persistent imbalance smaller than one window's timing noise: rank 1 is 12 % slower (moving 2 of
// 40 chains per group gains 5 %), and round times alternate 15 % above and below their mean (cv
// 0.15, with no luck in it: a window's sum is the mean). One window of ~8 rounds puts the noise
// threshold at the 10 % ceiling, 16 rounds at 8.2 %, 32 at 5.8 %: each alone moves nothing. A
// decision that moves nothing keeps measuring; at 64 rounds (4.1 %) the chains move, once.
TEST(ReplicaPool, AnImbalanceHiddenInOneWindowsNoiseIsFoundByMeasuringLonger) {
  Fixture fx;
  fx.settings.family.levels = 4;
  fx.settings.ladders = 40;  // 160 chains, 80 per group, 40 per rank and group at the start
  fx.settings.placement = Placement::Spread;
  // Rank 1 steps a group round in 40 x 11.2 ms = 0.448 s, so a window of this many seconds (it
  // counts group rounds x groups) holds about 8 rounds.
  fx.settings.balanceWindow = 8.0 * 0.448 * 2.0;
  const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
  TwoRanks t(fx, lum);
  for (int g = 0; g < t.a.groups(); ++g) ASSERT_EQ(t.hostedInGroup(0, g), 40);
  uint64_t firstMove = 0;
  const uint64_t lag = uint64_t(fx.settings.normaliserLag);
  for (uint64_t r = 0; r < lag + 200; ++r)
    for (int g = 0; g < t.a.groups(); ++g) {
      const double wobble = r % 2 == 0 ? 1.15 : 0.85;
      const bool moved = t.round(r, g, 0.01 * t.hostedInGroup(0, g) * wobble, 0.0112 * t.hostedInGroup(1, g) * wobble);
      if (moved && firstMove == 0) firstMove = r;
    }
  // Not before about 60 rounds had been read back; then 42 chains per group on the faster rank
  // (42.3 would balance), moved once per group, and never back.
  EXPECT_GT(firstMove, lag + 50) << "moved on a window's noise";
  for (int g = 0; g < t.a.groups(); ++g) EXPECT_EQ(t.hostedInGroup(0, g), 42) << "group " << g;
  EXPECT_EQ(t.a.chainMoves(), 4u);
}

// A time budget under the normaliser lag: elapsed times come back lag rounds late, so the loop
// carries the latest forward by the agreed duration of a round (first a guess). A clock that
// advances 1 s per group round (2 s per round) and a 20 s budget: about 10 rounds, not the 32
// before the first time comes back; the guess being 25 % low costs a few rounds at most.
TEST(RoundLoop, ATimeBudgetHoldsWhileTheElapsedTimesAreStillTravelling) {
  Fixture fx;
  const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
  ASSERT_GT(fx.settings.normaliserLag, 20);
  for (double guess : {2.0, 1.5}) {
    ReplicaPool pool(*fx.eval, fx.settings, 5, lum, 0, 1);
    const ReplicaSchedule schedule(16.0 * 12.0, 15, 4, 20.0, 64.0);
    std::vector<Film> films(1, Film(16, 12));
    LocalTransport transport;
    double clock = 0.0;
    RoundLoopHooks hooks;
    hooks.elapsed = [&] { return clock += 1.0; };
    RoundLoopStart start;
    start.secondsPerRound = guess;
    const RoundLoopResult r = runRoundLoop(pool, schedule, transport, films, hooks, start);
    EXPECT_GE(r.rounds, 9u) << guess;
    EXPECT_LE(r.rounds, guess == 2.0 ? 11u : 15u) << guess;
  }
}

// A rank paused for a moment (SIGSTOP, a busy machine) makes one round last 2 s where the others
// take 0.1 s. The budget must still hold: the stalled round's duration is no guess for the rounds
// not read back yet (carried over them it ended a 20 s render at 8 s), nor for the next one.
TEST(RoundLoop, ATimeBudgetHoldsAfterAStall) {
  for (Placement placement : {Placement::Spread, Placement::Packed}) {
    Fixture fx;
    fx.settings.placement = placement;
    ReplicaPool pool(*fx.eval, fx.settings, 5, fx.bootstrap(), 0, 1);
    const ReplicaSchedule schedule(16.0 * 12.0, 15, 4, 20.0, 64.0);
    std::vector<Film> films(1, Film(16, 12));
    LocalTransport transport;
    double clock = 0.0;
    int posts = 0;
    RoundLoopHooks hooks;
    hooks.elapsed = [&] { return clock += (++posts == 100 ? 2.0 : 0.05); };  // two posts a round
    RoundLoopStart start;
    start.secondsPerRound = 0.1;
    const RoundLoopResult r = runRoundLoop(pool, schedule, transport, films, hooks, start);
    EXPECT_GE(clock, 0.98 * 20.0) << placementName(placement);
    EXPECT_LE(clock, 20.0 + 0.1) << placementName(placement);
    EXPECT_NEAR(double(r.rounds), (20.0 - 1.95) / 0.1, 2.0) << placementName(placement);
  }
}

// The scaling model replays each group round's stepping time: the loop records the first
// traceLimit of them, in loop order, and nothing without a limit.
TEST(RoundLoop, RecordsTheSteppingTimeOfTheFirstGroupRounds) {
  Fixture fx;
  const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
  const ReplicaSchedule schedule(16.0 * 12.0, 15, 4, std::nullopt, 64.0);  // 205 rounds of 2 groups
  for (size_t limit : {size_t(0), size_t(7), size_t(10000)}) {
    ReplicaPool pool(*fx.eval, fx.settings, 5, lum, 0, 1);
    std::vector<Film> films(1, Film(16, 12));
    LocalTransport transport;
    RoundLoopHooks hooks;
    hooks.elapsed = [] { return 0.0; };
    hooks.traceLimit = limit;
    const RoundLoopResult r = runRoundLoop(pool, schedule, transport, films, hooks);
    ASSERT_EQ(r.stepTrace.size(), std::min<size_t>(limit, 2 * r.rounds)) << limit;
    double sum = 0.0;
    for (double t : r.stepTrace) {
      EXPECT_GT(t, 0.0);
      sum += t;
    }
    if (limit == 10000) EXPECT_NEAR(sum / double(r.stepTrace.size()), r.stepMean, 1e-12);
  }
}

// The round loop's order (group 0 steps a round before the other groups finish theirs) with a
// regularisation that moves the tempered targets: a chain can move while its state still waits to
// be evaluated under the new targets, and must then be evaluated on arrival exactly as it would
// have been at home.
TEST(ReplicaPool, ChainsMovedBeforeARegularisationRefreshContinueAsIfTheyHadStayed) {
  Fixture fx;
  fx.settings.ladders = 4;
  fx.settings.family.kind = FamilyKind::Tempered;
  fx.settings.family.levels = 4;
  fx.settings.family.regularisation = 0.05;
  fx.settings.family.regularisationDecay = 0.2;
  fx.settings.balanceWindow = 10.0;
  const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
  ReplicaPool one(*fx.eval, fx.settings, 5, lum, 0, 1);
  ReplicaPool a(*fx.eval, fx.settings, 5, lum, 0, 2), b(*fx.eval, fx.settings, 5, lum, 1, 2);
  ASSERT_EQ(one.groups(), 2);
  std::vector<Film> f1(1, Film(16, 12)), fa(1, Film(16, 12)), fb(1, Film(16, 12));
  std::vector<std::vector<std::vector<double>>> posted1(2), posted2(2);
  auto stepAndPost = [&](int g) {  // as the loop does: a group's message right after its steps
    one.runRound(g, 4, f1);
    a.runRound(g, 4, fa);
    b.runRound(g, 4, fb);
    posted1[size_t(g)] = {one.roundMessage(g, 0.0, 1.0)};
    posted2[size_t(g)] = {a.roundMessage(g, 0.0, 1.0), b.roundMessage(g, 0.0, 3.0)};
  };
  auto finish = [&](int g, uint64_t r) {
    one.finishRound(g, posted1[size_t(g)], r);
    a.finishRound(g, posted2[size_t(g)], r);
    b.finishRound(g, posted2[size_t(g)], r);
    for (const ChainMove& mv : a.plannedMoves()) a.importChain(mv.chain, b.exportChain(mv.chain));
    a.commitMoves();
    b.commitMoves();
  };
  stepAndPost(0);
  stepAndPost(1);
  for (uint64_t r = 0; r < 12; ++r) {
    finish(0, r);
    stepAndPost(0);  // the regularisation moves here, before group 1 finishes round r
    finish(1, r);
    stepAndPost(1);
  }
  for (int c = 0; c < one.chainCount(); ++c) ASSERT_EQ(one.levelOf(c), (a.hosts(c) ? a : b).levelOf(c)) << c;
  EXPECT_GT(a.chainMoves(), 0u);
  const double s1 = sum(f1), s2 = sum(fa) + sum(fb);
  EXPECT_GT(s1, 0.0);
  EXPECT_NEAR(s1, s2, 1e-9 * s1);
}

namespace {

// A render of `mpp` mutations per pixel through the round loop; with `resumeFrom` it continues
// that checkpoint (part and film) instead of starting afresh. `checkpoint` receives the part and
// the film at the last roundDone.
struct LoopRun {
  std::vector<uint64_t> part;
  std::vector<Film> films;
  uint64_t rounds = 0;
  std::vector<double> normalisers;
  std::vector<int> levels;  // every chain's at the end
};

LoopRun runLoopSized(Fixture& fx, const std::vector<double>& lum, double mpp, const LoopRun* resumeFrom, int w, int h) {
  // A resumed pool takes no bootstrap: what it needs of it is in the checkpoint.
  std::optional<ReplicaPool> pooled;
  if (resumeFrom) {
    const CheckpointBootstrap b = ReplicaPool::checkpointBootstrap({resumeFrom->part});
    ReplicaSettings resumed = fx.settings;
    resumed.family.leftOut = b.leftOut;
    pooled.emplace(*fx.eval, resumed, 5, b.meanTarget, 0, 1);
  } else
    pooled.emplace(*fx.eval, fx.settings, 5, lum, 0, 1);
  ReplicaPool& pool = *pooled;
  ReplicaSchedule schedule(double(w) * h, pool.chainCount(), fx.settings.exchangeInterval, std::nullopt, mpp);
  LoopRun out;
  out.films.assign(1, Film(w, h));
  RoundLoopStart start;
  if (resumeFrom) {
    pool.restore({resumeFrom->part});
    out.films = resumeFrom->films;
    start.rounds = resumeFrom->rounds;
    schedule.resumeAt(start.rounds, pool.stepsPerChain());
  }
  LocalTransport transport;
  RoundLoopHooks hooks;
  hooks.elapsed = [] { return 0.0; };
  hooks.roundDone = [&](uint64_t rounds, double, bool more) {
    if (more) return;
    out.part = pool.checkpointPart();
    out.rounds = rounds;
  };
  const RoundLoopResult r = runRoundLoop(pool, schedule, transport, out.films, hooks, start);
  if (out.part.empty()) out.part = pool.checkpointPart();
  out.rounds = r.rounds;
  out.normalisers = pool.normalisers();
  for (int c = 0; c < pool.chainCount(); ++c) out.levels.push_back(pool.levelOf(c));
  return out;
}


}  // namespace

// A render continued from its checkpoint is the render that never stopped: two groups staggered
// (the second's collective pending at the checkpoint), the tempered family with a regularisation
// that moves the targets (and empties the normalisers' sums) before and after the checkpoint.
TEST(NormaliserLag, GrowsWithTheRoundFromTheBaseToEightTimesIt) {
  EXPECT_EQ(normaliserLagAt(32, 8, 1), 32u);
  EXPECT_EQ(normaliserLagAt(32, 8, 256), 32u);
  EXPECT_EQ(normaliserLagAt(32, 8, 264), 33u);
  EXPECT_EQ(normaliserLagAt(32, 8, 2048), 256u);
  EXPECT_EQ(normaliserLagAt(32, 8, 100000), 256u) << "capped at 8 x the base";
  EXPECT_EQ(normaliserLagAt(32, 0, 8000), 32u) << "0: fixed";
}

// A rank with local decisions leads the slowest by about kMaxLeadSeconds of rounds at most, so a
// stop (acted on once all have caught up) waits no longer, however long the lag.
TEST(NormaliserLag, ARanksLeadIsCappedBySecondsOfItsRoundsNotByTheLag) {
  EXPECT_EQ(leadCapRounds(0.005), 60u);  // 207 rounds/s: 60 rounds, not the lag's 256
  EXPECT_EQ(leadCapRounds(0.1), 3u);
  EXPECT_EQ(leadCapRounds(2.0), 1u) << "at least the round before";
  EXPECT_EQ(leadCapRounds(0.0), std::numeric_limits<size_t>::max()) << "not measured yet: no cap";
}

// Both placements read back at the lag of each round: unread rounds are the lag less one.
TEST(ReplicaPool, AGrowingLagKeepsLagLessOneRoundsUnread) {
  for (Placement placement : {Placement::Spread, Placement::Packed}) {
    Fixture fx;
    fx.settings.placement = placement;
    fx.settings.normaliserLag = 2;
    fx.settings.normaliserLagGrowth = 4;
    const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
    ReplicaPool pool(*fx.eval, fx.settings, 5, lum, 0, 1);
    std::vector<Film> films(1, Film(16, 12));
    Collectives c(pool.groups());
    for (uint64_t r = 0; r < 40; ++r)
      for (int g = 0; g < pool.groups(); ++g) {
        pool.runRound(g, 2, films);
        c.post(g, {pool.roundMessage(g, 0.0, 0.0)});
        c.finish({&pool}, g, r);
        ASSERT_EQ(pool.unread(g), normaliserLagAt(2, 4, r + 1) - 1) << placementName(placement) << " round " << r;
      }
    EXPECT_EQ(pool.unread(0), 9u) << "lag 10 at round 40";
    EXPECT_EQ(normaliserLagAt(2, 4, 100), 16u) << "and at most 16 later";
  }
}

TEST(ReplicaPool, AResumedRenderIsTheRenderThatNeverStopped) {
  for (FamilyKind kind : {FamilyKind::Relaxed, FamilyKind::Tempered})
  for (int lag : {32, 3}) {  // 3: the lag grows from round 32 on (7 at the checkpoint, 15 by round 120)
    SCOPED_TRACE(lag);
    Fixture fx("scenes/ring.gltf", 40, 30);
    fx.settings.normaliserLag = lag;
    fx.settings.ladders = 2;
    fx.settings.family.kind = kind;
    fx.settings.family.levels = 4;
    fx.settings.exchangeInterval = 10;
    fx.settings.exchange.move = ExchangeMove::Deo;
    if (kind == FamilyKind::Tempered) {
      fx.settings.family.regularisation = 0.05;
      fx.settings.family.regularisationDecay = 0.2;
    }
    const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
    // 8 chains, 1200 pixels: 4 mpp = 600 steps = 60 rounds, 8 mpp = 120 rounds.
    const LoopRun whole = runLoopSized(fx, lum, 8.0, nullptr, 40, 30);
    const LoopRun half = runLoopSized(fx, lum, 4.0, nullptr, 40, 30);
    ASSERT_EQ(half.rounds, 60u);
    const LoopRun resumed = runLoopSized(fx, lum, 8.0, &half, 40, 30);
    EXPECT_EQ(resumed.rounds, whole.rounds);
    EXPECT_EQ(resumed.normalisers, whole.normalisers);
    EXPECT_EQ(resumed.levels, whole.levels) << "every chain where it would have been";
    EXPECT_EQ(resumed.films[0].data(), whole.films[0].data()) << "bitwise: one rank, the same order of sums";
    const LoopRun again = runLoopSized(fx, lum, 8.0, &whole, 40, 30);
    EXPECT_EQ(again.films[0].data(), whole.films[0].data()) << "a finished render resumed does nothing more";
    // The part does not depend on the placement: rounds still travelling with local decisions are
    // held with spread and the other way round (one rank: the same sums in the same order).
    for (auto [before, after] : {std::pair{Placement::Spread, Placement::Packed},
                                 std::pair{Placement::Packed, Placement::Spread},
                                 std::pair{Placement::Packed, Placement::Packed}}) {
      fx.settings.placement = before;
      const LoopRun first = runLoopSized(fx, lum, 4.0, nullptr, 40, 30);
      fx.settings.placement = after;
      const LoopRun second = runLoopSized(fx, lum, 8.0, &first, 40, 30);
      EXPECT_EQ(second.normalisers, whole.normalisers) << placementName(before) << " -> " << placementName(after);
      EXPECT_EQ(second.films[0].data(), whole.films[0].data()) << placementName(before) << " -> " << placementName(after);
    }
    fx.settings.placement = Placement::Auto;
  }
}

// cornell-box has no implicit path after a specular bounce: kitaoka's specific level (L0 + delta L5)
// sees nothing in the bootstrap and is left out, its class L0 going to the other three; a render
// resumed from a checkpoint keeps the same ladder and is the render that never stopped.
TEST(ReplicaPool, AnIdleLevelIsLeftOutAndStaysOutWhenResumed) {
  Fixture fx;
  fx.settings.family.kind = FamilyKind::Kitaoka;
  fx.settings.ladders = 2;
  fx.settings.exchangeInterval = 10;
  fx.settings.exchange.move = ExchangeMove::Deo;
  const std::vector<double> lum = bootstrapFeatures((*fx.eval)[0], fx.settings.family, 5, fx.settings.bootstrap, 0, 1);
  {
    const ReplicaPool pool(*fx.eval, fx.settings, 5, lum, 0, 1);
    ASSERT_EQ(pool.levels(), 3);
    EXPECT_EQ(pool.settings().family.leftOut, 1u);
    EXPECT_EQ(pool.chainCount(), 6) << "no chain for the left-out level";
    EXPECT_EQ(pool.family().name(0), "indirect");
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(pool.family().estimates(k, 0)) << "L0 handed to level " << k;
    for (double b : pool.normalisers()) EXPECT_GT(b, 0.0);
  }
  // 6 chains, 192 pixels: 5 mpp = 160 steps = 16 rounds, 10 mpp = 32 rounds.
  const LoopRun whole = runLoopSized(fx, lum, 10.0, nullptr, 16, 12);
  const LoopRun half = runLoopSized(fx, lum, 5.0, nullptr, 16, 12);
  ASSERT_EQ(half.rounds, 16u);
  const LoopRun resumed = runLoopSized(fx, lum, 10.0, &half, 16, 12);
  EXPECT_EQ(resumed.normalisers, whole.normalisers);
  EXPECT_EQ(resumed.films[0].data(), whole.films[0].data());
  EXPECT_GT(sum(whole.films), 0.0);
}

// Tempered targets whose regularisation moves every 12 % more steps (decay 0.1): faster than the
// lag grows. After each move the normalisers must rest on every large step taken under the new
// targets until they have a bootstrap's worth, not on the first round read back for lag rounds.
TEST(ReplicaPool, AfterTheRegularisationMovesTheNormalisersReadEveryRoundUntilABootstrapsWorth) {
  for (Placement placement : {Placement::Spread, Placement::Packed}) {
    Fixture fx;
    fx.settings.placement = placement;
    fx.settings.ladders = 4;
    fx.settings.family.kind = FamilyKind::Tempered;
    fx.settings.family.levels = 4;
    fx.settings.family.regularisation = 0.05;
    fx.settings.family.regularisationDecay = 0.1;
    ReplicaPool pool(*fx.eval, fx.settings, 5, fx.bootstrap(), 0, 1);
    const ReplicaSchedule schedule(16.0 * 12.0, pool.chainCount(), fx.settings.exchangeInterval, std::nullopt, 2000.0);
    std::vector<Film> films(1, Film(16, 12));
    LocalTransport transport;
    RoundLoopHooks hooks;
    hooks.elapsed = [] { return 0.0; };
    int few = 0;
    hooks.roundDone = [&](uint64_t rounds, double, bool) {
      if (pool.regularisationMoves() == 0 || pool.normaliserSamples() >= fx.settings.bootstrap) return;
      ++few;
      EXPECT_EQ(pool.unread(0), 0u) << "round " << rounds << " " << placementName(placement);
    };
    runRoundLoop(pool, schedule, transport, films, hooks);
    EXPECT_GT(pool.regularisationMoves(), 5u);
    EXPECT_GT(few, 10) << "rounds with fewer samples than the bootstrap after a move";
  }
}

TEST(RoundLoop, RanksActOnEveryRequestAtTheLargestOfferedRound) {
  const RequestAgreement a = agreeOnOffers({{12, false, true}, {40, false, false}, {13, true, false}});
  EXPECT_EQ(a.round, 40u);  // the rank 27 rounds ahead cannot go back: the others catch up
  EXPECT_TRUE(a.stop);
  EXPECT_TRUE(a.save);
  const RequestAgreement none = agreeOnOffers({{7, false, false}, {7, false, false}});
  EXPECT_EQ(none.round, 7u);
  EXPECT_FALSE(none.stop || none.save);
}
