#include "replica/replica_pool.h"

#include <algorithm>
#include <stdexcept>

#include "mcmc/pssmlt.h"
#include "parallel/workers.h"
#include "replica/annealing.h"

namespace relt {
namespace {

constexpr uint64_t kExchangePurpose = 0xe8c4;

ReplicaSettings withoutIdleLevels(ReplicaSettings settings, const std::vector<double>& bootstrap) {
  settings.family.leftOut = idleLevels(settings.family, bootstrap);
  return settings;
}

}  // namespace

std::vector<double> bootstrapFeatures(PssEvaluator& eval, const FamilySettings& family, uint64_t seed, int count,
                                      int first, int stride) {
  const LevelFamily f(family, 0.0);  // the features do not depend on the mean
  const LevelEvaluator levels(eval, f);
  const size_t n = size_t(LevelFamily::featureCount(family));
  std::vector<double> out(size_t(count) * n, 0.0);
  PathSample sample;
  for (int i = first; i < count; i += stride) {
    IndependentSource u(bootstrapKey(seed, uint64_t(i)));
    levels.features(u, sample, out.data() + size_t(i) * n);  // non-finite: features (hence targets) 0
  }
  return out;
}

ReplicaPool::ReplicaPool(PerWorker<PssEvaluator>& evals, const ReplicaSettings& settings, uint64_t seed,
                         const std::vector<double>& bootstrap, int rank, int ranks)
    : ReplicaPool(evals, withoutIdleLevels(settings, bootstrap), seed, LevelFamily::meanTarget(settings.family, bootstrap),
                  rank, ranks) {
  startFromBootstrap(bootstrap);
}

ReplicaPool::ReplicaPool(PerWorker<PssEvaluator>& evals, const ReplicaSettings& settings, uint64_t seed,
                         double meanTarget, int rank, int ranks)
    : settings_(settings),
      seed_(seed),
      rank_(rank),
      ranks_(ranks),
      family_(settings.family, meanTarget),
      estimator_(family_, misExponent(settings.levelHeuristic)),
      placement_(resolvePlacement(settings.placement, settings.ladders, ranks)),
      hosting_(settings.ladders * family_.levels(), family_.levels(), rank, ranks, placement_),
      windows_(roundGroups(settings.ladders), ranks, settings.balanceWindow),
      departed_(size_t(family_.levels())),
      ledger_(family_.levels()),
      tally_(family_.levels()),
      trips_(settings.ladders * family_.levels(), family_.levels()) {
  const int m = levels();
  for (int w = 0; w < evals.size(); ++w) evaluators_.emplace_back(evals[w], family_);
  meanTarget_ = meanTarget;
  if (settings.normaliserLag < 1) throw std::invalid_argument("the normaliser lag must be at least 1 round");
  pendingLarge_.assign(size_t(roundGroups(settings.ladders)), LargeStepSums(m));  // defines groups()
  posted_.resize(size_t(groups()));
  held_.resize(size_t(groups()));
  ungathered_.assign(size_t(groups()), 0);
  epochRead_.assign(size_t(groups()), 1);  // epoch 0: the bootstrap describes the targets
  placementVersion_.assign(size_t(groups()), 0);
  readBackCount_.assign(size_t(groups()), 0);
  epochOf_.assign(size_t(chainCount()), 0);
  levelOf_.resize(size_t(chainCount()));
  for (int c = 0; c < chainCount(); ++c) {
    levelOf_[size_t(c)] = c % m;
    trips_.visit(c, c % m);
  }
  // Nothing visible (I = 0 everywhere the bootstrap looked): no chain runs, the image stays black.
  active_ = meanTarget > 0.0;
}

void ReplicaPool::startFromBootstrap(const std::vector<double>& bootstrap) {
  const int m = levels();
  const size_t features = size_t(LevelFamily::featureCount(settings_.family));
  const size_t samples = bootstrap.size() / features;
  // Every level's targets on the bootstrap: its normaliser and its starting distribution.
  std::vector<std::vector<double>> q(static_cast<size_t>(m), std::vector<double>(samples));
  std::vector<double> qi(static_cast<size_t>(m));
  for (size_t i = 0; i < samples; ++i) {
    family_.targets(bootstrap.data() + i * features, qi.data());
    for (int k = 0; k < m; ++k) q[size_t(k)][i] = qi[size_t(k)];
    ledger_.addBootstrapSample(qi.data());
  }
  ledger_.bootstrapDone(double(samples));
  std::vector<double> b(static_cast<size_t>(m));
  for (int k = 0; k < m; ++k) b[size_t(k)] = samples ? ledger_.bootstrapSum(k) / double(samples) : 0.0;
  estimator_.setNormalisers(b);
  if (!active_) return;
  std::vector<Distribution1D> start;
  for (int k = 0; k < m; ++k) {
    // A level whose target the bootstrap never saw starts anywhere (its chain wanders to q > 0).
    start.emplace_back(ledger_.bootstrapSum(k) > 0.0 ? q[size_t(k)] : std::vector<double>(samples, 1.0));
  }
  std::vector<std::vector<StreamValues>> annealed;
  if (settings_.init == InitKind::Annealing)
    annealed = annealedStarts(evaluator(), family_, q, seed_, settings_.annealing);
  std::vector<ReplicaChain> chains;
  chains.reserve(hosted().size());
  for (int c : hosted()) {
    const int level = c % m;
    ReplicaChain& chain = chains.emplace_back(replicaChainKey(seed_, c), level, family_);
    if (!annealed.empty()) {
      const std::vector<StreamValues>& particles = annealed[size_t(level)];
      chain.start(evaluator(), replicaChainKey(seed_, c), particles[chain.pickUniform(particles.size())]);
    } else {
      chain.start(evaluator(), bootstrapKey(seed_, chain.pickBootstrap(start[size_t(level)])));
    }
  }
  hosting_.setChains(std::move(chains));
}

void ReplicaPool::runRound(int group, uint64_t steps, std::vector<Film>& films, const std::function<void()>& progress) {
  // Regularisation shrinks with the steps taken so far; it is checked when group 0 starts a round,
  // where every group has taken the same steps. When it moves the targets are new: states are
  // evaluated again (a group whose exchange is still pending keeps its old targets for that
  // exchange and is evaluated again when it next runs), and the normalisers start again from large
  // steps taken under the new targets (sums of the old ones would bias them).
  if (group == 0) {
    if (family_.setRegularisationStep(stepsPerChain_)) {
      ledger_.targetsMoved();
      epochRead_.assign(epochRead_.size(), 0);
    }
    stepsPerChain_ += steps;
  }
  std::vector<size_t> mine;  // the group's hosted chains, in order
  for (size_t i = 0; i < hosting_.chains().size(); ++i)
    if (groupOf(hosted()[i]) == group) mine.push_back(i);
  LargeStepSums& large = pendingLarge_[size_t(group)];
  const int workers = std::min(int(evaluators_.size()), std::max(int(mine.size()), 1));
  if (workers == 1) {
    for (size_t i : mine) {
      DirectOutput out{filmOf(i, films), large};
      stepChain(i, steps, 0, out);
      if (progress) progress();
    }
    return;
  }
  // Each worker takes the next chain as soon as it is free (none waits for another's dearer
  // chains); a chain's splats and large steps are kept (ChainLog) and added in chain order on the
  // calling thread, so the films and sums are bit for bit those of one worker.
  if (logs_.size() < mine.size()) logs_.resize(mine.size());
  runInOrder(
      workers, mine.size(),
      [&](size_t k, int w) {
        logs_[k].clear();
        stepChain(mine[k], steps, w, logs_[k]);
      },
      [&](size_t k) {
        logs_[k].replayInto(filmOf(mine[k], films), large);
        if (progress) progress();  // MPI calls stay on the calling thread
      });
}

Film& ReplicaPool::filmOf(size_t i, std::vector<Film>& films) const {
  return films.size() > 1 ? films[size_t(hosting_.chains()[i].level())] : films[0];
}

template <class Output>
void ReplicaPool::stepChain(size_t i, uint64_t steps, int worker, Output& out) {
  const int c = hosted()[i];
  ReplicaChain& chain = hosting_.chains()[i];
  const LevelEvaluator& eval = evaluators_[size_t(worker)];
  if (epochOf_[size_t(c)] != ledger_.epoch()) {
    chain.refresh(eval);
    epochOf_[size_t(c)] = ledger_.epoch();
  }
  chain.run(steps, eval, estimator_, out);
}

size_t ReplicaPool::messageLength(int group, int rank) const {
  if (!active_) return 4;
  if (localDecisions()) return size_t(levels()) + 4;
  size_t chains = 0;
  for (int c : hosting_.hostedBy(rank)) chains += groupOf(c) == group;
  return chains * size_t(levels()) + size_t(levels()) + 4;
}

namespace {
// What a rank's tail adds to the round's agreement: the latest elapsed time and any request.
void agreeOn(const RoundTail& tail, RoundAgreement& agreed) {
  agreed.elapsed = std::max(agreed.elapsed, tail.elapsed);
  agreed.stop |= tail.stop;
  agreed.save |= tail.save;
}
}  // namespace

std::vector<double> ReplicaPool::roundMessage(int group, double elapsed, double roundSeconds, bool stop, bool save) {
  std::vector<double> msg;
  msg.reserve(messageLength(group, rank_));
  LargeStepSums& large = pendingLarge_[size_t(group)];
  if (active_ && !localDecisions()) appendTargets(group, msg);
  RoundTail tail = tailOf(large);
  tail.seconds = roundSeconds;
  tail.stop = stop;
  tail.save = save;
  tail.elapsed = elapsed;
  appendRoundTail(tail, msg);
  posted_[size_t(group)].push_back({large, ledger_.epoch(), placementVersion_[size_t(group)]});
  large = LargeStepSums(levels());
  return msg;
}

void ReplicaPool::appendTargets(int group, std::vector<double>& message) const {
  for (int c : hosted())
    if (groupOf(c) == group) message.insert(message.end(), hosting_.chain(c).targets(), hosting_.chain(c).targets() + levels());
}

std::vector<double> ReplicaPool::messageTail(const std::vector<double>& message) const {
  const std::span<const double> tail = roundTailOf(message, levels(), active_);
  return std::vector<double>(tail.begin(), tail.end());
}

RoundTail ReplicaPool::tailOf(const LargeStepSums& large) const {
  RoundTail tail;
  if (active_) tail.largeSums = large.sum;
  tail.largeCount = double(large.count);
  return tail;
}

std::vector<double> ReplicaPool::tail(const LargeStepSums& large, double elapsed) const {
  RoundTail tail = tailOf(large);  // no seconds (load-balance windows start afresh) and no requests
  tail.elapsed = elapsed;
  std::vector<double> t;
  appendRoundTail(tail, t);
  return t;
}

size_t ReplicaPool::dueReadBacks(int group, uint64_t round) const {
  const std::deque<PostedRound>& rounds = posted_[size_t(group)];
  const size_t n = rounds.size();
  const size_t lag = size_t(normaliserLagAt(settings_.normaliserLag, settings_.normaliserLagGrowth, round + 1));
  // After the regularisation moved, every posted round is read back at once (lag 1) until the new
  // targets have a bootstrap's worth of large steps: with the lag the normalisers would rest on the
  // first round read back for lag rounds, and for the whole render when the moves come faster than
  // the lag (decay above about 0.085).
  const bool few = ledger_.fewSamplesSinceMove();
  if ((few || !epochRead_[size_t(group)]) && n > 0 && rounds.back().epoch == ledger_.epoch()) return n;
  return n >= lag ? n - lag + 1 : 0;
}

size_t ReplicaPool::inFlight(int group) const { return localDecisions() ? posted_[size_t(group)].size() : 0; }

RoundAgreement ReplicaPool::finishRound(int group, const std::vector<std::vector<double>>& messages, uint64_t round,
                                        const std::vector<std::vector<std::vector<double>>>& readBacks) {
  const int m = levels();
  RoundAgreement agreed;
  agreed.elapsed = agreedElapsed_;
  if (active_) exchange(group, messages, round);

  // The rounds due: held since their messages arrived, or with local decisions just arrived.
  std::deque<std::vector<std::vector<double>>>& held = held_[size_t(group)];
  const size_t due = dueReadBacks(group, round);
  if (!localDecisions()) {
    std::vector<std::vector<double>> tails;
    for (const std::vector<double>& msg : messages) tails.push_back(messageTail(msg));
    agreed.fresh = true;
    for (const std::vector<double>& t : tails) agreeOn(readRoundTail(t, m, active_), agreed);
    held.push_back(std::move(tails));
    for (size_t i = 0; i < due; ++i) {
      readBack(group, held.front(), agreed);
      held.pop_front();
    }
  } else {
    if (readBacks.size() != due) throw std::logic_error("finishRound needs the collectives of the rounds due");
    for (const std::vector<std::vector<double>>& tails : readBacks) readBack(group, tails, agreed);
  }
  if (!active_) return agreed;

  // Normalisers from the bootstrap and every large step read back so far, frozen until the next
  // finished round (no samples since the regularisation moved: the previous ones stay).
  if (const auto b = ledger_.normalisers()) estimator_.setNormalisers(*b);

  // The group's placement from the speeds measured since its last decision (balance_window.h); a
  // gain that the window's own noise could explain (noiseGain, 1 % to 10 %) moves nothing.
  if (windows_.due(group, groups())) {
    moves_ = balanceMoves(group);
    windows_.decided(group, !moves_.empty());
  }
  return agreed;
}

void ReplicaPool::readBack(int group, const std::vector<std::vector<double>>& tails, RoundAgreement& agreed) {
  const int m = levels();
  const PostedRound mine = posted_[size_t(group)].front();
  posted_[size_t(group)].pop_front();
  ++readBackCount_[size_t(group)];
  // Sums taken before the regularisation last moved belong to other targets: dropped.
  const bool current = mine.epoch == ledger_.epoch();
  if (current) epochRead_[size_t(group)] = 1;
  // Rounds restored from a checkpoint carry no stepping times: they are not timing data.
  std::vector<double> seconds;
  bool timed = false;
  for (const std::vector<double>& tail : tails) {
    const RoundTail t = readRoundTail(tail, m, active_);
    agreeOn(t, agreed);
    seconds.push_back(t.seconds);
    timed |= t.seconds > 0.0;
    if (active_ && current) ledger_.addLargeSteps(t.largeSums, t.largeCount);
  }
  // Stepping times of rounds stepped before the group's chains last moved describe the old placement.
  if (mine.placement == placementVersion_[size_t(group)]) windows_.addRound(group, seconds, timed);
  agreedElapsed_ = agreed.elapsed;
}

// Each ladder of the group this rank decides: Q(i, j) = q_i(state held by level j), one exchange,
// new labels. Targets from the messages by global id, or with local decisions from the hosted
// chains themselves (no work that grows with the rank count).
void ReplicaPool::exchange(int group, const std::vector<std::vector<double>>& messages, uint64_t round) {
  const int m = levels();
  std::vector<const double*> targetsOf;
  if (!localDecisions()) {
    targetsOf.assign(size_t(chainCount()), nullptr);
    for (int r = 0; r < int(messages.size()); ++r) {
      const double* msg = messages[size_t(r)].data();
      for (int c : hosting_.hostedBy(r)) {
        if (groupOf(c) != group) continue;
        targetsOf[size_t(c)] = msg;
        msg += m;
      }
    }
  }
  auto targets = [&](int c) {
    return localDecisions() ? hosting_.chain(c).targets() : targetsOf[size_t(c)];
  };
  std::vector<int> holder(static_cast<size_t>(m));
  auto decide = [&](int ladder) {
    const int first = ladder * m;
    for (int c = first; c < first + m; ++c) holder[size_t(levelOf_[size_t(c)])] = c;
    TargetMatrix q(m);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) q(i, j) = targets(holder[size_t(j)])[i];
    q.normaliseRows(estimator_.normalisers());  // this round's, the same on every rank
    Rng rng(hashKey(seed_, kExchangePurpose, uint64_t(ladder), round));
    const std::vector<int> from = exchangeLevels(settings_.exchange, q, round, rng, &tally_);
    for (int i = 0; i < m; ++i) {
      const int c = holder[size_t(from[size_t(i)])];
      levelOf_[size_t(c)] = i;
      trips_.visit(c, i);
    }
  };
  if (localDecisions()) {
    for (int c : hosted())  // whole ladders: each named by its first chain
      if (c % m == 0 && groupOf(c) == group) decide(c / m);
  } else {
    for (int ladder = group; ladder < settings_.ladders; ladder += groups()) decide(ladder);
  }
  for (int c : hosted())
    if (hosting_.hosts(c)) hosting_.chain(c).setLevel(levelOf_[size_t(c)]);
}

