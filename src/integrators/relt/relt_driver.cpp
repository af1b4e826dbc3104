#include "integrators/relt/relt_driver.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "checkpoint/checkpoint.h"
#include "core/clock.h"
#include "core/error.h"
#include "integrators/relt/relt_settings.h"
#include "mcmc/round_schedule.h"
#include "parallel/workers.h"
#include "replica/replica_schedule.h"
#include "replica/round_loop.h"
#include "schedule/schedule.h"

namespace relt {
namespace {

// The family's scale and the levels left out of the render a checkpoint continues (a broken part:
// one named error).
CheckpointBootstrap checkpointBootstrap(const Resumed& checkpoint) {
  try {
    return ReplicaPool::checkpointBootstrap(checkpoint.parts);
  } catch (const std::runtime_error& e) {
    throw InputError(checkpoint.file, "", e.what());
  }
}

// The sum of every level's film, reduced onto the root.
std::vector<double> reducedSum(Job& job, const std::vector<Film>& films) {
  std::vector<double> sums = films[0].data();
  for (size_t k = 1; k < films.size(); ++k)
    for (size_t i = 0; i < sums.size(); ++i) sums[i] += films[k].data()[i];
  job.reduceSumToRoot(sums);
  return sums;
}

// Exchange counts of every rank's ladders (with local decisions each rank counts only its own).
ExchangeTally sumOverRanks(Job& job, const ExchangeTally& mine) {
  std::vector<double> v;
  for (uint64_t x : mine.proposed) v.push_back(double(x));
  for (uint64_t x : mine.accepted) v.push_back(double(x));
  for (uint64_t x : mine.changed) v.push_back(double(x));
  v.push_back(double(mine.rounds));
  job.allreduceSum(v);  // exact: counts stay far below 2^53
  ExchangeTally out(mine.levels);
  size_t k = 0;
  for (uint64_t& x : out.proposed) x = uint64_t(v[k++]);
  for (uint64_t& x : out.accepted) x = uint64_t(v[k++]);
  for (uint64_t& x : out.changed) x = uint64_t(v[k++]);
  out.rounds = uint64_t(v[k]);
  return out;
}

// The round loop's transport over the job: one nonblocking gather per group and round; chain
// states point to point; with local decisions, stop and save requests on the job's request
// channel (none in a job of one process, which acts on its requests at once).
class JobTransport final : public RoundTransport {
 public:
  JobTransport(Job& job, bool localDecisions) : job_(job) {
    if (localDecisions) channel_ = job.openRequestChannel();
    if (channel_) idle_ = [this] { channel_->poll(); };
  }
  void post(int group, std::vector<double> mine, const std::vector<size_t>& lengths) override {
    if (pending_.size() <= size_t(group)) pending_.resize(size_t(group) + 1);
    pending_[size_t(group)].push_back(job_.startAllgatherv(std::move(mine), lengths));
  }
  std::vector<std::vector<double>> wait(int group) override {
    std::vector<std::vector<double>> out = pending_[size_t(group)].front()->wait(idle_);
    pending_[size_t(group)].pop_front();
    return out;
  }
  void migrate(ReplicaPool& pool) override {
    std::vector<Payload> sends;
    std::vector<int> from, chains;
    for (const ChainMove& m : pool.plannedMoves()) {
      if (m.from == job_.rank()) sends.push_back({m.to, pool.exportChain(m.chain)});
      if (m.to == job_.rank()) {
        from.push_back(m.from);
        chains.push_back(m.chain);
      }
    }
    const std::vector<std::vector<uint64_t>> states = job_.transfer(sends, from, idle_);
    for (size_t i = 0; i < states.size(); ++i) pool.importChain(chains[i], states[i]);
    pool.commitMoves();
  }

  void progress() override {
    // One test per group: under MPI each call runs the progress engine for every pending request.
    for (const auto& group : pending_)
      if (!group.empty()) group.front()->test();
    if (channel_) channel_->poll();
  }
  void settle(int group, size_t newest) override {
    const auto& q = pending_[size_t(group)];
    if (q.size() <= newest) return;
    for (size_t i = 0; i < q.size() - newest; ++i) q[i]->complete(idle_);
  }
  std::optional<RequestAgreement> requests(uint64_t rounds, bool stop, bool save) override {
    return channel_ ? channel_->at(rounds, stop, save) : RoundTransport::requests(rounds, stop, save);
  }
  void endRequests() override {
    if (channel_) channel_->close();
  }
  // Before a snapshot's or checkpoint's collectives (RequestChannel::barrier).
  void meet() {
    if (channel_) channel_->barrier();
  }

 private:
  Job& job_;
  std::vector<std::deque<std::unique_ptr<PendingGather>>> pending_;  // per group, oldest first
  std::unique_ptr<RequestChannel> channel_;  // none: requests travel in the round messages
  std::function<void()> idle_;  // empty without a channel: plain blocking waits
};

// The pool, films and schedule where the checkpoint left them; where the loop starts.
RoundLoopStart restoreFrom(const Resumed& checkpoint, ReplicaPool& pool, std::vector<Film>& films,
                           ReplicaSchedule& schedule) {
  checkpoint.restoreFilms(films);
  try {
    pool.restore(checkpoint.parts);
  } catch (const std::runtime_error& e) {
    throw InputError(checkpoint.file, "", e.what());
  }
  RoundLoopStart start;
  start.rounds = checkpoint.progress.at("rounds").get<uint64_t>();
  start.elapsed = checkpoint.progress.at("elapsed").get<double>();
  schedule.resumeAt(start.rounds, pool.stepsPerChain());
  return start;
}

// What the render reports (collective): the loop's counts, every rank's timings and counters.
ReltOutcome outcomeOf(Job& job, const ReplicaPool& pool, const ReplicaSchedule& schedule,
                      const RoundLoopResult& loop, double area, double elapsed, double roundCollective) {
  const uint64_t rounds = loop.rounds;
  const std::vector<double> stepMean = job.allgather(loop.stepMean), stepDeviation = job.allgather(loop.stepDeviation);
  const std::vector<double> finishMean = job.allgather(loop.finishMean);
  const std::vector<std::vector<double>> stepTrace = job.gatherToRoot(loop.stepTrace);
  ReltOutcome out;
  out.rounds = rounds;
  out.stepsPerChain = schedule.stepsAfter(rounds);
  out.ladders = pool.settings().ladders;
  out.levels = pool.levels();
  for (int k = 0; k < pool.levels(); ++k) out.levelNames.push_back(pool.family().name(k));
  out.leftOutNames = LevelFamily::leftOutNames(pool.settings().family);
  out.normalisers = pool.normalisers();
  out.placement = pool.placement();
  out.tally = pool.localDecisions() ? sumOverRanks(job, pool.tally()) : pool.tally();
  out.roundTrips = pool.localDecisions() ? job.allreduceSum(pool.roundTrips().total()) : pool.roundTrips().total();
  out.chainMoves = pool.chainMoves();
  out.stepMean = stepMean;
  out.stepDeviation = stepDeviation;
  out.finishMean = finishMean;
  out.stepTrace = stepTrace;
  for (int r = 0; r < job.size(); ++r) out.chainsPerRank.push_back(pool.hostedCount(r));
  out.bootstrapSamples = uint64_t(pool.settings().bootstrap);
  out.resolveDivisor = replicaResolveDivisor(out.stepsPerChain, out.ladders, area);
  out.loopSeconds = elapsed;
  out.roundCollectiveSeconds = job.allgather(roundCollective);
  uint64_t nonFinite = 0;
  for (const LevelCounters& c : pool.hostedCounters()) nonFinite += c.nonFinite;
  out.nonFinitePerRank = job.allgather(double(nonFinite));
  for (const LevelCounters& c : pool.hostedCounters()) {
    LevelCounters s;
    static_cast<ChainCounters&>(s) = relt::sumOverRanks(job, static_cast<const ChainCounters&>(c));
    s.nonFinite = job.allreduceSum(c.nonFinite);
    s.seconds = job.allreduceSum(c.seconds);
    out.perLevel.push_back(s);
  }
  return out;
}

// Bootstrap: sample i on rank i mod P (and there on one of its workers); every rank then holds
// every sample's features. A resumed render takes what it needs of it from the checkpoint instead.
void bootstrapPool(std::optional<ReplicaPool>& pool, PerWorker<PssEvaluator>& eval, const ReplicaSettings& rs,
                   uint64_t seed, Job& job, const Resumed* checkpoint) {
  if (checkpoint) {
    const CheckpointBootstrap b = checkpointBootstrap(*checkpoint);
    ReplicaSettings resumed = rs;
    resumed.family.leftOut = b.leftOut;
    pool.emplace(eval, resumed, seed, b.meanTarget, job.rank(), job.size());
  } else {
    std::vector<double> features =
        sumOfWorkerShares(eval.size(), job.rank(), job.size(), [&](int w, int first, int stride) {
          return bootstrapFeatures(eval[w], rs.family, seed, rs.bootstrap, first, stride);
        });
    job.allreduceSum(features);
    pool.emplace(eval, rs, seed, features, job.rank(), job.size());
  }
  const std::vector<std::string> idle = LevelFamily::leftOutNames(pool->settings().family);
  if (job.rank() == 0 && !idle.empty()) {
    std::string names;
    for (const std::string& n : idle) names += (names.empty() ? "" : ", ") + n;
    std::fprintf(stderr,
                 "relt: warning: left out of the ladder: %s (the bootstrap found nothing to do there: a target "
                 "of 0, or no path of the classes estimated there); the levels that remain estimate those classes\n",
                 names.c_str());
  }
}

}  // namespace

ReltOutcome runRelt(Job& job, Renderer& renderer, const RenderSettings& settings,
                    std::vector<Film>& films, const SnapshotWriter& snapshot, const CheckpointPlan& plan,
                    const Resumed* checkpoint) {
  const ReplicaSettings rs = effectiveReplicaSettings(settings);
  PerWorker<PssEvaluator> eval(settings.threads, renderer.context(), settings.width, settings.height);

  const auto bootstrapStart = Clock::now();
  std::optional<ReplicaPool> pooled;
  bootstrapPool(pooled, eval, rs, settings.seed, job, checkpoint);
  ReplicaPool& pool = *pooled;
  const double bootstrapSeconds = job.allreduceMax(secondsSince(bootstrapStart));
  films.assign(rs.perLevel ? size_t(pool.levels()) : 1, Film(settings.width, settings.height));

  const double area = double(settings.width) * settings.height;
  ReplicaSchedule schedule(area, pool.chainCount(), rs.exchangeInterval, settings.seconds,
                           settings.mutationsPerPixel.value_or(kDefaultMutationsPerPixel));
  RoundLoopStart resumed;
  // A bootstrap sample costs about what a mutation does: the agreed first guess of a round's
  // duration, until the lagged elapsed times of two rounds have come back.
  const double perSample = bootstrapSeconds / std::max(1.0, double(rs.bootstrap) / job.size());
  if (checkpoint)
    resumed = restoreFrom(*checkpoint, pool, films, schedule);
  else
    resumed.secondsPerRound = perSample * rs.exchangeInterval * double(pool.chainCount()) / job.size();
  // A time budget counts the bootstrap too.
  resumed.elapsed += job.allreduceMax(secondsSince(bootstrapStart));
  const double collectiveBefore = job.collectiveSeconds();
  const auto start = Clock::now();
  double lastSnapshot = resumed.elapsed, lastPrint = resumed.elapsed, lastCheckpoint = resumed.elapsed;
  const bool tty = ::isatty(STDERR_FILENO);
  JobTransport transport(job, pool.localDecisions());
  auto writeSnapshot = [&](uint64_t rounds, double elapsed) {
    transport.meet();
    lastSnapshot = elapsed;
    const std::vector<double> sums = reducedSum(job, films);
    if (job.isRoot()) snapshot(sums, replicaResolveDivisor(schedule.stepsAfter(rounds), rs.ladders, area));
  };
  auto writeCheckpoint = [&](uint64_t rounds, double elapsed) {
    transport.meet();
    const nlohmann::json progress = {
        {"rounds", rounds}, {"elapsed", elapsed}, {"steps_per_chain", schedule.stepsAfter(rounds)}};
    saveCheckpoint(job, plan, "relt", progress, films, pool.checkpointPart());
  };
  RoundLoopHooks hooks;
  hooks.elapsed = [&] { return resumed.elapsed + secondsSince(start); };
  hooks.stop = [&job] { return job.stopRequested(); };
  hooks.save = [&job] { return job.takeSaveRequest(); };
  // The scaling model replays the stepping times (--trace); at most about 2^20 numbers in all.
  if (!settings.trace.empty()) hooks.traceLimit = std::max<size_t>(1024, (size_t(1) << 20) / size_t(job.size()));
  hooks.roundDone = [&](uint64_t rounds, double elapsed, bool more) {
    if (job.isRoot() && elapsed - lastPrint >= 1.0) {
      lastPrint = elapsed;
      const double rate = double(schedule.stepsAfter(rounds)) * pool.chainCount() / std::max(elapsed, 1e-9);
      std::fprintf(stderr, tty ? "\r%s" : "%s\n",
                   progressLine(schedule.fraction(rounds, elapsed), elapsed, rate, "mutations").c_str());
    }
    if (snapshotDue(settings.snapshotEvery, elapsed, lastSnapshot, more)) writeSnapshot(rounds, elapsed);
    if (checkpointNow(plan, elapsed, lastCheckpoint, more)) writeCheckpoint(rounds, elapsed);
  };
  // Ranks whose requests travel in different groups' messages agree on them a round apart: one
  // save for them all (the agreed time is the same on every rank).
  hooks.saveNow = [&, lastSave = -1.0](uint64_t rounds, double elapsed) mutable {
    if (lastSave >= 0.0 && elapsed - lastSave < 0.25) return;
    lastSave = elapsed;
    writeSnapshot(rounds, elapsed);
    if (checkpointNow(plan, elapsed, lastCheckpoint, true, true)) writeCheckpoint(rounds, elapsed);
  };
  const RoundLoopResult loop = runRoundLoop(pool, schedule, transport, films, hooks, resumed);
  if (loop.stopped) job.markStopAgreed();
  const double roundCollective = job.collectiveSeconds() - collectiveBefore;
  // The loop's agreed time is that of the messages read back (normaliser lag): the real end here.
  const double elapsed = job.allreduceMax(resumed.elapsed + secondsSince(start));
  if (job.isRoot() && tty && lastPrint > 0.0) std::fprintf(stderr, "\n");
  return outcomeOf(job, pool, schedule, loop, area, elapsed, roundCollective);
}

}  // namespace relt