std::vector<ChainMove> ReplicaPool::balanceMoves(int group) const {
  // The units that move: chains, or whole ladders (named by their first chain) with local decisions.
  const int m = levels();
  const int unit = localDecisions() ? m : 1;
  std::vector<std::vector<int>> units(static_cast<size_t>(ranks_));
  std::vector<int> counts(static_cast<size_t>(ranks_));
  for (int r = 0; r < ranks_; ++r) {
    for (int c : hosting_.hostedBy(r))
      if (groupOf(c) == group && c % unit == 0) units[size_t(r)].push_back(c);
    counts[size_t(r)] = int(units[size_t(r)].size());
  }
  const std::vector<double>& seconds = windows_.seconds(group);
  const double minGain = noiseGain(counts, seconds, windows_.squares(group), windows_.rounds(group), 0.01, 0.1);
  std::vector<ChainMove> moves;
  for (const ChainMove& u : planMoves(units, balancedCounts(counts, seconds, minGain)))
    for (int k = 0; k < unit; ++k) moves.push_back({u.chain + k, u.from, u.to});
  return moves;
}

std::vector<uint64_t> ReplicaPool::travellingChain(int chain) const {
  std::vector<uint64_t> state = hosting_.chain(chain).serialize();
  state.push_back(epochOf_[size_t(chain)] == ledger_.epoch() ? 0 : 1);
  state.push_back(trips_.phase(chain));  // only the host tracks it with local decisions
  return state;
}

std::vector<uint64_t> ReplicaPool::noteArrival(int chain, const std::vector<uint64_t>& travelling) {
  if (travelling.size() < 5) throw std::runtime_error("truncated replica-chain state");
  std::vector<uint64_t> state(travelling.begin(), travelling.end() - 2);
  levelOf_[size_t(chain)] = ReplicaChain::serializedLevel(state);
  epochOf_[size_t(chain)] = travelling[travelling.size() - 2] != 0 ? ledger_.epoch() - 1 : ledger_.epoch();  // owed: a stale epoch
  trips_.setPhase(chain, uint8_t(travelling.back()));
  return state;
}

std::vector<uint64_t> ReplicaPool::exportChain(int chain) {
  if (!hosting_.hosts(chain)) throw std::logic_error("exporting a chain this rank does not host");
  for (int k = 0; k < levels(); ++k) departed_[size_t(k)].add(hosting_.chain(chain).counters()[size_t(k)]);
  return travellingChain(chain);
}

void ReplicaPool::importChain(int chain, const std::vector<uint64_t>& state) {
  hosting_.receive(chain, ReplicaChain(noteArrival(chain, state), family_, evaluator()));
}

void ReplicaPool::commitMoves() {
  if (!moves_.empty()) ++placementVersion_[size_t(groupOf(moves_.front().chain))];
  hosting_.commit(moves_);
  chainMoves_ += moves_.size();
  moves_.clear();
}

std::vector<LevelCounters> ReplicaPool::hostedCounters() const {
  std::vector<LevelCounters> total(static_cast<size_t>(levels()));
  for (const ReplicaChain& chain : hosting_.chains())
    for (int k = 0; k < levels(); ++k) total[size_t(k)].add(chain.counters()[size_t(k)]);
  for (int k = 0; k < levels(); ++k) total[size_t(k)].add(departed_[size_t(k)]);
  return total;
}

}  // namespace relt
